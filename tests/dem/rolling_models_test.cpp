// Type B (viscous) and the absolute-frame type A rolling models (models/rolling.h), and the
// sinusoidal wall translation (walls/wall.h, integrate.h moveWalls), against their formulas.
#include "dem/contact_law.h"
#include "dem/integrate.h"
#include "dem/materials.h"

#include <gtest/gtest.h>

#include <cmath>

using namespace veridem;
using namespace veridem::dem;

namespace
{
ContactOutput contact(RollingModel model, const Vec3& relative, const Vec3& own)
{
    Material m;
    m.name = "ball";
    m.normalStiffness = 1e5;
    m.restitution = 1.0;
    m.rollingModel = model;
    m.rollingFrictionLength = model == RollingModel::Viscous ? 0.0 : 1e-4;
    m.rollingViscousCoefficient = model == RollingModel::Viscous ? 0.5 : 0.0;
    const PairParams p = mixMaterials(m, m);
    ContactInput in;
    in.normal = {0, 0, 1};
    in.overlap = 1e-6; // Fn = 0.1 N
    in.relativeAngularVelocity = relative;
    in.angularVelocity = own;
    in.effectiveMass = 1e-2;
    in.effectiveRadius = 2e-3;
    in.spinInertia = in.rollingInertia = 1e-6;
    ContactHistory h;
    return evaluateContact(p, in, h, 1e-5);
}
} // namespace

TEST(RollingModels, ViscousTorqueIsMinusCrFnRr2TimesRelativeOmega)
{
    const ContactOutput out = contact(RollingModel::Viscous, {3, 0, 4}, {100, 0, 0});
    const double scale = 0.5 * 0.1 * 2e-3 * 2e-3; // c_r Fn R_r^2
    EXPECT_NEAR(out.rollingTorque.x, -3 * scale, 1e-15);
    EXPECT_NEAR(out.rollingTorque.y, 0, 1e-18);
    EXPECT_NEAR(out.rollingTorque.z, -4 * scale, 1e-15);
}

TEST(RollingModels, AbsoluteFrameOpposesTheParticlesOwnOmega)
{
    // Relative w is along x, own w along y: the absolute model ignores the relative one.
    const ContactOutput out = contact(RollingModel::ConstantTorqueAbsolute, {5, 0, 0}, {0, 2, 0});
    EXPECT_NEAR(out.rollingTorque.x, 0, 1e-18);
    EXPECT_NEAR(out.rollingTorque.y, -1e-4 * 0.1, 1e-15); // -muR Fn w/|w|
    EXPECT_NEAR(out.rollingTorque.z, 0, 1e-18);
}

TEST(RollingModels, ViscousCoefficientMustNotBeNegative)
{
    Material m;
    m.name = "ball";
    m.rollingViscousCoefficient = -1;
    EXPECT_THROW(validateMaterial(m), std::exception);
}

TEST(WallOscillation, PositionExactAndVelocityAtTheHalfStep)
{
    std::vector<Wall> walls(1);
    walls[0].shape = PlaneShape{};
    walls[0].motion.oscillationAmplitude = {0, 0, 2e-3};
    walls[0].motion.oscillationAngularFrequency = 30;
    const double dt = 1e-3;
    for (int k = 0; k < 77; ++k)
        moveWalls(walls, dt);
    const double t = 77 * dt;
    EXPECT_NEAR(walls[0].displacement.z, 2e-3 * std::sin(30 * t), 1e-15);
    EXPECT_NEAR(walls[0].motion.velocity.z, 2e-3 * 30 * std::cos(30 * (t - dt / 2)), 1e-15);
    EXPECT_EQ(walls[0].displacement.x, 0);
}
