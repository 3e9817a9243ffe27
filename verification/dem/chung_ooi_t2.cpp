// Chung & Ooi (2011) test 2: elastic normal impact of a sphere on a rigid plane, R = 0.1 m,
// v = 0.2 m/s, e = 1; aluminium alloy (E = 70 GPa, nu = 0.30, rho = 2699) and magnesium alloy
// (40 GPa, 0.35, 1800) (BENCHMARKS 4). Rigid plane: E* = E/(1 - nu^2), R* = R, m* = m; the closed
// forms of test 1. Expected (BENCHMARKS 4): Al 49.72 um, 11.37 kN, 0.732 ms; Mg 52.12 um, 7.233 kN,
// 0.767 ms. Tolerances as test 1 (1 %, e within 1e-3).
#include "chung_ooi.h"

namespace veridem::verify
{
namespace
{
using namespace chung_ooi;

void runMaterial(const Solid& solid, const CaseContext& context, CaseResult& r)
{
    const Real radius = 0.1, speed = 0.2;
    const Outcome o = wallImpact(solid, 1.0, 0.0, radius, {0, 0, -speed}, {}, 1000, context, true);
    const Real m = sphereMass(solid.density, radius), eStar = effectiveModulus(solid, true);
    const HertzImpact h = hertzImpact(m, radius, eStar, speed);
    const std::string tag = " (" + solid.name + ")";
    const char* why = "BENCHMARKS 7 #10 (Chung & Ooi test 2)";
    r.quantities.push_back(relativeQuantity("F_max" + tag, "N", h.maxForce, o.maxNormalForce, 1e-2, why));
    r.quantities.push_back(relativeQuantity("delta_max" + tag, "m", h.maxOverlap, o.maxOverlap, 1e-2, why));
    r.quantities.push_back(relativeQuantity("tc" + tag, "s", h.contactTime, o.contactTime, 1e-2, why));
    r.quantities.push_back(relativeQuantity("e" + tag, "", 1.0, o.velocity.z / speed, 1e-3,
                                            "elastic Hertz contact conserves energy"));
    Series s{solid.name + "_force", {"t", "delta", "F", "F_hertz"}, {}};
    for (const auto& row : o.history)
        s.rows.push_back(
            {row[0], row[1], row[2], 4.0 / 3.0 * eStar * std::sqrt(radius) * std::pow(row[1], 1.5)});
    r.series.push_back(std::move(s));
}

CaseResult run(const CaseContext& context)
{
    CaseResult r;
    runMaterial(kAluminiumAlloy, context, r);
    runMaterial(kMagnesiumAlloy, context, r);
    return r;
}
} // namespace

VERIDEM_CASE(
    {.name = "chung_ooi_t2",
     .summary = "Chung & Ooi test 2 (Al, Mg alloys): sphere on a rigid plane, Hertz F_max, delta_max, tc",
     .reference = "Chung & Ooi 2011; Johnson 1985; BENCHMARKS 4",
     .labels = {"dem", "quick", "chung_ooi"},
     .run = run});
VERIDEM_SWEEP("chung_ooi_t2",
              {.orders = {
                   {"F_max", 2.0, "the peak of a smooth Verlet trajectory sampled at the steps: O(dt^2)"},
                   {"delta_max", 2.0, "the peak of a smooth Verlet trajectory sampled at the steps: O(dt^2)"},
                   {"tc", 2.0, "interpolated at both ends: second order"},
                   {"e (", 1.25,
                    "the Hertz stiffness has an infinite slope at delta = 0: the step of separation errs by "
                    "~dt^(5/4) (convergence_orders)"}}});
} // namespace veridem::verify
