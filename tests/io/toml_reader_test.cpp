#include "core/error.h"
#include "io/toml_reader.h"

#include <gtest/gtest.h>

#include <functional>
#include <string>

using veridem::InputError;
using veridem::io::TableReader;

namespace
{
std::string errorOf(const std::function<void()>& f)
{
    try
    {
        f();
    }
    catch (const InputError& e)
    {
        return e.what();
    }
    return "";
}
} // namespace

TEST(TomlReader, UnknownKeyNamesLineAndNearestKey)
{
    const toml::table t =
        toml::parse(std::string_view{"radius = 1.0\nradus = 2.0\n"}, std::string_view{"scene.toml"});
    TableReader r(t, "[[sphere]] #1", "scene.toml");
    EXPECT_EQ(r.number("radius", 0), 1.0);
    const std::string message = errorOf([&] { r.finish(); });
    EXPECT_NE(message.find("scene.toml:2"), std::string::npos) << message;
    EXPECT_NE(message.find("'radus'"), std::string::npos) << message;
    EXPECT_NE(message.find("did you mean 'radius'"), std::string::npos) << message;
}

TEST(TomlReader, WrongTypeAndMissingKey)
{
    const toml::table t = toml::parse(std::string_view{"radius = \"big\"\n"}, std::string_view{"scene.toml"});
    TableReader r(t, "[[sphere]] #1", "scene.toml");
    EXPECT_NE(errorOf([&] { r.number("radius", 0); }).find("must be a number, got a string"),
              std::string::npos);
    EXPECT_NE(errorOf([&] { r.requiredNumber("density"); }).find("missing required key 'density'"),
              std::string::npos);
}

TEST(TomlReader, IntegersAreNumbersAndVectorsHaveThreeEntries)
{
    const toml::table t =
        toml::parse(std::string_view{"a = 3\nv = [1, 2.5, 3]\nw = [1, 2]\n"}, std::string_view{"s.toml"});
    TableReader r(t, "[x]", "s.toml");
    EXPECT_EQ(r.number("a", 0), 3.0);
    EXPECT_EQ(r.vec3("v", {}).y, 2.5);
    EXPECT_NE(errorOf([&] { r.vec3("w", {}); }).find("array of 3 numbers"), std::string::npos);
}

TEST(TomlReader, EditDistance)
{
    EXPECT_EQ(veridem::io::editDistance("radius", "radus"), 1u);
    EXPECT_EQ(veridem::io::editDistance("", "abc"), 3u);
}
