// Replays every input kept in tests/io/fuzz_cases/TARGET/ through the fuzzed readers
// (fuzz/fuzz_targets.h): inputs that once crashed a fuzz target or reached undefined behaviour,
// and the bad inputs of the hardening tests. Each must end with a refusal or a scene, never a
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

TEST(FuzzCases, Msh)
{
    EXPECT_GT(replay("msh", veridem::fuzz::readMsh), 0u);
}
