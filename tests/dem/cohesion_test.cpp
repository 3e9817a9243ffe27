// The adhesion models (models/cohesion.h) against their closed forms, and the JKR touch criterion
// of the contact law.
#include "core/constants.h"
#include "dem/contact_law.h"
#include "dem/lanes.h"
#include "dem/models/cohesion.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstring>

using namespace veridem;
using namespace veridem::dem;

namespace
{
constexpr Real kModulus = 5e6;  // E* [Pa]
constexpr Real kRadius = 5e-4;  // R* [m]
constexpr Real kAdhesion = 0.2; // w [J/m^2]

Real criticalRadius() // a_c = (pi w R*^2 / (8 E*))^(1/3) [m]
{
    return std::cbrt(kPi * kAdhesion * kRadius * kRadius / (8 * kModulus));
}
} // namespace

TEST(Jkr, ContactRadiusInvertsTheOverlapOnTheStableBranch)
{
    // delta(a) from the closed form, then a(delta) by the law's Newton iteration. Away from the
    // breaking point the root is simple and converges to round-off (1e-13); at 1.01 a_c it is
    // nearly double, where a relative error eps in delta becomes ~sqrt(eps) in a (1e-7).
    const Real ac = criticalRadius();
    for (Real factor : {1.01, 1.1, 1.5, 2.0, 5.0, 30.0})
    {
        const Real a = factor * ac;
        const Real delta = jkrOverlap(kModulus, kRadius, kAdhesion, a);
        const Real tolerance = factor < 1.05 ? 1e-7 : 1e-12;
        EXPECT_NEAR(jkrContactRadius<Real>(kModulus, kRadius, kAdhesion, delta), a, tolerance * a) << factor;
    }
}

TEST(Jkr, BreakingOverlapAndPullOffForce)
{
    const Real ac = criticalRadius();
    // delta_c = delta(a_c) = -(3/4) (pi^2 w^2 R* / E*^2)^(1/3).
    EXPECT_NEAR(jkrBreakingOverlap<Real>(kModulus, kRadius, kAdhesion),
                jkrOverlap(kModulus, kRadius, kAdhesion, ac), 1e-14);
    // The force minimum -(3/2) pi w R* at a = (9 pi w R*^2 / (8 E*))^(1/3) = 9^(1/3) a_c.
    const Real pullOff = jkrPullOffForce<Real>(kRadius, kAdhesion);
    EXPECT_NEAR(jkrForce<Real>(kModulus, kRadius, kAdhesion, std::cbrt(9.0) * ac), -pullOff, 1e-12 * pullOff);
    EXPECT_DOUBLE_EQ(pullOff, 1.5 * kPi * kAdhesion * kRadius);
    // At touch (delta = 0) the force is -(4/3) pi w R*; at the break -(5/6) pi w R*.
    const Real a0 = jkrContactRadius<Real>(kModulus, kRadius, kAdhesion, 0.0);
    EXPECT_NEAR(jkrForce<Real>(kModulus, kRadius, kAdhesion, a0), -4.0 / 3.0 * kPi * kAdhesion * kRadius,
                1e-10 * pullOff);
    EXPECT_NEAR(jkrForce<Real>(kModulus, kRadius, kAdhesion, ac), -5.0 / 6.0 * kPi * kAdhesion * kRadius,
                1e-12 * pullOff);
}

TEST(Jkr, WithoutAdhesionIsHertz)
{
    for (Real delta : {1e-9, 1e-7, 1e-5})
    {
        const Real a = jkrContactRadius<Real>(kModulus, kRadius, 0.0, delta);
        EXPECT_NEAR(a, std::sqrt(kRadius * delta), 1e-14 * a);
        const Real hertz = hertzElasticForce<Real>(kModulus, kRadius, delta);
        EXPECT_NEAR(jkrForce<Real>(kModulus, kRadius, 0.0, a), hertz, 1e-13 * hertz);
    }
}

TEST(Jkr, LanesGiveTheScalarBits)
{
    const Real breaking = jkrBreakingOverlap<Real>(kModulus, kRadius, kAdhesion);
    // Two lanes (the portable width; the four-lane one compiles only inside AVX2 functions, and
    // determinism_test runs it through the force stage). Lanes that converge at different steps.
    using L = lanes::Lanes2;
    for (const L delta : {L{1e-6, 0.0}, L{0.999 * breaking, 2 * breaking}}) // 2 delta_c: past the break
    {
        const L a = jkrContactRadius<L>(lanes::broadcast<L>(kModulus), lanes::broadcast<L>(kRadius),
                                        lanes::broadcast<L>(kAdhesion), delta);
        for (int l = 0; l < 2; ++l)
        {
            const Real scalar = jkrContactRadius<Real>(kModulus, kRadius, kAdhesion, delta[l]);
            const Real lane = a[l];
            EXPECT_EQ(std::memcmp(&scalar, &lane, sizeof scalar), 0) << l;
        }
    }
}

TEST(Dmt, IsHertzMinusTwoPiWR)
{
    const Real delta = 2e-6;
    EXPECT_NEAR(dmtForce<Real>(kModulus, kRadius, kAdhesion, delta),
                4.0 / 3.0 * kModulus * std::sqrt(kRadius) * std::pow(delta, 1.5) -
                    2 * kPi * kAdhesion * kRadius,
                1e-15);
    EXPECT_DOUBLE_EQ(dmtPullOffForce<Real>(kRadius, kAdhesion), 2 * kPi * kAdhesion * kRadius);
}

namespace
{
PairParams adhesivePair(NormalModel model)
{
    PairParams p;
    p.normalModel = model;
    p.effectiveModulus = kModulus;
    p.effectiveShearModulus = 0.4 * kModulus;
    p.workOfAdhesion = kAdhesion;
    p.mu = 0.5;
    return p; // no damping: hertzBeta 0
}

ContactOutput evaluateAt(const PairParams& p, Real overlap, ContactHistory& history)
{
    ContactInput in;
    in.normal = {0, 0, 1};
    in.overlap = overlap;
    in.effectiveMass = 1e-3;
    in.effectiveRadius = kRadius;
    return evaluateContact(p, in, history, 1e-6);
}
} // namespace

TEST(ContactLaw, JkrFormsAtTouchAndBreaksAtDeltaC)
{
    const PairParams p = adhesivePair(NormalModel::Jkr);
    const Real breaking = jkrBreakingOverlap<Real>(kModulus, kRadius, kAdhesion);
    const Real inside = 0.5 * breaking; // apart, but within the reach
    // Approaching: not formed yet, so no force even within the reach.
    ContactHistory apart;
    EXPECT_EQ(evaluateAt(p, inside, apart).normalForce, 0.0);
    EXPECT_EQ(apart.formed, 0.0);
    // Formed at touch: the JKR force, and it holds when pulled apart to the same separation.
    ContactHistory formed;
    const ContactOutput touch = evaluateAt(p, 0.0, formed);
    EXPECT_EQ(formed.formed, 1.0);
    EXPECT_LT(touch.normalForce, 0.0);
    const ContactOutput pulled = evaluateAt(p, inside, formed);
    EXPECT_EQ(formed.formed, 1.0);
    EXPECT_NEAR(pulled.normalForce,
                jkrForce<Real>(kModulus, kRadius, kAdhesion,
                               jkrContactRadius<Real>(kModulus, kRadius, kAdhesion, inside)),
                1e-15);
    // Beyond delta_c it breaks, and stays broken until the surfaces touch again.
    EXPECT_EQ(evaluateAt(p, 1.01 * breaking, formed).normalForce, 0.0);
    EXPECT_EQ(formed.formed, 0.0);
    EXPECT_EQ(evaluateAt(p, inside, formed).normalForce, 0.0);
}

TEST(ContactLaw, AdhesiveFrictionCapTakesTheLoadPlusTwicePullOff)
{
    // Thornton & Yin (1991): sliding at |Ft| = mu (Fn + 2 F_pulloff), here with Fn < 0.
    const PairParams p = adhesivePair(NormalModel::Dmt);
    ContactHistory history;
    history.tangentialSpring = {1.0, 0, 0}; // far beyond the cap
    ContactInput in;
    in.normal = {0, 0, 1};
    in.overlap = 1e-8;
    in.effectiveMass = 1e-3;
    in.effectiveRadius = kRadius;
    const ContactOutput out = evaluateContact(p, in, history, 1e-6);
    const Real load = out.normalForce + 2 * dmtPullOffForce<Real>(kRadius, kAdhesion);
    EXPECT_LT(out.normalForce, 0.0);
    EXPECT_NEAR(length(out.tangentialForce), p.mu * load, 1e-12 * load);
}
