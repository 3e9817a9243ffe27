// The stored energy of a JKR contact (models/cohesion.h, docs/measurements.md): its derivative is
// the law's force, it equals the quadrature of the force, it is zero at touch and
// jkrBreakingEnergy at delta_c; and the energy ledger of two JKR spheres that touch, stick and
// separate (or stay stuck) balances with the breaking energy booked as D_adhesion.
#include "core/constants.h"
#include "dem/contact_diagnostics.h"
#include "dem/energy_ledger.h"
#include "dem/models/cohesion.h"
#include "dem/world.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>

namespace veridem::dem
{
namespace
{

constexpr Real kModulus = 5e6;  // E* [Pa]
constexpr Real kRadius = 5e-4;  // R* [m]
constexpr Real kAdhesion = 0.2; // w [J/m^2]
constexpr Real kEps = std::numeric_limits<Real>::epsilon();

/// The law's JKR force at overlap delta >= delta_c [N] (cohesion.h, as contact_law.h uses it).
Real lawForce(Real delta)
{
    return jkrForce<Real>(kModulus, kRadius, kAdhesion,
                          jkrContactRadius<Real>(kModulus, kRadius, kAdhesion, delta));
}
Real energy(Real delta)
{
    return jkrStoredEnergy(kModulus, kRadius, kAdhesion, delta);
}
Real breakingOverlap()
{
    return jkrBreakingOverlap<Real>(kModulus, kRadius, kAdhesion);
}
/// |G(a0)| = (3/10) 2 pi w a0^2 [J]: the scale of the terms whose difference U is.
Real energyScale()
{
    const Real a0 = std::cbrt(2 * kPi * kAdhesion * kRadius * kRadius / kModulus);
    return 0.6 * kPi * kAdhesion * a0 * a0;
}

TEST(JkrEnergy, DerivativeIsTheLawsForce)
{
    // Central differences (U(d + h) - U(d - h)) / 2h: truncation h^2 |F''| / 6, F'' bounded by a
    // second difference of the force over 10 h (doubled: the bound is itself estimated), and
    // rounding ~4 eps (|G(a)| + |G(a0)|) / 2h, bounded by 8 eps (|U| + scale) / h.
    const Real dc = breakingOverlap();
    for (const Real factor : {-0.9, -0.5, 0.0, 0.5, 2.0, 10.0, 40.0}) // delta / |delta_c|
    {
        const Real delta = factor * std::abs(dc);
        const Real h = 1e-3 * std::abs(dc);
        const Real derivative = (energy(delta + h) - energy(delta - h)) / (2 * h);
        const Real H = 10 * h;
        const Real second =
            std::abs(lawForce(delta + H) - 2 * lawForce(delta) + lawForce(delta - H)) / (H * H);
        const Real tolerance =
            2 * h * h * second / 6 + 8 * kEps * (std::abs(energy(delta)) + energyScale()) / h;
        EXPECT_NEAR(derivative, lawForce(delta), tolerance) << "delta / |delta_c| = " << delta / -dc;
        EXPECT_LT(tolerance, 1e-5 * jkrPullOffForce<Real>(kRadius, kAdhesion)); // a sharp test
    }
}

/// Composite Simpson of the law's force over [d0, d1] with n (even) intervals in s, delta =
/// d0 + (d1 - d0) s^2 (the substitution removes the square-root singularity of F at delta_c).
Real simpsonOfForce(Real d0, Real d1, int n)
{
    const auto f = [&](Real s) { return lawForce(d0 + (d1 - d0) * s * s) * 2 * (d1 - d0) * s; };
    Real sum = f(0) + f(1);
    for (int k = 1; k < n; ++k)
        sum += (k % 2 ? 4 : 2) * f(Real(k) / n);
    return sum / (3 * n);
}

TEST(JkrEnergy, EqualsTheQuadratureOfTheForce)
{
    // U(d1) - U(d0) against Simpson with 400 and 800 intervals: Simpson's error of the finer one
    // is ~|Q_800 - Q_400| / 15; the rounding of U is ~eps scale.
    const Real dc = breakingOverlap();
    for (const auto& [d0, d1] : {std::pair{dc, 0.0}, std::pair{0.0, -5 * dc}, std::pair{dc, -20 * dc},
                                 std::pair{-0.3 * dc, 0.7 * dc}})
    {
        const Real coarse = simpsonOfForce(d0, d1, 400), fine = simpsonOfForce(d0, d1, 800);
        const Real tolerance = std::abs(fine - coarse) + 16 * kEps * energyScale();
        EXPECT_NEAR(energy(d1) - energy(d0), fine, tolerance) << d0 << " " << d1;
        EXPECT_LT(tolerance, 1e-7 * energyScale());
    }
}

TEST(JkrEnergy, ZeroAtTouchBreakingEnergyAtDeltaCAndHertzWithoutAdhesion)
{
    EXPECT_NEAR(energy(0.0), 0.0, 8 * kEps * energyScale()); // a(0) = a0 to round-off
    // At delta_c, a is found to ~sqrt(eps) (a double root), but dU/da = 0 there: U to ~eps.
    const Real breaking = jkrBreakingEnergy(kModulus, kRadius, kAdhesion);
    EXPECT_NEAR(energy(breakingOverlap()), breaking, 16 * kEps * energyScale());
    EXPECT_GT(breaking, 0);
    // Below delta_c: clamped to U(delta_c).
    EXPECT_EQ(energy(2 * breakingOverlap()), energy(breakingOverlap()));
    // w = 0: Hertz (8/15) E* sqrt(R*) delta^(5/2), through normalElasticEnergy.
    PairParams p;
    p.normalModel = NormalModel::Jkr;
    p.effectiveModulus = kModulus;
    const Real delta = 1e-6;
    const Real hertz = 8.0 / 15.0 * kModulus * std::sqrt(kRadius) * std::pow(delta, 2.5);
    EXPECT_NEAR(normalElasticEnergy(p, delta, kRadius), hertz, 1e-13 * hertz);
    EXPECT_EQ(normalElasticEnergy(p, -delta, kRadius), 0.0);
}

struct Collision
{
    Real initialKinetic = 0, finalKinetic = 0, residual = 0, dissipated = 0, adhesion = 0, elastic = 0;
    Real breaking = 0; // jkrBreakingEnergy of the pair [J]
};

/// Two equal JKR spheres (R = 1 mm: R* = 0.5 mm, E = 1e7 Pa, nu = 0.3, gamma = 0.1 J/m^2,
/// e = 0.5, no friction) approach head-on at relative speed `speed` [m/s] from a 10 um gap.
Collision collide(Real speed, Real dt, int steps, Real gamma = 0.1)
{
    World world;
    Material m;
    m.name = "adhesive";
    m.normalModel = NormalModel::Jkr;
    m.youngsModulus = 1e7;
    m.poissonRatio = 0.3;
    m.surfaceEnergy = gamma;
    m.restitution = 0.5;
    m.friction = 0;
    world.addMaterial(m);
    world.gravity = {0, 0, 0};
    const Real r = 1e-3, half = r + 5e-6;
    world.particles.add({-half, 0, 0}, {0.5 * speed, 0, 0}, {}, r, 2500, 0);
    world.particles.add({half, 0, 0}, {-0.5 * speed, 0, 0}, {}, r, 2500, 0);
    prepare(world);
    EnergyLedger ledger;
    ledger.start(world);
    world.observer = &ledger;
    Collision c;
    c.initialKinetic = kineticEnergy(world);
    for (int s = 0; s < steps; ++s)
        step(world, dt);
    c.finalKinetic = kineticEnergy(world);
    c.residual = ledger.residual(world);
    c.dissipated = ledger.dissipated();
    c.adhesion = ledger.state.adhesion;
    c.elastic = ledger.state.elasticEnergy;
    const PairParams& p = world.pairs(0, 0);
    c.breaking = jkrBreakingEnergy(p.effectiveModulus, 0.5 * r, p.workOfAdhesion);
    return c;
}

/// The largest error of the balance from the force's jumps at formation (to -(4/3) pi w R*, at
/// relative normal speed vIn [m/s]) and at the break (from -(5/6) pi w R*, at vOut) [J]: each
/// jump falls somewhere inside a step while the force sampled at the step acts over the kick
/// window centred on it, so its work is off by up to |F| |v| dt / 2 (docs/measurements.md).
Real jumpBound(Real vIn, Real vOut, Real dt, bool broke)
{
    const Real w = 0.2, rStar = 0.5e-3;
    return (4.0 / 3.0 * kPi * w * rStar * vIn + (broke ? 5.0 / 6.0 * kPi * w * rStar * vOut : 0)) * 0.5 * dt;
}

/// The relative normal speed after a collision that separated, from the final kinetic energy.
Real speedAfter(const Collision& c)
{
    const Real mass = 2500 * 4.0 / 3.0 * kPi * 1e-9; // each sphere [kg]
    return std::sqrt(2 * c.finalKinetic / (0.5 * mass));
}

TEST(JkrEnergy, LedgerBalancesThroughTouchStickAndPullOff)
{
    // 0.2 m/s: m* = 5.2e-6 kg, E_kin = 1.0e-7 J against a breaking energy of 6.2e-10 J: the
    // spheres stick, rebound and pull apart (one formation, one break). t_c ~ 3e-4 s; dt = 1e-6 s.
    const Real dt = 1e-6;
    const Collision c = collide(0.2, dt, 1500);
    EXPECT_EQ(c.elastic, 0.0);         // separated
    EXPECT_EQ(c.adhesion, c.breaking); // one break, booked at its closed form
    EXPECT_GT(c.dissipated, 0.5 * c.initialKinetic);
    // The rest of the balance is the integrator's O(dt^2) error: that of the same collision
    // without adhesion (w = 0: Hertz with the same damping, 1.5e-12 J), doubled as a margin.
    const Collision hertz = collide(0.2, dt, 1500, 0.0);
    const Real bound = jumpBound(0.2, speedAfter(c), dt, true) + 2 * std::abs(hertz.residual);
    EXPECT_LT(std::abs(c.residual), bound) << c.residual / c.dissipated; // 4.3e-4 of D_total
    // Without D_adhesion the balance would be off by the breaking energy, 10 times the bound.
    EXPECT_GT(c.breaking, 10 * bound);
    // Halving dt: the jumps' bound halves.
    const Collision half = collide(0.2, 0.5 * dt, 3000);
    EXPECT_EQ(half.adhesion, half.breaking);
    EXPECT_LT(std::abs(half.residual),
              jumpBound(0.2, speedAfter(half), 0.5 * dt, true) + 2 * std::abs(hertz.residual) / 4);
}

TEST(JkrEnergy, LedgerBalancesForAContactThatStaysStuck)
{
    // 0.01 m/s: E_kin = 2.6e-10 J, below the breaking energy: the spheres stick and ring down
    // (no break: D_adhesion = 0) to the JKR equilibrium, where the stored energy is negative.
    // The 10 um gap takes exactly 1000 steps, so the touch falls on a step: the formation jump's
    // error is at its bound F v dt / 2 (2.1e-12 J, 3e-3 of the energy dissipated). It is first
    // order: dt / 2 halves the residual to 1e-3 of itself, so the O(dt^2) rest is below 5 % of it.
    const Real dt = 1e-6;
    const Collision c = collide(0.01, dt, 20000);
    EXPECT_EQ(c.adhesion, 0.0);
    EXPECT_LT(c.elastic, 0.0);
    EXPECT_LT(c.finalKinetic, 1e-6 * c.initialKinetic);
    EXPECT_LT(std::abs(c.residual), 1.05 * jumpBound(0.01, 0, dt, false)) << c.residual / c.dissipated;
    const Collision half = collide(0.01, 0.5 * dt, 40000);
    EXPECT_NEAR(half.residual / c.residual, 0.5, 0.05 * 0.5);
}

} // namespace
} // namespace veridem::dem
