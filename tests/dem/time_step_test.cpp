// The stable time step (time_step.cpp): the viscous rolling (type B) bound 2 I_r / (c_r Fn R_r^2)
// enters the estimate, and the integrator's spin decays or grows across it as derived there
// (half-step spin multiplied by 1 - lambda dt each step).
#include "dem/time_step.h"
#include "dem/world.h"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

using namespace veridem;
using namespace veridem::dem;

namespace
{
constexpr double kRadius = 0.01, kDensity = 2500, kn = 1e5, kG = 9.81; // m, kg/m^3, N/m, m/s^2

double mass()
{
    return 4.0 / 3.0 * std::numbers::pi * kRadius * kRadius * kRadius * kDensity;
}

// One ball of viscous rolling coefficient cr [s/m] resting on a frictionless floor at its
// equilibrium overlap (Fn = m g), spinning about x at w0 [rad/s].
World restingBall(double cr, double w0)
{
    Material m;
    m.name = "ball";
    m.density = kDensity;
    m.normalStiffness = kn;
    m.friction = 0; // no tangential force: only the rolling torque acts on the spin
    m.rollingModel = RollingModel::Viscous;
    m.rollingViscousCoefficient = cr;
    World w;
    w.addMaterial(m);
    w.gravity = {0, 0, -kG};
    Wall floor;
    floor.name = "floor";
    floor.shape = PlaneShape{{0, 0, 0}, {0, 0, 1}};
    w.walls.push_back(floor);
    w.particles.add({0, 0, kRadius - mass() * kG / kn}, {}, {w0, 0, 0}, kRadius, kDensity, 0);
    return w;
}
} // namespace

TEST(TimeStep, ViscousRollingLimitIsTwoInertiaOverDampingCoefficient)
{
    EXPECT_DOUBLE_EQ(viscousRollingLimit(3.0, 2.0, 0.1, 5e-4), 2 * 5e-4 / (3.0 * 2.0 * 0.01));
    EXPECT_TRUE(std::isinf(viscousRollingLimit(0.0, 2.0, 0.1, 5e-4)));
}

TEST(TimeStep, ViscousRollingSetsTheEstimateWhenBelowTheContactLimit)
{
    // c_r = 10 s/m: 2 I / (c_r Fn a^2) with Fn = sqrt(kn m) v (impact at v = 1 m/s, 32 N, above
    // the weight 0.10 N) is 2.6e-5 s, below the contact's 6e-4 s.
    const World w = restingBall(10, 0);
    const TimeStepEstimate e = estimateTimeStep(w, 1.0);
    const double inertia = 0.4 * mass() * kRadius * kRadius;
    const double fn = std::sqrt(kn * mass()) * 1.0;
    EXPECT_NEAR(e.critical, 2 * inertia / (10 * fn * kRadius * kRadius), 1e-12 * e.critical);
    EXPECT_NE(e.limitedBy.find("viscous rolling"), std::string::npos) << e.limitedBy;
    // A small coefficient leaves the contact limit in charge.
    EXPECT_EQ(estimateTimeStep(restingBall(0.1, 0), 1.0).limitedBy.find("viscous"), std::string::npos);
}

TEST(TimeStep, SpinDecaysBelowTheViscousLimitAndGrowsAboveIt)
{
    // At rest the load is the weight (the impact force at the smallest speed, 1e-3 m/s, is below
    // it), so the estimate's bound is the one the ball meets. Per step the spin is multiplied by
    // 1 - lambda dt (time_step.cpp), lambda = c_r m g a^2 / I; after the first step the full-step
    // spin follows the same factor. Tolerance 1e-9 relative: the only departure is the settled
    // overlap's round-off in Fn (1e-16 relative) compounded over 40 steps.
    const double cr = 500, inertia = 0.4 * mass() * kRadius * kRadius;
    const double lambda = cr * mass() * kG * kRadius * kRadius / inertia;
    const double limit = estimateTimeStep(restingBall(cr, 1.0), 1e-3).critical;
    ASSERT_NEAR(limit, 2 / lambda, 1e-12 * limit);
    for (const double fraction : {0.9, 0.98, 1.02, 1.1})
    {
        World w = restingBall(cr, 0.0);
        const double dt = fraction * limit;
        prepare(w);
        // The first step's half kick has no contact force yet, which sets the ball bouncing on its
        // contact spring (+-25 % in Fn at this dt); 3000 steps (0.4 s, 90 damping times) settle it
        // to Fn = m g before the spin starts.
        for (int s = 0; s < 3000; ++s)
            step(w, dt);
        w.particles.angularVelocity[0] = {1.0, 0, 0};
        step(w, dt);
        const double w1 = w.particles.angularVelocity[0].x;
        const int n = 40;
        for (int s = 1; s < n; ++s)
            step(w, dt);
        const double expected = w1 * std::pow(1 - lambda * dt, n - 1);
        EXPECT_NEAR(w.particles.angularVelocity[0].x, expected, 1e-9 * std::fabs(expected)) << fraction;
        EXPECT_EQ(std::fabs(w.particles.angularVelocity[0].x) < std::fabs(w1), fraction < 1) << fraction;
    }
}
