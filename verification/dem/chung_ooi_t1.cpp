// Chung & Ooi (2011) test 1: elastic normal impact of two identical spheres, R = 10 mm, each at
// 10 m/s head-on (v = 20 m/s relative), Hertz contact, e = 1; glass (E = 48 GPa, nu = 0.20,
// rho = 2800) and limestone (20 GPa, 0.25, 2500) (BENCHMARKS 4).
//   E* = E / (2 (1 - nu^2)), R* = R/2, m* = m/2
//   delta_max = (15 m* v^2 / (16 E* sqrt(R*)))^(2/5),  F_max = (4/3) E* sqrt(R*) delta_max^(3/2),
//   tc = 2.868 (m*^2 / (R* E*^2 v))^(1/5)
// Tolerances: 1 % each (BENCHMARKS 7 #10; the constant 2.868 of tc is given to 4 digits and
// 1000 steps per contact resolve the peak to ~1e-5); e = 1 within 1e-3 (an elastic contact
// conserves energy; velocity Verlet's error at 1000 steps per contact is ~1e-6).
// Chung & Ooi draw F against delta and F against t: the series hold both, with the Hertz curve.
#include "chung_ooi.h"

namespace veridem::verify
{
namespace
{
using namespace chung_ooi;

void runMaterial(const Solid& solid, const CaseContext& context, CaseResult& r)
{
    const Real radius = 0.01, speed = 10.0;
    const Outcome o = sphereImpact(solid, 1.0, 0.0, radius, {0, 0, -speed}, {}, radius, {0, 0, speed}, {},
                                   1.0, 1000, context, true);
    const Real m = sphereMass(solid.density, radius), eStar = effectiveModulus(solid, false);
    const HertzImpact h = hertzImpact(m / 2, radius / 2, eStar, 2 * speed);
    const std::string tag = " (" + solid.name + ")";
    const char* why = "BENCHMARKS 7 #10 (Chung & Ooi test 1)";
    r.quantities.push_back(relativeQuantity("F_max" + tag, "N", h.maxForce, o.maxNormalForce, 1e-2, why));
    r.quantities.push_back(relativeQuantity("delta_max" + tag, "m", h.maxOverlap, o.maxOverlap, 1e-2, why));
    r.quantities.push_back(relativeQuantity("tc" + tag, "s", h.contactTime, o.contactTime, 1e-2, why));
    const Real e = (o.velocity.z - o.partnerVelocity.z) / (2 * speed);
    r.quantities.push_back(
        relativeQuantity("e" + tag, "", 1.0, e, 1e-3, "elastic Hertz contact conserves energy"));
    Series s{solid.name + "_force", {"t", "delta", "F", "F_hertz"}, {}};
    for (const auto& row : o.history)
        s.rows.push_back(
            {row[0], row[1], row[2], 4.0 / 3.0 * eStar * std::sqrt(radius / 2) * std::pow(row[1], 1.5)});
    r.series.push_back(std::move(s));
}

CaseResult run(const CaseContext& context)
{
    CaseResult r;
    runMaterial(kGlass, context, r);
    runMaterial(kLimestone, context, r);
    return r;
}
} // namespace

VERIDEM_CASE(
    {.name = "chung_ooi_t1",
     .summary = "Chung & Ooi test 1 (glass, limestone): sphere-sphere Hertz F_max, delta_max, tc, e = 1",
     .reference = "Chung & Ooi 2011; Johnson 1985; BENCHMARKS 4 and 7 #10",
     .labels = {"dem", "quick", "chung_ooi"},
     .run = run});
VERIDEM_SWEEP("chung_ooi_t1",
              {.orders = {
                   {"F_max", 2.0, "the peak of a smooth Verlet trajectory sampled at the steps: O(dt^2)"},
                   {"delta_max", 2.0, "the peak of a smooth Verlet trajectory sampled at the steps: O(dt^2)"},
                   {"tc", 2.0, "interpolated at both ends: second order"},
                   {"e (", 1.25,
                    "the Hertz stiffness has an infinite slope at delta = 0: the step of separation errs by "
                    "~dt^(5/4) (convergence_orders)"}}});
} // namespace veridem::verify
