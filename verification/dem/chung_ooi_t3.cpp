// Chung & Ooi (2011) test 3: normal impact of a sphere on a rigid plane with restitution e_in
// from 0.1 to 1, R = 2.5 mm, v = 3.9 m/s; aluminium oxide (E = 380 GPa, nu = 0.23, rho = 4000)
// and cast iron (100 GPa, 0.25, 7000) (BENCHMARKS 4). Expected: e_out = e_in (the identity line
// Chung & Ooi draw), and at e = 1 the Hertz closed forms of test 1 (Al2O3: delta_max = 8.09 um,
// F_max = 615 N, tc = 6.10 us; cast iron 17.2 um, 507 N, 12.97 us).
// The damping eta = 2 sqrt(5/6) beta sqrt(S_n m*) with the normal force clipped at zero: beta is
// computed for the clipped law from the dimensionless equation x'' = -max(0, x^{3/2} +
// sqrt(5) beta x^{1/4} x'), whose restitution depends on beta alone (RK4 and bisection,
// models/normal.h, docs/models.md), so e_out = e_in up to the time-step error.
// Tolerance on e_out: 1e-3 absolute at 1000 steps per contact, the bound BENCHMARKS 2.1 gives for
// velocity Verlet at >= 50 steps per contact scaled down by the second-order damping (see
// chung_ooi_convergence for the measured order).
#include "chung_ooi.h"

#include <cstdio>

namespace veridem::verify
{
namespace
{
using namespace chung_ooi;

void runMaterial(const Solid& solid, const CaseContext& context, CaseResult& r)
{
    const Real radius = 2.5e-3, speed = 3.9;
    Series s{solid.name + "_restitution", {"e_in", "e_out", "e_identity"}, {}};
    Real worst = 0, worstAt = 0;
    for (int k = 1; k <= 10; ++k)
    {
        const Real e = 0.1 * k;
        const Outcome o = wallImpact(solid, e, 0.0, radius, {0, 0, -speed}, {}, 1000, context, k == 10);
        const Real eOut = o.velocity.z / speed;
        s.rows.push_back({e, eOut, e});
        if (std::fabs(eOut - e) > worst)
        {
            worst = std::fabs(eOut - e);
            worstAt = e;
        }
        if (k == 10)
        {
            const HertzImpact h =
                hertzImpact(sphereMass(solid.density, radius), radius, effectiveModulus(solid, true), speed);
            const std::string tag = " (" + solid.name + ", e = 1)";
            const char* why = "Hertz closed form (BENCHMARKS 4, 7 #10)";
            r.quantities.push_back(
                relativeQuantity("F_max" + tag, "N", h.maxForce, o.maxNormalForce, 1e-2, why));
            r.quantities.push_back(
                relativeQuantity("delta_max" + tag, "m", h.maxOverlap, o.maxOverlap, 1e-2, why));
            r.quantities.push_back(
                relativeQuantity("tc" + tag, "s", h.contactTime, o.contactTime, 1e-2, why));
        }
    }
    char name[96];
    std::snprintf(name, sizeof name, "max |e_out - e_in|, e_in = 0.1..1 (%s; worst at %.1f)",
                  solid.name.c_str(), worstAt);
    r.quantities.push_back(absoluteQuantity(name, "", 0, worst, 1e-3,
                                            "exact-restitution Hertz damping; 1000 steps per contact"));
    r.series.push_back(std::move(s));
}

CaseResult run(const CaseContext& context)
{
    CaseResult r;
    runMaterial(kAluminiumOxide, context, r);
    runMaterial(kCastIron, context, r);
    return r;
}
} // namespace

VERIDEM_CASE(
    {.name = "chung_ooi_t3",
     .summary = "Chung & Ooi test 3 (Al2O3, cast iron): e_out = e_in for e_in = 0.1..1, Hertz at e = 1",
     .reference = "Chung & Ooi 2011; BENCHMARKS 4",
     .labels = {"dem", "quick", "chung_ooi"},
     .run = run});
VERIDEM_SWEEP("chung_ooi_t3",
              {.orders = {
                   {"F_max", 2.0, "the peak of a smooth Verlet trajectory sampled at the steps: O(dt^2)"},
                   {"delta_max", 2.0, "the peak of a smooth Verlet trajectory sampled at the steps: O(dt^2)"},
                   {"tc", 2.0, "interpolated at both ends: second order"}}});
} // namespace veridem::verify
