// Chung & Ooi (2011) tests 6 and 8 share their sweep: an impact at constant normal speed
// V_n = 0.2 m/s with topspin only (the centre has no tangential velocity, the contact point moves
// at V_t = R w0), R = 0.1 m, mu = 0.4, e = 0.5; aluminium alloy and nylon (BENCHMARKS 4). Test 6
// hits a rigid plane, test 8 a sphere of radius 0.5 m and 1000 times the density (effectively
// immovable). Drawn as Chung & Ooi draw them: beta = -V_t'/V_t against X = 3.5 mu (1 + e) V_n/V_t,
// and tan(recoil) = V_t'/V_n' against tan(incidence) = V_t/V_n (contact-point velocities).
// Rigid body [D]: X < 1 slides throughout: beta = X - 1, tan(recoil) = (tan(incidence) - 2.1)/0.5;
// X >= 1 sticks: beta = 0, tan(recoil) = 0.
// Checks:
//  * rigid sliding range (X < 1): 1 + beta = X (the tangential impulse over the incident
//    contact-point momentum) within 0.5 % (issue 21). The rigid body needs a tangential impulse of
//    exactly mu times the normal impulse (1 + e) m V_n. Two properties of the contact law give it,
//    and the case prints both: the Hertz normal force never pulls (clipped at zero, damping
//    computed for the clipped law), so the Coulomb cap's impulse mu sum max(F_n, 0) dt equals mu
//    times the normal impulse (the printed ratio sum max(F_n, 0) dt / sum F_n dt is 1); and the
//    spring reset on a sliding step never opposes the friction force, so no step of the impact
//    falls below the cap (the printed "sticking" share) (docs/models.md, "Gross sliding").
//  * sticking regime (X >= 1): Mindlin compliance makes the contact point leave reversed
//    (beta > 0) near the transition, and with its incident sense (beta < 0, the no-slip spring
//    completing most of an oscillation) at the largest X, where the rigid body gives beta = 0.
#pragma once

#include "chung_ooi.h"

#include <algorithm>
#include <cstdio>

namespace veridem::verify::chung_ooi
{

/// Runs the sweep for one material; `target` = false for the rigid plane (test 6), true for the
/// large sphere (test 8).
inline void spinSweep(const Solid& solid, bool target, const CaseContext& context, CaseResult& r)
{
    const Real radius = 0.1, vn = 0.2, mu = 0.4, e = 0.5;
    const Real slide = 3.5 * mu * (1 + e); // 2.1
    Series s{solid.name + "_sweep",
             {"tan_incidence", "X", "beta", "beta_rigid", "tan_recoil", "tan_recoil_rigid", "slid"},
             {}};
    std::vector<Real> impulse, impulseRigid, stickShare, cappedShare;
    std::vector<std::size_t> rigidSliding;
    std::vector<Real> stickingBeta;
    for (const Real tanIncidence :
         {0.1, 0.2, 0.4, 0.6, 0.8, 1.0, 1.2, 1.5, 1.8, 2.1, 2.5, 3.0, 4.0, 5.0, 7.0, 10.0})
    {
        const Real w0 = tanIncidence * vn / radius; // contact point V_x = -R * w_y = R w0
        Outcome o;
        Real vtOut = 0, vnOut = 0;
        if (!target)
        {
            o = wallImpact(solid, e, mu, radius, {0, 0, -vn}, {0, -w0, 0}, 1000, context);
            vtOut = o.velocity.x - radius * o.angularVelocity.y;
            vnOut = o.velocity.z;
        }
        else
        {
            const Real big = 0.5;
            o = sphereImpact(solid, e, mu, radius, {0, 0, -vn}, {0, -w0, 0}, big, {}, {}, 1000.0, 1000,
                             context);
            // Contact point of sphere 1 (arm -R z) relative to that of the target (arm +R2 z).
            vtOut = (o.velocity.x - radius * o.angularVelocity.y) -
                    (o.partnerVelocity.x + big * o.partnerAngularVelocity.y);
            vnOut = o.velocity.z - o.partnerVelocity.z;
        }
        const Real vt = tanIncidence * vn, x = slide / tanIncidence;
        const Real beta = -vtOut / vt, tanRecoil = vtOut / vnOut;
        const bool sticks = x >= 1;
        if (!sticks)
        {
            impulse.push_back(1 + beta);
            impulseRigid.push_back(x);
            rigidSliding.push_back(impulse.size() - 1);
            stickShare.push_back(o.stickingImpulseFraction);
            cappedShare.push_back(o.compressiveImpulse / o.normalImpulse);
        }
        else
            stickingBeta.push_back(beta);
        s.rows.push_back({tanIncidence, x, beta, sticks ? 0.0 : x - 1, tanRecoil,
                          sticks ? 0.0 : (tanIncidence - slide) / e, o.slidThroughout ? 1.0 : 0.0});
    }
    const std::string tag = " (" + solid.name + ")";
    char n[200];
    std::snprintf(n, sizeof n,
                  "worst rel. error of 1 + beta = X (tangential impulse), %zu impacts with X < 1%s",
                  rigidSliding.size(), tag.c_str());
    r.quantities.push_back(absoluteQuantity(n, "", 0, worstRelative(impulse, impulseRigid, rigidSliding),
                                            5e-3,
                                            "issue 21: rigid-body values within 0.5 % in gross sliding"));
    const Real maxBeta = *std::max_element(stickingBeta.begin(), stickingBeta.end());
    r.quantities.push_back(absoluteQuantity("max beta over X >= 1 > 0 (contact point reversed)" + tag, "",
                                            0.5, maxBeta, 0.5,
                                            "sign check: passes for 0 <= beta <= 1; rigid gives 0"));
    r.quantities.push_back(absoluteQuantity("beta at the largest X < 0 (no-slip limit)" + tag, "", -0.5,
                                            stickingBeta.front(), 0.5,
                                            "sign check: passes for -1 <= beta <= 0; rigid gives 0"));
    std::snprintf(n, sizeof n,
                  "%s, X < 1: sum max(F_n,0) dt / sum F_n dt = %.4f..%.4f (1 when the normal force never "
                  "pulls); share of it on sticking steps %.4f..%.4f",
                  solid.name.c_str(), *std::min_element(cappedShare.begin(), cappedShare.end()),
                  *std::max_element(cappedShare.begin(), cappedShare.end()),
                  *std::min_element(stickShare.begin(), stickShare.end()),
                  *std::max_element(stickShare.begin(), stickShare.end()));
    r.notes.push_back(n);
    r.series.push_back(std::move(s));
}

} // namespace veridem::verify::chung_ooi
