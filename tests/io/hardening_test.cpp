// Input that once hung or reached undefined behaviour: the neighbour grid on non-finite and huge
// positions, the lexical TOML check (refuses what toml++ 3.3.0 mishandles, accepts valid TOML),
// and the derived-quantity range checks of the 3D scene reader.
#include "core/error.h"
#include "dem/neighbor_list.h"
#include "io/dem_scene.h"
#include "io/toml_guard.h"
#include "io/toml_reader.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>

using namespace veridem;

namespace
{
dem::ParticleStore twoSpheresAnd(Vec3 third)
{
    dem::ParticleStore p;
    p.add({0, 0, 0}, {}, {}, 0.01, 2500, 0);
    p.add({0.015, 0, 0}, {}, {}, 0.01, 2500, 0);
    p.add(third, {}, {}, 0.01, 2500, 0);
    return p;
}

std::string scene(const std::string& extra)
{
    return "[simulation]\ndt = 1e-5\nduration = 1e-4\n[[material]]\nname = \"m\"\ndensity = 2500\nkn = "
           "1e5\n" +
           extra;
}
} // namespace

// The grid sizing used to loop forever or convert inf/NaN to an integer. A blown-up state must
// only end the rebuild (the run's health check stops it); the finite pair is still found.
TEST(Hardening, NeighbourGridSurvivesNonFiniteAndHugePositions)
{
    const Real inf = std::numeric_limits<Real>::infinity(), nan = std::numeric_limits<Real>::quiet_NaN();
    for (const Vec3 third : {Vec3{inf, 0, 0}, Vec3{nan, 0, 0}, Vec3{1e308, -1e308, 0}, Vec3{nan, nan, nan}})
    {
        const dem::ParticleStore p = twoSpheresAnd(third);
        dem::NeighborList list;
        dem::ContactHistoryStore history;
        list.skin = 1e-3;
        list.rebuild(p, history);
        bool found = false;
        for (std::size_t k = 0; k < list.size(); ++k)
            found |= list.first[k] == 0 && list.second[k] == 1;
        EXPECT_TRUE(found) << third.x;
    }
    dem::ParticleStore p;
    p.add({nan, nan, nan}, {}, {}, 0.01, 2500, 0);
    p.add({nan, 0, 0}, {}, {}, 0.01, 2500, 0);
    dem::NeighborList list;
    dem::ContactHistoryStore history;
    list.rebuild(p, history); // all positions NaN: one cell, returns
}

TEST(Hardening, TomlGuardAcceptsValidToml)
{
    const std::string valid = "# comment with non-ASCII: densit\xC3\xA9 \xE2\x89\xA4\n"
                              "[simulation]\n"
                              "name = \"caf\xC3\xA9 [[*a]]\" # r\xC3\xA9sum\xC3\xA9\n"
                              "\"densit\xC3\xA9\" = 1\n"
                              "text = '''\nline [[*x]]\n\xC3\xA9\n'''\n"
                              "multi = \"\"\"\n\\\"\"\" still \xC3\xA9\n\"\"\"\n"
                              "polygon = [\n[0, 0],\n  [1, 0], [0, 1]]\n"
                              "inline = { a = [1, 2], b = \"]\" }\n"
                              "[ a . \"b c\" . 'd\xC3\xA9' ]  # header with quoted keys\n"
                              "[[ list ]]\n"
                              "[[list]]\r\n";
    EXPECT_NO_THROW(io::checkTomlText(valid, "t.toml"));
    EXPECT_NO_THROW(io::parseText(valid, "t.toml"));
}

TEST(Hardening, TomlGuardRefusesWhatToml3MisreadsWithTheLine)
{
    auto message = [](const std::string& text)
    {
        try
        {
            io::checkTomlText(text, "t.toml");
        }
        catch (const InputError& e)
        {
            return std::string(e.what());
        }
        return std::string("accepted");
    };
    EXPECT_EQ(message("a = 1\n\ndensit\xC3\xA9 = 2500\n").substr(0, 34),
              "t.toml:3: non-ASCII character outs");
    EXPECT_EQ(message("x = 1 \xC3\xA9\n").substr(0, 9), "t.toml:1:");
    EXPECT_EQ(message("a = 1\n[[*a]]\n").substr(0, 34), "t.toml:2: a table header must be [");
    EXPECT_EQ(message("[a.]\n").substr(0, 10), "t.toml:1: ");
    EXPECT_EQ(message("[a] b = 1\n").substr(0, 10), "t.toml:1: ");
    EXPECT_EQ(message("[a\n").substr(0, 10), "t.toml:1: ");
    EXPECT_EQ(message("[[a]\n").substr(0, 10), "t.toml:1: ");
    EXPECT_EQ(message("[t\xC3\xA9]\n").substr(0, 34), "t.toml:1: non-ASCII character outs");
}

TEST(Hardening, SceneRefusesOutOfRangeDerivedQuantities)
{
    auto read = [](const std::string& text) { io::readDemScene(io::parseText(text, "s.toml"), "s.toml"); };
    EXPECT_NO_THROW(read(scene("[[sphere]]\nmaterial = \"m\"\nradius = 0.01\nposition = [0, 0, 0]\n")));
    // radius 1e-120: mass 1e-356 kg underflows to zero
    EXPECT_THROW(read(scene("[[sphere]]\nmaterial = \"m\"\nradius = 1e-120\nposition = [0, 0, 0]\n")),
                 InputError);
    EXPECT_THROW(read(scene("[[sphere]]\nmaterial = \"m\"\nradius = 1e200\nposition = [0, 0, 0]\n")),
                 InputError);
    EXPECT_THROW(read(scene("[[sphere]]\nmaterial = \"m\"\nradius = 0.01\nposition = [0, 0, 0]\n"
                            "angular_velocity = [1e300, 0, 0]\n")),
                 InputError);
    // 1e8 m is 1e10 radii away
    EXPECT_THROW(read(scene("[[sphere]]\nmaterial = \"m\"\nradius = 0.01\nposition = [0, 1e8, 0]\n")),
                 InputError);
    // a lattice box of 1e300 m is refused before its count (1e301 per axis) becomes an integer
    EXPECT_THROW(read(scene("[[lattice]]\nmaterial = \"m\"\nradius = 0.01\nmin = [0, 0, 0]\n"
                            "max = [1e300, 1e300, 1e300]\n")),
                 InputError);
}

// Found by fuzzing: a quote inside a bare value followed by non-ASCII text reached an
// unreachable point of toml++ 3.3.0 (tests/io/fuzz_cases/scene3d/toml_quote_in_bare_value_non_ascii).
TEST(Hardening, TomlGuardRefusesMisplacedQuotesBadUtf8AndControlCharacters)
{
    auto refused = [](const std::string& text)
    {
        try
        {
            io::checkTomlText(text, "t.toml");
        }
        catch (const InputError& e)
        {
            return std::string(e.what()).substr(0, 9) == "t.toml:2:";
        }
        return false;
    };
    EXPECT_TRUE(refused("[simulation]\ntype = 2-fdem2d\"[simu\xD0\x93\n"));
    EXPECT_TRUE(refused("[simulation]\nradius = 0.\"\xC3\xA9\n")); // toml_quote_after_number_dot
    // toml_non_ascii_after_line_ending_backslash: U+FEDF after a trimmed line end
    EXPECT_TRUE(refused("b = \"\"\"x\\\n \xEF\xBB\x9Fy\"\"\"\n"));
    EXPECT_TRUE(refused("b = \"\"\"x\\  \r\n \xC3\xA9\"\"\"\n"));
    EXPECT_TRUE(refused("\"\"\"\\\n\\\xEF\xB9\xBF")); // toml_non_ascii_after_backslash: U+FE7F
    EXPECT_TRUE(refused("a = 1\nb = \"x\\ \xC3\xA9\"\n"));
    EXPECT_TRUE(refused("a = 1\nb = 1[[S[[\"mu\xD0\x93\"]]\n")); // toml_bracket_after_number
    EXPECT_TRUE(refused("a = 1\nb = x{c = 1}\n"));
    EXPECT_TRUE(refused("a = 1\nu= 0b000ouw=\"l\xD0\x93")); // toml_second_equals_in_value
    EXPECT_TRUE(refused("a = 1\nb = \"x\xC3\"\n"));         // cut sequence
    EXPECT_TRUE(refused("a = 1\nb = \"\xC0\xAF\"\n"));      // overlong '/'
    EXPECT_TRUE(refused("a = 1\nb = \"\xED\xA0\x80\"\n"));  // surrogate
    EXPECT_TRUE(refused("a = 1\nb = 2\x01\n"));             // control character
    EXPECT_TRUE(refused(std::string("a = 1\nb = \"\0\"\n", 13)));
    EXPECT_NO_THROW(io::checkTomlText("a = [\"x\", 'y', { b = \"z\", c.\"d\" = 1 }]\n\"q\".'r' = 1\n"
                                      "e = { f = [1, \"g\"], \"h\" = 2 }\n"
                                      "i = \"\"\"j\\\n  k \xC3\xA9 \\\"\\\\\"\"\"\n",
                                      "t.toml"));
}
