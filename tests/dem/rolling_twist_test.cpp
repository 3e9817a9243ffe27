// The rolling torque's twist option (Material::rollingTwist, BENCHMARKS 1c): by default the torque
// opposes the whole relative angular velocity; without twist resistance only its part
// perpendicular to the contact normal.
#include "dem/contact_law.h"
#include "dem/materials.h"

#include <gtest/gtest.h>

#include <cmath>

using namespace veridem;
using namespace veridem::dem;

namespace
{
ContactOutput rollingContact(bool twist, RollingModel model)
{
    Material m;
    m.name = "ball";
    m.normalStiffness = 1e5;
    m.restitution = 1.0;
    m.rollingModel = model;
    m.rollingFrictionLength = 1e-4;
    m.rollingTwist = twist;
    const PairParams p = mixMaterials(m, m);
    ContactInput in;
    in.normal = {0, 0, 1};
    in.overlap = 1e-6;                      // Fn = 0.1 N
    in.relativeAngularVelocity = {3, 0, 4}; // rolling 3 rad/s about x, twist 4 rad/s about the normal
    in.effectiveMass = 1e-2;
    in.spinInertia = in.rollingInertia = 1e-6;
    ContactHistory h;
    return evaluateContact(p, in, h, 1e-5);
}
} // namespace

TEST(RollingTwist, DefaultOpposesTheWholeRelativeAngularVelocity)
{
    const ContactOutput out = rollingContact(true, RollingModel::ConstantTorque);
    const double magnitude = 1e-4 * 0.1; // muR Fn
    EXPECT_NEAR(out.rollingTorque.x, -magnitude * 3.0 / 5.0, 1e-18);
    EXPECT_NEAR(out.rollingTorque.z, -magnitude * 4.0 / 5.0, 1e-18);
}

TEST(RollingTwist, WithoutTwistOnlyTheRollingPartIsResisted)
{
    for (RollingModel model : {RollingModel::ConstantTorque, RollingModel::Epsd})
    {
        const ContactOutput out = rollingContact(false, model);
        EXPECT_EQ(out.rollingTorque.z, 0.0);
        EXPECT_LT(out.rollingTorque.x, 0.0);
    }
    EXPECT_NEAR(rollingContact(false, RollingModel::ConstantTorque).rollingTorque.x, -1e-4 * 0.1, 1e-18);
}

TEST(RollingTwist, PairsMixWithAnd)
{
    Material a, b;
    a.name = "a";
    b.name = "b";
    b.rollingTwist = false;
    EXPECT_TRUE(mixMaterials(a, a).rollingTwist);
    EXPECT_FALSE(mixMaterials(a, b).rollingTwist);
}
