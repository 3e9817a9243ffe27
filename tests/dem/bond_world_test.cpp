// Bonded particles in the world (dem/bonds/bond_set.h) through a scene's `[bonds]` table: the same
// bits on 1, 2 and 3 threads, a restored checkpoint steps to the same bits (bonds and their state
// included), an outlet's particle drops its bonds, and every bad key is refused with one line
// naming it.
#include "core/error.h"
#include "dem/world.h"
#include "exec/thread_pool.h"
#include "io/dem_checkpoint.h"
#include "io/dem_scene.h"
#include "io/toml_reader.h"

#include <gtest/gtest.h>

#include <cstring>
#include <filesystem>
#include <string>

namespace
{

using namespace veridem;

// A bonded block of 8^3 glued spheres (above the parallel threshold) dropped on a shaking floor:
// the bonds near the floor break, the others hold; contacts and bonds act together.
const std::string kScene = R"(
[simulation]
dt = 5e-7
duration = 1
gravity = [0, 0, -30]
vtk = false

[[material]]
name = "rock"
density = 2500
kn = 1e5
friction = 0.5

[[wall]]
name = "floor"
material = "rock"
normal = [0, 0, 1]
oscillation_amplitude = [0, 0, 0.0002]
oscillation_omega = 3000

[[lattice]]
material = "rock"
radius = 0.001
min = [0.0, 0.0, 0.0]
max = [0.0162, 0.0162, 0.0162]
spacing = 0.00202
jitter = 0.00001
velocity = [0, 0, -0.5]
)";

const std::string kBonds = R"(
[bonds]
kn = 1e11
ks = 4e10
tensile_strength = 5e4
shear_strength = 1e5
gap = 0.00006
damping_ratio = 0.1
)";

io::DemScene makeScene(const std::string& bonds = kBonds)
{
    return io::readDemScene(io::parseText(kScene + bonds, "bonds.toml"), "bonds.toml");
}

template <class T> bool sameBits(const std::vector<T>& a, const std::vector<T>& b)
{
    return a.size() == b.size() && (a.empty() || std::memcmp(a.data(), b.data(), a.size() * sizeof(T)) == 0);
}

std::string errorOf(const std::string& bonds)
{
    try
    {
        makeScene(bonds);
    }
    catch (const InputError& e)
    {
        return e.what();
    }
    return "";
}

TEST(BondWorld, SameBitsOnOneTwoAndThreeThreads)
{
    std::vector<dem::World> worlds;
    for (const int threads : {1, 2, 3})
    {
        const exec::ThreadCountOverride loops(threads);
        io::DemScene scene = makeScene();
        dem::prepare(scene.world);
        dem::advance(scene.world, scene.dt, 1500);
        worlds.push_back(std::move(scene.world));
    }
    ASSERT_GT(worlds[0].bonds.formed, 1000u);
    ASSERT_GT(worlds[0].bonds.broken, 0u) << "the case should break some bonds";
    ASSERT_GT(worlds[0].bonds.bonds.size(), 0u);
    for (std::size_t k = 1; k < worlds.size(); ++k)
    {
        EXPECT_TRUE(sameBits(worlds[0].particles.position, worlds[k].particles.position)) << k;
        EXPECT_TRUE(sameBits(worlds[0].particles.angularVelocity, worlds[k].particles.angularVelocity)) << k;
        EXPECT_TRUE(sameBits(worlds[0].bonds.bonds, worlds[k].bonds.bonds)) << k;
        EXPECT_EQ(worlds[0].bonds.broken, worlds[k].bonds.broken);
    }
}

TEST(BondWorld, RestoredBondsStepToTheSameBits)
{
    io::DemScene original = makeScene();
    dem::prepare(original.world);
    dem::advance(original.world, original.dt, 1000);
    const auto path = std::filesystem::temp_directory_path() / "veridem_bond_checkpoint_test.bin";
    io::writeDemCheckpoint(path, original.world, 7, {{0.0}, {10, 20}, 0});
    io::DemScene restored = makeScene();
    io::readDemCheckpoint(path, restored.world, 7);
    EXPECT_TRUE(sameBits(original.world.bonds.bonds, restored.world.bonds.bonds));
    dem::advance(original.world, original.dt, 700);
    dem::advance(restored.world, restored.dt, 700);
    ASSERT_GT(original.world.bonds.broken, 0u);
    EXPECT_TRUE(sameBits(original.world.particles.position, restored.world.particles.position));
    EXPECT_TRUE(sameBits(original.world.particles.velocity, restored.world.particles.velocity));
    EXPECT_TRUE(sameBits(original.world.particles.angularVelocity, restored.world.particles.angularVelocity));
    EXPECT_TRUE(sameBits(original.world.bonds.bonds, restored.world.bonds.bonds));
    EXPECT_EQ(original.world.bonds.broken, restored.world.bonds.broken);
    std::filesystem::remove(path);
}

TEST(BondWorld, ARemovedParticleDropsItsBonds)
{
    io::DemScene scene = makeScene();
    dem::prepare(scene.world);
    dem::step(scene.world, scene.dt);
    const std::size_t before = scene.world.bonds.bonds.size();
    ASSERT_GT(before, 0u);
    // Retire particle 0 as an outlet does (radius 0 marks it); its bonds go at the next pass.
    std::size_t its = 0;
    for (const dem::Bond& b : scene.world.bonds.bonds)
        its += b.idA == scene.world.particles.id[0] || b.idB == scene.world.particles.id[0];
    ASSERT_GT(its, 0u);
    scene.world.particles.radius[0] = 0;
    scene.world.particles.position[0] = {1e30, 1e30, 1e30};
    const std::uint64_t broken = scene.world.bonds.broken;
    dem::step(scene.world, scene.dt);
    EXPECT_EQ(scene.world.bonds.dropped, its);
    EXPECT_EQ(scene.world.bonds.bonds.size(), before - its - (scene.world.bonds.broken - broken));
}

TEST(BondWorld, BadKeysAreRefusedWithTheirName)
{
    EXPECT_NE(errorOf("[bonds]\nkn = -1\nks = 1\n").find("kn"), std::string::npos);
    EXPECT_NE(errorOf("[bonds]\nkn = 1e11\nks = -1\n").find("ks"), std::string::npos);
    EXPECT_NE(errorOf("[bonds]\nkn = 1e11\nks = 4e10\ntensile_strength = 0\n").find("tensile_strength"),
              std::string::npos);
    EXPECT_NE(errorOf("[bonds]\nkn = 1e11\nks = 4e10\nshear_strength = -3\n").find("shear_strength"),
              std::string::npos);
    EXPECT_NE(errorOf("[bonds]\nkn = 1e11\nks = 4e10\nmaterials = [\"sand\"]\n").find("materials"),
              std::string::npos);
    EXPECT_NE(errorOf("[bonds]\nkn = 1e11\nks = 4e10\nradius_multiplier = 0\n").find("radius_multiplier"),
              std::string::npos);
    EXPECT_NE(errorOf("[bonds]\nkn = 1e11\nks = 4e10\nstrength = 3\n").find("strength"), std::string::npos);
    // The lattice keeps its spheres apart (spacing 2.02 mm, radius 1 mm, jitter at most 1e-5 m a
    // coordinate): with gap = 0 no pair is within reach.
    const std::string none = errorOf("[bonds]\nkn = 1e11\nks = 4e10\n");
    EXPECT_NE(none.find("gap"), std::string::npos) << none;
    // Stiff enough that dt = 5e-7 s is unstable (the limit scales as 1/sqrt(kn): ~5e-9 s here).
    const std::string unstable = errorOf("[bonds]\nkn = 1e17\nks = 4e10\ngap = 0.00004\n");
    EXPECT_NE(unstable.find("kn"), std::string::npos) << unstable;
    EXPECT_NE(unstable.find("unstable"), std::string::npos) << unstable;
    for (const std::string& e : {none, unstable})
    {
        EXPECT_EQ(e.find('\n'), std::string::npos) << e; // one line
    }
}

} // namespace
