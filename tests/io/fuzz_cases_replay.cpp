// Replays every input kept in tests/io/fuzz_cases/TARGET/ through the fuzzed readers
// (fuzz/fuzz_targets.h) and the region measures: inputs that once crashed a fuzz target or reached undefined
// behaviour, and the bad inputs of the hardening tests. Each must end with a refusal or a scene, never a
// crash (under the asan preset, never a sanitizer report).
#include "fuzz_targets.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <iterator>

namespace
{
std::string contents(const std::filesystem::path& path)
{
    std::ifstream in(path, std::ios::binary);
    return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

std::size_t replay(const char* target, void (*read)(std::string_view))
{
    std::size_t count = 0;
    for (const auto& entry :
         std::filesystem::directory_iterator(std::filesystem::path(VERIDEM_FUZZ_CASES) / target))
    {
        SCOPED_TRACE(entry.path().string());
        read(contents(entry.path()));
        ++count;
    }
    return count;
}
} // namespace

TEST(FuzzCases, Scene3d)
{
    EXPECT_GT(replay("scene3d", veridem::fuzz::readScene3d), 0u);
}

TEST(FuzzCases, Scene2d)
{
    EXPECT_GT(replay("scene2d", veridem::fuzz::readScene2d), 0u);
}

TEST(FuzzCases, Checkpoint3d)
{
    // A checkpoint of the fuzz scene is read back (the seed of the fuzz target is one).
    veridem::io::DemScene scene = veridem::fuzz::checkpointScene();
    veridem::dem::prepare(scene.world);
    veridem::dem::advance(scene.world, scene.dt, 1500);
    const auto path = std::filesystem::temp_directory_path() / "veridem_fuzz_seed_checkpoint.bin";
    veridem::io::writeDemCheckpoint(path, scene.world, veridem::fuzz::kCheckpointSceneHash,
                                    {{0.0}, {1, 2}, 0});
    veridem::io::DemScene restored = veridem::fuzz::checkpointScene();
    EXPECT_NO_THROW(
        veridem::io::readDemCheckpoint(path, restored.world, veridem::fuzz::kCheckpointSceneHash));
    std::filesystem::remove(path);
    // The stored seed must stay a valid checkpoint of the current format (a stale seed would start
    // the fuzzer from refused inputs only); regenerate it from the checkpoint written above.
    veridem::io::DemScene fromSeed = veridem::fuzz::checkpointScene();
    EXPECT_NO_THROW(veridem::io::readDemCheckpoint(std::filesystem::path(VERIDEM_FUZZ_CASES) /
                                                       "checkpoint3d" / "valid_seed.bin",
                                                   fromSeed.world, veridem::fuzz::kCheckpointSceneHash));
    EXPECT_GT(replay("checkpoint3d", veridem::fuzz::readCheckpoint3d), 0u);
}

TEST(FuzzCases, Msh)
{
    EXPECT_GT(replay("msh", veridem::fuzz::readMsh), 0u);
}

TEST(FuzzCases, Region)
{
    EXPECT_GT(replay("region", veridem::fuzz::measureRegionVolumes), 0u);
}
