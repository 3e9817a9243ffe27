// Chung & Ooi (2011) test 7: two identical spheres, R = 0.1 m, head-on at +-0.2 m/s, spinning
// +-w about the same axis so that their contact points move together (zero relative slip),
// mu = 0.4, e = 0.5; aluminium alloy (70 GPa, 0.33, 2700) and copper (120 GPa, 0.35, 8900)
// (BENCHMARKS 4). Expected [D]: no tangential force arises, so w' = w and v_t' = 0 exactly;
// checked to 1e-12 (relative on w', absolute in m/s on v_t'), over w = 0.1..100 rad/s. This catches
// a sign error in the relative contact velocity (R1 w1 + R2 w2 instead of the difference).
#include "chung_ooi.h"

#include <cstdio>

namespace veridem::verify
{
namespace
{
using namespace chung_ooi;

void runMaterial(const Solid& solid, const CaseContext& context, CaseResult& r)
{
    const Real radius = 0.1, speed = 0.2, mu = 0.4, e = 0.5;
    Series s{solid.name + "_sweep", {"omega", "omega_out_1", "omega_out_2", "vt_out_1", "vt_out_2"}, {}};
    Real worstSpin = 0, worstVt = 0;
    for (const Real w : {0.1, 0.3, 1.0, 3.0, 10.0, 30.0, 100.0})
    {
        // Sphere 1 above (contact arm -R z), sphere 2 below (arm +R z): w1 = (0, w, 0) and
        // w2 = (0, -w, 0) give both contact points the velocity -w R x.
        const Outcome o = sphereImpact(solid, e, mu, radius, {0, 0, -speed}, {0, w, 0}, radius, {0, 0, speed},
                                       {0, -w, 0}, 1.0, 1000, context);
        worstSpin = std::fmax(worstSpin, std::fabs(o.angularVelocity.y - w) / w);
        worstSpin = std::fmax(worstSpin, std::fabs(o.partnerAngularVelocity.y + w) / w);
        worstVt = std::fmax(worstVt, std::fmax(length(Vec3{o.velocity.x, o.velocity.y, 0}),
                                               length(Vec3{o.partnerVelocity.x, o.partnerVelocity.y, 0})));
        s.rows.push_back(
            {w, o.angularVelocity.y, -o.partnerAngularVelocity.y, o.velocity.x, o.partnerVelocity.x});
    }
    const std::string tag = " (" + solid.name + ")";
    r.quantities.push_back(absoluteQuantity("max |w' - w| / w, both spheres" + tag, "", 0, worstSpin, 1e-12,
                                            "zero slip: no tangential force (exact)"));
    r.quantities.push_back(absoluteQuantity("max |v_t'|, both spheres" + tag, "m/s", 0, worstVt, 1e-12,
                                            "zero slip: no tangential force (exact)"));
    r.series.push_back(std::move(s));
}

CaseResult run(const CaseContext& context)
{
    CaseResult r;
    runMaterial(kAluminiumAlloy033, context, r);
    runMaterial(kCopper, context, r);
    return r;
}
} // namespace

VERIDEM_CASE({.name = "chung_ooi_t7",
              .summary = "Chung & Ooi test 7: counter-spinning spheres with zero slip keep w and gain no v_t",
              .reference = "Chung & Ooi 2011; BENCHMARKS 4",
              .labels = {"dem", "quick", "chung_ooi"},
              .run = run});
VERIDEM_SWEEP("chung_ooi_t7", {});
} // namespace veridem::verify
