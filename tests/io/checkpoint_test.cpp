// The 3D checkpoint in process: a world restored from a checkpoint steps to the same bits as the
// world that wrote it; every truncation and a sweep of byte flips of a checkpoint are refused
// with an InputError (or, for a flip the checks cannot see, read without harm), never a crash
// (this runs under ASan + UBSan in the asan preset); particles retired by an outlet restore to the
// same run. The run-level checks (straight vs interrupted runs, 2D, signals) are
// tests/io/restart_check.py.
#include "core/error.h"
#include "dem/particle_flow.h"
#include "io/dem_checkpoint.h"
#include "io/dem_scene.h"
#include "io/toml_reader.h"

#include <gtest/gtest.h>

#include <cstring>
#include <filesystem>
#include <fstream>
#include <iterator>

namespace
{

using namespace veridem;

// 64 spheres in a box with friction and EPSD rolling, on an oscillating floor: pair and wall
// history, rolling springs, a wall phase.
const char* kScene = R"(
[simulation]
dt = 2e-5
duration = 1
gravity = [0, 0, -30]
vtk = false

[[material]]
name = "grain"
density = 2500
kn = 1e4
friction = 0.5
rolling_model = "epsd"
rolling_friction = 0.0005

[[wall]]
name = "floor"
material = "grain"
normal = [0, 0, 1]
oscillation_amplitude = [0, 0, 0.0002]
oscillation_omega = 300

[[lattice]]
material = "grain"
radius = 0.005
min = [0.0001, 0.0001, 0.0001]
max = [0.0405, 0.0405, 0.0405]
spacing = 0.0101
jitter = 0.00004
velocity = [0.1, 0.05, -0.1]
)";

io::DemScene makeScene()
{
    return io::readDemScene(io::parseText(kScene, "checkpoint_test.toml"), "checkpoint_test.toml");
}

std::filesystem::path scratch(const char* name)
{
    return std::filesystem::temp_directory_path() / name;
}

std::string readAll(const std::filesystem::path& path)
{
    std::ifstream in(path, std::ios::binary);
    return {std::istreambuf_iterator<char>(in), {}};
}

void writeAll(const std::filesystem::path& path, const std::string& bytes)
{
    std::ofstream(path, std::ios::binary).write(bytes.data(), static_cast<std::streamsize>(bytes.size()));
}

bool sameBits(const std::vector<Vec3>& a, const std::vector<Vec3>& b)
{
    return a.size() == b.size() &&
           (a.empty() || std::memcmp(a.data(), b.data(), a.size() * sizeof(Vec3)) == 0);
}

TEST(Checkpoint, RestoredWorldStepsToTheSameBits)
{
    io::DemScene original = makeScene();
    dem::prepare(original.world);
    dem::advance(original.world, original.dt, 1500);
    ASSERT_GT(original.world.health.touchingPairs, 0u);
    const auto path = scratch("veridem_checkpoint_test.bin");
    io::writeDemCheckpoint(path, original.world, 7, {{0.0, 0.01}, {10, 20}, 0});

    io::DemScene restored = makeScene();
    const io::CheckpointOutputs outputs = io::readDemCheckpoint(path, restored.world, 7);
    EXPECT_EQ(outputs.frameTimes, (std::vector<double>{0.0, 0.01}));
    EXPECT_EQ(outputs.fileBytes, (std::vector<std::uint64_t>{10, 20}));
    EXPECT_EQ(restored.world.stepCount, original.world.stepCount);

    dem::advance(original.world, original.dt, 700);
    dem::advance(restored.world, restored.dt, 700);
    EXPECT_TRUE(sameBits(original.world.particles.position, restored.world.particles.position));
    EXPECT_TRUE(sameBits(original.world.particles.velocity, restored.world.particles.velocity));
    EXPECT_TRUE(sameBits(original.world.particles.angularVelocity, restored.world.particles.angularVelocity));
    EXPECT_TRUE(sameBits(original.world.pairHistory.spring, restored.world.pairHistory.spring));
    EXPECT_TRUE(sameBits(original.world.pairHistory.rolling, restored.world.pairHistory.rolling));
    EXPECT_TRUE(sameBits(original.world.wallHistory.spring, restored.world.wallHistory.spring));
    EXPECT_EQ(original.world.time, restored.world.time);
    std::filesystem::remove(path);
}

// Particles retired by an outlet (dem/particle_changes.h) are saved as they are, parked in the
// store with their slots: the restored world steps to the same bits as the one that wrote it, and
// both take them out of the store at the same rebuild.
TEST(Checkpoint, RetiredParticlesRestoreToTheSameRun)
{
    io::DemScene original = makeScene();
    dem::prepare(original.world);
    dem::advance(original.world, original.dt, 1500);
    dem::ParticleFlow flow;
    dem::Outlet top;
    top.region.kind = dem::FlowRegion::Kind::HalfSpace;
    top.region.point = {0, 0, 0.02};
    top.region.normal = {0, 0, 1};
    flow.outlets.push_back(top);
    const std::size_t count = original.world.particles.size();
    ASSERT_TRUE(flow.apply(original.world, original.dt));
    ASSERT_GT(flow.outlets[0].count, 0u);
    ASSERT_EQ(original.world.particles.size(), count); // retired, still in the store
    const auto path = scratch("veridem_checkpoint_retired_test.bin");
    io::writeDemCheckpoint(path, original.world, 7, {{0.0}, {10, 20}, 0});

    io::DemScene restored = makeScene();
    io::readDemCheckpoint(path, restored.world, 7);
    ASSERT_EQ(restored.world.particles.size(), count);
    const std::size_t rebuilds = original.world.neighbors.rebuildCount();
    dem::advance(original.world, original.dt, 700);
    dem::advance(restored.world, restored.dt, 700);
    ASSERT_GT(original.world.neighbors.rebuildCount(), rebuilds); // (a rebuild took them out)
    EXPECT_EQ(original.world.particles.size() + flow.outlets[0].count, count);
    EXPECT_EQ(original.world.particles.id, restored.world.particles.id);
    EXPECT_TRUE(sameBits(original.world.particles.position, restored.world.particles.position));
    EXPECT_TRUE(sameBits(original.world.particles.velocity, restored.world.particles.velocity));
    EXPECT_TRUE(sameBits(original.world.particles.angularVelocity, restored.world.particles.angularVelocity));
    EXPECT_TRUE(sameBits(original.world.pairHistory.spring, restored.world.pairHistory.spring));
    EXPECT_TRUE(sameBits(original.world.wallHistory.spring, restored.world.wallHistory.spring));
    std::filesystem::remove(path);
}

TEST(Checkpoint, DamagedFilesAreRefusedWithoutHarm)
{
    io::DemScene original = makeScene();
    dem::prepare(original.world);
    dem::advance(original.world, original.dt, 300);
    const auto path = scratch("veridem_checkpoint_damage.bin"),
               damaged = scratch("veridem_checkpoint_damaged.bin");
    io::writeDemCheckpoint(path, original.world, 7, {{0.0}, {1, 2}, 0});
    const std::string good = readAll(path);
    ASSERT_GT(good.size(), 1000u);
    io::DemScene target = makeScene();
    const auto refused = [&](const std::string& bytes)
    {
        writeAll(damaged, bytes);
        try
        {
            io::readDemCheckpoint(damaged, target.world, 7);
            return false;
        }
        catch (const InputError& e)
        {
            EXPECT_EQ(std::string(e.what()).find('\n'), std::string::npos) << e.what();
            return true;
        }
    };
    // Every cut of the file (a truncation at any byte) is refused.
    for (std::size_t size = 0; size < good.size(); size += size < 256 ? 1 : 97)
        EXPECT_TRUE(refused(good.substr(0, size))) << "truncated to " << size << " bytes";
    // A flipped bit anywhere (header, record headers, data, trailer) is refused: the checksum
    // covers every record byte, and the header and trailer fields are each checked.
    for (std::size_t k = 0; k < good.size(); k += k < 512 ? 1 : 61)
    {
        std::string bytes = good;
        bytes[k] = static_cast<char>(bytes[k] ^ 0x04);
        EXPECT_TRUE(refused(bytes)) << "bit flipped at byte " << k;
    }
    // Another scene (hash) and another version are refused by name.
    try
    {
        io::readDemCheckpoint(path, target.world, 8);
        FAIL() << "another scene's hash was accepted";
    }
    catch (const InputError& e)
    {
        EXPECT_NE(std::string(e.what()).find("belongs to another scene"), std::string::npos) << e.what();
    }
    std::filesystem::remove(path);
    std::filesystem::remove(damaged);
}

} // namespace
