// Scene loading: placement helpers, defaults and the errors users see.
#include "core/error.h"
#include "dem/time_step.h"
#include "io/dem_scene.h"

#include <gtest/gtest.h>

#include <cmath>
#include <string>

using namespace veridem;

namespace
{
io::DemScene load(const std::string& text)
{
    return io::readDemScene(toml::parse(std::string_view{text}, std::string_view{"scene.toml"}),
                            "scene.toml");
}

std::string errorOf(const std::string& text)
{
    try
    {
        load(text);
    }
    catch (const InputError& e)
    {
        return e.what();
    }
    return "";
}

const std::string kHeader = R"(
[simulation]
dt = 1e-5
duration = 0.1
[[material]]
name = "steel"
density = 7800
kn = 1e5
friction = 0.15
)";
} // namespace

TEST(DemScene, OnWallPlacesAtRestingOverlapWithNoSlipSpin)
{
    const io::DemScene s = load(kHeader + R"(
[[wall]]
name = "table"
type = "turntable"
material = "steel"
radius = 0.2
omega = 10
[[sphere]]
material = "steel"
radius = 0.00635
position = [-0.04, 0, 0.5]
velocity = [0, -0.107, 0]
on_wall = "table"
no_slip = true
)");
    const auto& p = s.world.particles;
    const double m = p.mass[0];
    EXPECT_NEAR(p.position[0].z, 0.00635 - m * 9.81 / 1e5, 1e-15);
    // Contact point moves with the table: v + w x (-a z) = Omega z x r.
    const Vec3 contact = p.velocity[0] + cross(p.angularVelocity[0], Vec3{0, 0, -0.00635});
    EXPECT_NEAR(contact.x, 0, 1e-15);
    EXPECT_NEAR(contact.y, -0.4, 1e-15);
    EXPECT_EQ(p.angularVelocity[0].z, 0);
}

TEST(DemScene, ErrorsNameWhatIsWrong)
{
    EXPECT_NE(errorOf(kHeader + "[[sphere]]\nmaterial = \"stel\"\nradius = 0.01\nposition = [0,0,0]\n")
                  .find("unknown material 'stel'"),
              std::string::npos);
    EXPECT_NE(errorOf(kHeader + "[[sphere]]\nmaterial = \"steel\"\nradius = -1\nposition = [0,0,0]\n")
                  .find("'radius' must be > 0 m"),
              std::string::npos);
    const std::string overlapping =
        kHeader + "[[sphere]]\nmaterial = \"steel\"\nradius = 0.01\nposition = [0,0,0]\n" +
        "[[sphere]]\nmaterial = \"steel\"\nradius = 0.01\nposition = [0.015,0,0]\n";
    EXPECT_NE(errorOf(overlapping).find("spheres 0 and 1 overlap by"), std::string::npos);
    EXPECT_NE(
        errorOf(
            "[simulation]\ndt = 1e-5\nduration = 1\n[[material]]\nname = \"a\"\ndensity = 1000\nkn = 1e3\n"
            "restitution = 1.5\n")
            .find("'restitution' must be in (0, 1]"),
        std::string::npos);
    EXPECT_NE(errorOf("[simulation]\nduration = 1\n").find("missing required key 'dt'"), std::string::npos);
}

TEST(DemScene, TimeStepLimitFromStiffnessAndMass)
{
    const io::DemScene s = load(kHeader + R"(
[[sphere]]
material = "steel"
radius = 0.00635
position = [0, 0, 0]
)");
    const dem::TimeStepEstimate e = dem::estimateTimeStep(s.world, 1.0);
    const double mStar = s.world.particles.mass[0] / 2; // a pair of equal spheres
    const double zeta = 0.0708526;                      // e = 0.8
    const double omega = std::sqrt(1e5 / mStar);
    EXPECT_NEAR(e.critical, 2 / omega * (std::sqrt(1 + zeta * zeta) - zeta), 1e-6 * e.critical);
    EXPECT_NEAR(e.contactTime, M_PI / (omega * std::sqrt(1 - zeta * zeta)), 1e-6 * e.contactTime);
}

TEST(DemScene, PairOverrideReplacesMixedValues)
{
    const io::DemScene s = load(kHeader + R"(
[[material]]
name = "rubber"
density = 1100
kn = 1e4
friction = 0.9
[[pair]]
first = "steel"
second = "rubber"
friction = 0.6
[[sphere]]
material = "steel"
radius = 0.01
position = [0, 0, 0]
)");
    EXPECT_DOUBLE_EQ(s.world.pairs(0, 1).mu, 0.6);
    EXPECT_DOUBLE_EQ(s.world.pairs(1, 0).mu, 0.6);
    EXPECT_DOUBLE_EQ(s.world.pairs(0, 0).mu, 0.15);
    EXPECT_DOUBLE_EQ(s.world.pairs(1, 1).mu, 0.9);
}
