// The parallel bond law (dem/bonds/bond_law.h) against its formulas, one mode at a time, and its
// objectivity under a rigid rotation of the pair.
#include "core/constants.h"
#include "dem/bonds/bond_law.h"

#include <gtest/gtest.h>

#include <cmath>

using namespace veridem;
using namespace veridem::dem;

namespace
{

constexpr Real kR = 1e-3; // partners' radius [m]

BondParams params()
{
    BondParams p;
    p.normalStiffness = 2e13; // [N/m^3]
    p.shearStiffness = 8e12;
    p.radiusMultiplier = 0.5;
    return p;
}

/// Two spheres of radius kR on the x axis, a at 0, b at 2 kR + gap, at rest.
BondPartners restingPair(Real gap = 0)
{
    return {{0, 0, 0}, {2 * kR + gap, 0, 0}, {}, {}, {}, {}, kR, kR, 1e-5, 1e-12};
}

// Round-off of a few products of O(1) numbers scaled to the load: 1e-12 relative.
constexpr Real kRoundOff = 1e-12;

} // namespace

TEST(BondLaw, SectionOfTheCementCylinder)
{
    const BondSection s = bondSection(params(), kR, 2 * kR);
    const Real rb = 0.5 * kR;
    EXPECT_DOUBLE_EQ(s.radius, rb);
    EXPECT_DOUBLE_EQ(s.area, kPi * rb * rb);
    EXPECT_DOUBLE_EQ(s.bend, kPi * std::pow(rb, 4) / 4);
    EXPECT_DOUBLE_EQ(s.twist, kPi * std::pow(rb, 4) / 2);
}

TEST(BondLaw, AxialStretchGivesKnATimesStretch)
{
    const BondParams p = params();
    BondPartners q = restingPair();
    BondState s = formBond(q.xa, q.xb);
    const Real stretch = 1e-7;
    q.xb.x += stretch;
    const BondLoad load = bondStep(p, s, q, 1e-8);
    const Real expected = p.normalStiffness * bondSection(p, kR, kR).area * stretch;
    EXPECT_NEAR(load.forceOnB.x, -expected,
                kRoundOff * expected * 1e3); // (d - d0: a difference of 2e-3 and 1e-7)
    EXPECT_EQ(load.forceOnB.y, 0);
    EXPECT_EQ(load.torqueOnA.y, 0);
    EXPECT_NEAR(load.tensileStress, expected / bondSection(p, kR, kR).area, 1e-9 * load.tensileStress);
}

TEST(BondLaw, ShearDisplacementGivesKsATimesIt)
{
    const BondParams p = params();
    BondPartners q = restingPair();
    BondState s = formBond(q.xa, q.xb);
    const Real dt = 1e-7, u = 0.01; // b moves along y at u over dt
    q.vb = {0, u, 0};
    const BondLoad load = bondStep(p, s, q, dt);
    const BondSection sec = bondSection(p, kR, kR);
    const Real fs = p.shearStiffness * sec.area * u * dt;
    EXPECT_NEAR(load.forceOnB.y, -fs, kRoundOff * fs);
    // Torques: the force acts at the contact point c = (kR, 0, 0): T_b = (c - xb) x F_b, T_a = (c - xa) x
    // F_a.
    EXPECT_NEAR(load.torqueOnB.z, (-kR) * (-fs), kRoundOff * fs * kR);
    EXPECT_NEAR(load.torqueOnA.z, kR * fs, kRoundOff * fs * kR);
    EXPECT_NEAR(load.shearStress, fs / sec.area, kRoundOff * fs / sec.area);
}

TEST(BondLaw, TwistGivesKsJTimesAngle)
{
    const BondParams p = params();
    BondPartners q = restingPair();
    BondState s = formBond(q.xa, q.xb);
    const Real dt = 1e-7, w = 3.0;
    q.wb = {w, 0, 0};
    const BondLoad load = bondStep(p, s, q, dt);
    const BondSection sec = bondSection(p, kR, kR);
    const Real mt = p.shearStiffness * sec.twist * w * dt;
    EXPECT_NEAR(load.torqueOnB.x, -mt, kRoundOff * mt);
    EXPECT_NEAR(load.torqueOnA.x, mt, kRoundOff * mt);
    EXPECT_EQ(lengthSquared(load.forceOnB), 0);
    EXPECT_NEAR(load.shearStress, mt * sec.radius / sec.twist, kRoundOff * mt * sec.radius / sec.twist);
}

TEST(BondLaw, RelativeRotationBendsWithKnI)
{
    // b turns about z: the bending moment -kn I w dt, and b's surface point at c moves by
    // w x (c - xb) dt = (0, -kR w dt, 0), which loads the shear spring too.
    const BondParams p = params();
    BondPartners q = restingPair();
    BondState s = formBond(q.xa, q.xb);
    const Real dt = 1e-7, w = 3.0;
    q.wb = {0, 0, w};
    const BondLoad load = bondStep(p, s, q, dt);
    const BondSection sec = bondSection(p, kR, kR);
    const Real mb = p.normalStiffness * sec.bend * w * dt;
    const Real fs = p.shearStiffness * sec.area * kR * w * dt; // +y on b
    EXPECT_NEAR(load.forceOnB.y, fs, kRoundOff * fs);
    EXPECT_NEAR(load.torqueOnB.z, -mb + (-kR) * fs, kRoundOff * (mb + kR * fs));
    EXPECT_NEAR(load.torqueOnA.z, mb + (-kR) * fs, kRoundOff * (mb + kR * fs));
    EXPECT_NEAR(load.tensileStress, mb * sec.radius / sec.bend, kRoundOff * mb * sec.radius / sec.bend);
}

TEST(BondLaw, AngularMomentumIsConserved)
{
    // F_a = -F_b and xa x F_a + xb x F_b + T_a + T_b = 0 for any motion.
    const BondParams p = params();
    BondPartners q = restingPair(2e-5);
    q.xa = {1e-4, -2e-4, 3e-4};
    BondState s = formBond(q.xa, q.xb);
    q.xb = q.xb + Vec3{1e-6, 2e-6, -1e-6};
    q.va = {0.1, -0.3, 0.2};
    q.vb = {-0.2, 0.1, 0.4};
    q.wa = {5, -7, 2};
    q.wb = {-3, 4, 9};
    const BondLoad load = bondStep(p, s, q, 1e-6);
    const Vec3 l = cross(q.xa, -load.forceOnB) + cross(q.xb, load.forceOnB) + load.torqueOnA + load.torqueOnB;
    const Real scale = length(load.forceOnB) * kR + length(load.torqueOnA) + length(load.torqueOnB);
    EXPECT_LT(length(l), 1e-12 * scale);
}

namespace
{

/// The pair turning rigidly about `axis` (unit) at rate w [rad/s] for `steps` of dt [s] from the
/// bond's formation, with b's bond preloaded by a stored shear force `f0` (perpendicular to x).
/// Returns the largest relative error of the stored shear force against f0 turned with the pair.
Real rigidTurnError(const Vec3& axis, Real w, Real dt, int steps, const Vec3& f0, BondLoad* last)
{
    const BondParams p = params();
    BondPartners q = restingPair();
    const Vec3 xa0 = q.xa - Vec3{kR, 0, 0}, xb0 = q.xb - Vec3{kR, 0, 0}; // centred on the origin
    BondState s = formBond(xa0, xb0);
    s.shearForce = f0;
    Real worst = 0;
    for (int k = 1; k <= steps; ++k)
    {
        const Real angle = w * dt * k;
        q.xa = rotateAbout(xa0, axis, angle);
        q.xb = rotateAbout(xb0, axis, angle);
        q.wa = q.wb = w * axis;
        q.va = cross(q.wa, q.xa); // (the rigid velocity field at the positions given to the law)
        q.vb = cross(q.wb, q.xb);
        *last = bondStep(p, s, q, dt);
        const Vec3 expected = rotateAbout(f0, axis, angle);
        worst = std::fmax(worst, length(s.shearForce - expected) / length(f0));
    }
    return worst;
}

} // namespace

TEST(BondLaw, RigidRotationGivesNoLoadAndTurnsTheStoredForce)
{
    BondLoad last{};
    // An unloaded bond stays unloaded (to round-off of the positions' rotation).
    rigidTurnError({0, 0, 1}, 50.0, 1e-4, 2000, {0, 0, 0}, &last);
    EXPECT_LT(length(last.forceOnB), 1e-12 * params().shearStiffness * kR * kR * kR);
    EXPECT_LT(length(last.torqueOnB), 1e-12 * params().shearStiffness * kR * kR * kR * kR);

    // About an axis normal to the bond the frame update is that rotation itself: exact to round-off,
    // a few ulps a step (the rotations of the vector and of the positions) over 2000 steps: 1e-10.
    const Vec3 f0{0, 1e-3, 0};
    EXPECT_LT(rigidTurnError({0, 0, 1}, 50.0, 1e-4, 2000, f0, &last), 1e-10);
    // About an oblique axis the tilt and the spin are composed per step (the spin about the new
    // normal): measured second order in dt over a given angle (8e-7 after 1 rad at w dt = 5e-3).
    // Halving dt quarters it (order 2 within 0.1).
    const Vec3 axis = Vec3{1, 1, 1} / std::sqrt(3.0);
    const Real e1 = rigidTurnError(axis, 50.0, 1e-4, 200, f0, &last);
    const Real e2 = rigidTurnError(axis, 50.0, 0.5e-4, 400, f0, &last);
    EXPECT_LT(e1, 1e-5);
    ASSERT_GT(e1, 1e-12);
    EXPECT_NEAR(std::log2(e1 / e2), 2.0, 0.1) << e1 << " " << e2;
}

TEST(BondLaw, BreaksAtItsTensileStrength)
{
    BondParams p = params();
    const BondSection sec = bondSection(p, kR, kR);
    p.tensileStrength = 1e6;
    const Real breakingStretch = p.tensileStrength / p.normalStiffness; // sigma = kn stretch
    for (const Real factor : {0.999, 1.001})
    {
        BondPartners q = restingPair();
        BondState s = formBond(q.xa, q.xb);
        q.xb.x += factor * breakingStretch;
        const BondLoad load = bondStep(p, s, q, 1e-8);
        EXPECT_EQ(load.broken, factor > 1) << factor;
        if (load.broken)
        {
            EXPECT_EQ(lengthSquared(load.forceOnB), 0);
        }
        else
        {
            EXPECT_NEAR(-load.forceOnB.x, factor * p.tensileStrength * sec.area,
                        1e-6 * p.tensileStrength * sec.area);
        }
    }
}

TEST(BondLaw, BreaksAtItsShearStrength)
{
    BondParams p = params();
    p.shearStrength = 1e5;
    const Real dt = 1e-6;
    const Real breakingSlide = p.shearStrength / p.shearStiffness; // tau = ks u
    for (const Real factor : {0.999, 1.001})
    {
        BondPartners q = restingPair();
        BondState s = formBond(q.xa, q.xb);
        q.vb = {0, 0, factor * breakingSlide / dt};
        EXPECT_EQ(bondStep(p, s, q, dt).broken, factor > 1) << factor;
    }
}
