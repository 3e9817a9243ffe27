// Chung & Ooi (2011) test 6: topspin impact at V_n = 0.2 m/s on a rigid plane, aluminium alloy
// and nylon; sweep, rigid-body expectations and checks in chung_ooi_spin.h.
#include "chung_ooi_spin.h"

namespace veridem::verify
{
namespace
{
CaseResult run(const CaseContext& context)
{
    CaseResult r;
    chung_ooi::spinSweep(chung_ooi::kAluminiumAlloy033, false, context, r);
    chung_ooi::spinSweep(chung_ooi::kNylon, false, context, r);
    r.notes.push_back(
        "beta = -V_t'/V_t and tan(recoil) = V_t'/V_n' use contact-point velocities relative to the "
        "partner; X = 3.5 mu (1 + e) V_n / V_t.");
    return r;
}
} // namespace

VERIDEM_CASE({.name = "chung_ooi_t6",
              .summary = "Chung & Ooi test 6: topspin impact on a rigid plane: beta against X, recoil angle",
              .reference = "Chung & Ooi 2011; BENCHMARKS 4",
              .labels = {"dem", "chung_ooi"},
              .run = run});
VERIDEM_SWEEP("chung_ooi_t6", {});
} // namespace veridem::verify
