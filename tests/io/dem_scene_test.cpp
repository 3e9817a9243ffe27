// Scene loading: placement helpers, defaults and the errors users see.
#include "core/error.h"
#include "dem/time_step.h"
#include "io/dem_scene.h"
#include "scene_text.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <string>

using namespace veridem;

namespace
{
io::DemScene load(const std::string& text)
{
    return test::loadScene(text);
}

std::string errorOf(const std::string& text)
{
    return test::sceneError(text);
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
    const std::string material =
        "[simulation]\ndt = 1e-5\nduration = 1\n[[material]]\nname = \"a\"\ndensity = 1000\nkn = 1e3\n";
    EXPECT_NE(errorOf(material + "rolling_model = \"viscous\"\n")
                  .find("'rolling_viscous_coefficient' is required by rolling_model = \"viscous\""),
              std::string::npos);
    const std::string wall = material + "[[wall]]\nname = \"plate\"\nmaterial = \"a\"\nnormal = [0,0,1]\n";
    EXPECT_NE(errorOf(wall + "oscillation_omega = -1\n").find("'oscillation_omega' must be >= 0"),
              std::string::npos);
    EXPECT_NE(
        errorOf(wall + "oscillation_omega = 10\nvelocity = [1,0,0]\n").find("cannot also have a steady"),
        std::string::npos);
}

TEST(DemScene, ReadsTheNewRollingModelsAndTheOscillatingPlate)
{
    const io::DemScene s = load(R"([simulation]
dt = 1e-5
duration = 1
[[material]]
name = "a"
density = 1000
kn = 1e3
rolling_model = "viscous"
rolling_viscous_coefficient = 0.25
[[material]]
name = "b"
density = 1000
kn = 1e3
rolling_model = "constant_torque_absolute"
rolling_friction = 1e-5
[[wall]]
name = "plate"
material = "a"
normal = [0, 0, 1]
oscillation_amplitude = [0, 0, 0.001]
oscillation_omega = 125.0
[[sphere]]
material = "a"
radius = 0.01
position = [0, 0, 0.02]
)");
    EXPECT_EQ(s.world.materials[0].rollingModel, dem::RollingModel::Viscous);
    EXPECT_EQ(s.world.materials[0].rollingViscousCoefficient, 0.25);
    EXPECT_EQ(s.world.materials[1].rollingModel, dem::RollingModel::ConstantTorqueAbsolute);
    EXPECT_EQ(s.world.walls[0].motion.oscillationAmplitude.z, 0.001);
    EXPECT_EQ(s.world.walls[0].motion.oscillationAngularFrequency, 125.0);
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

TEST(DemScene, CappedCylinderAddsTwoDiskWallsSharingItsMotion)
{
    const io::DemScene s = load(kHeader + R"(
[[wall]]
name = "drum"
type = "cylinder"
material = "steel"
point = [0, 0, 0]
axis = [0, 2, 0]
radius = 0.05
length = 0.03
caps = true
omega_table = [[0, 0], [1, 4]]
active_until = 2
[[sphere]]
material = "steel"
radius = 0.005
position = [0, 0.015, 0]
)");
    const auto& walls = s.world.walls;
    ASSERT_EQ(walls.size(), 3u);
    EXPECT_EQ(walls[1].name, "drum/cap0");
    EXPECT_EQ(walls[2].name, "drum/cap1");
    const auto& c = std::get<dem::CylinderShape>(walls[0].shape);
    EXPECT_EQ(c.axis, (Vec3{0, 1, 0}));
    const auto& cap0 = std::get<dem::PlaneShape>(walls[1].shape);
    const auto& cap1 = std::get<dem::PlaneShape>(walls[2].shape);
    EXPECT_EQ(cap0.normal, (Vec3{0, 1, 0})); // facing into the drum
    EXPECT_EQ(cap1.normal, (Vec3{0, -1, 0}));
    EXPECT_EQ(cap1.point, (Vec3{0, 0.03, 0}));
    EXPECT_EQ(cap0.diskRadius, 0.05);
    for (const auto& w : walls)
    {
        EXPECT_EQ(w.motion.angularVelocityTable.at(0.5), (Vec3{0, 2, 0}));
        EXPECT_EQ(w.activeUntil, 2);
        EXPECT_EQ(w.loadPoint, (Vec3{0, 0, 0}));
    }
}

TEST(DemScene, WallMotionKeysAreChecked)
{
    const std::string plane = kHeader + R"(
[[sphere]]
material = "steel"
radius = 0.005
position = [0, 0, 0.1]
[[wall]]
name = "floor"
material = "steel"
normal = [0, 0, 1]
)";
    EXPECT_NE(errorOf(plane + "velocity = [0, 0, 1]\nvelocity_table = [[0, 0, 0, 1]]\n")
                  .find("'velocity_table' cannot be combined with a constant 'velocity'"),
              std::string::npos);
    EXPECT_NE(errorOf(plane + "velocity_table = [[0, 0, 0, 1], [0, 0, 0, 2]]\n").find("strictly increasing"),
              std::string::npos);
    EXPECT_NE(errorOf(plane + "velocity_table = [[0, 0, 1]]\n").find("rows of 4 numbers"), std::string::npos);
    EXPECT_NE(errorOf(plane + "active_from = 1\nactive_until = 0.5\n").find("'active_until' must be after"),
              std::string::npos);
    EXPECT_NE(errorOf(plane + "caps = true\n").find("caps"), std::string::npos); // not a plane key
}

TEST(DemScene, ZonesSpeciesAndTrackedParticlesAreRead)
{
    const std::string scene = kHeader + R"(
[[material]]
name = "glass"
density = 2500
kn = 1e4
[output]
species = true
track = [0]
[[zone]]
name = "upper"
min = [-1, -1, 0]
materials = ["glass"]
[[zone]]
name = "all"
[[sphere]]
material = "glass"
radius = 0.01
position = [0, 0, 0]
)";
    const io::DemScene s = load(scene);
    ASSERT_EQ(s.measurements.zones.size(), 2u);
    EXPECT_EQ(s.measurements.zones[0].materials, (std::vector<std::uint32_t>{1}));
    EXPECT_EQ(s.measurements.zones[0].lo.z, 0);
    EXPECT_EQ(s.measurements.zones[0].hi.x, std::numeric_limits<Real>::infinity());
    EXPECT_EQ(s.measurements.zones[1].materials, (std::vector<std::uint32_t>{0, 1})); // (every material)
    EXPECT_TRUE(s.measurements.species);
    EXPECT_EQ(s.measurements.track, (std::vector<std::uint32_t>{0}));
    // An unknown material is named with the key, its line and the scene's materials.
    EXPECT_NE(errorOf(kHeader + "[[zone]]\nname = \"z\"\nmaterials = [\"M3\"]\n").find("scene.toml:12"),
              std::string::npos)
        << errorOf(kHeader + "[[zone]]\nname = \"z\"\nmaterials = [\"M3\"]\n");
    EXPECT_NE(errorOf(kHeader + "[[zone]]\nname = \"z\"\nmaterials = [\"M3\"]\n")
                  .find("'materials' names an unknown material 'M3' (the scene's [[material]] names: steel)"),
              std::string::npos);
    EXPECT_NE(errorOf(kHeader + "[[zone]]\nname = \"z\"\nmin = [0, 0, 1]\nmax = [1, 1, 1]\n")
                  .find("'max' must exceed min"),
              std::string::npos);
    EXPECT_NE(errorOf(kHeader + "[output]\ntrack = [1.5]\n").find("'track' must be an array of particle ids"),
              std::string::npos);
}
