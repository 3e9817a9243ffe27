// The declared model parameters (dem/model_params.h) against docs/scene-format.md's tables, the
// Material's defaults, and the scene reader's errors for a key given to the wrong model, a key
// missing and a value out of range.
#include "core/error.h"
#include "dem/model_params.h"
#include "dem/models/normal.h"
#include "io/dem_scene.h"
#include "io/material_keys.h"
#include "scene_text.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <map>
#include <string>
#include <vector>

using namespace veridem;

namespace
{

/// A table row of the doc: its cells after the key (unit, default, ...), by key.
using DocTable = std::map<std::string, std::vector<std::string>>;

std::string trimmed(std::string text)
{
    const auto first = text.find_first_not_of(' ');
    const auto last = text.find_last_not_of(' ');
    return first == std::string::npos ? "" : text.substr(first, last - first + 1);
}

/// The doc's spelling made comparable: no backticks, "–" as "-", "²" and "³" as "^2" and "^3".
std::string normalised(std::string text)
{
    for (const auto& [from, to] :
         std::vector<std::pair<std::string, std::string>>{{"`", ""}, {"–", "-"}, {"²", "^2"}, {"³", "^3"}})
        for (auto at = text.find(from); at != std::string::npos; at = text.find(from, at + to.size()))
            text.replace(at, from.size(), to);
    return trimmed(text);
}

/// The first table under the heading that starts with `heading` in docs/scene-format.md.
DocTable docTable(const std::string& heading)
{
    // (VERIDEM_SOURCE_DIR from tests/CMakeLists.txt: __FILE__ is relative when the compiler is
    // given relative paths, e.g. under ccache's base_dir)
    const auto doc = std::filesystem::path(VERIDEM_SOURCE_DIR) / "docs" / "scene-format.md";
    std::ifstream in(doc);
    EXPECT_TRUE(in.good()) << "cannot open " << doc;
    DocTable table;
    std::string line;
    bool under = false, inTable = false;
    while (std::getline(in, line))
    {
        if (!under)
        {
            under = line.rfind(heading, 0) == 0;
            continue;
        }
        if (line.rfind("|", 0) != 0)
        {
            if (inTable)
                break;
            continue;
        }
        inTable = true;
        std::vector<std::string> cells;
        std::string::size_type start = 1;
        for (auto bar = line.find('|', start); bar != std::string::npos; bar = line.find('|', start))
        {
            cells.push_back(normalised(line.substr(start, bar - start)));
            start = bar + 1;
        }
        if (cells.size() < 3 || cells[0] == "key" || cells[0].rfind("---", 0) == 0)
            continue;
        const std::string keys = cells[0];
        cells.erase(cells.begin());
        std::string::size_type from = 0;
        for (auto comma = keys.find(',');; comma = keys.find(',', from))
        {
            table[trimmed(keys.substr(from, comma - from))] = cells;
            if (comma == std::string::npos)
                break;
            from = comma + 1;
        }
    }
    EXPECT_FALSE(table.empty()) << "no table under " << heading << " in " << doc;
    return table;
}

template <std::size_t kCount> bool listed(const std::string_view (&keys)[kCount], const std::string& key)
{
    for (const std::string_view k : keys)
        if (k == key)
            return true;
    return false;
}

io::DemScene load(const std::string& text)
{
    return test::loadScene(text);
}

std::string errorOf(const std::string& text)
{
    return test::sceneError(text);
}

const std::string kSimulation = "[simulation]\ndt = 1e-6\nduration = 1e-3\n";
const std::string kSphere = "[[sphere]]\nmaterial = \"a\"\nradius = 0.01\nposition = [0, 0, 0]\n";
std::string material(const std::string& name, const std::string& keys)
{
    return "[[material]]\nname = \"" + name + "\"\ndensity = 1000\n" + keys;
}
const std::string kThornton = "model = \"thornton\"\nyoungs_modulus = 1e9\npoisson_ratio = 0.3\n";

} // namespace

TEST(MaterialKeys, DocTableHasEveryDeclaredKeyWithItsUnitDefaultAndModels)
{
    const DocTable table = docTable("## `[[material]]`");
    for (const dem::ModelParam& p : dem::kModelParams)
    {
        const auto row = table.find(std::string(p.key));
        ASSERT_NE(row, table.end()) << "'" << p.key << "' is declared (dem/model_params.h) but not in "
                                    << "docs/scene-format.md's [[material]] table";
        ASSERT_GE(row->second.size(), 3u) << p.key;
        EXPECT_EQ(row->second[0], std::string(p.unit)) << "unit of '" << p.key << "'";
        EXPECT_EQ(row->second[1], dem::defaultText(p)) << "default of '" << p.key << "'";
        EXPECT_EQ(row->second[2], dem::readersText(p)) << "models of '" << p.key << "'";
    }
    for (const auto& [key, cells] : table)
        EXPECT_TRUE(dem::findModelParam(key) != nullptr || listed(io::kMaterialOwnKeys, key))
            << "'" << key << "' is in docs/scene-format.md's [[material]] table but not declared";
}

TEST(MaterialKeys, DocPairTableHasEveryOverridableKey)
{
    const DocTable table = docTable("## `[[pair]]`");
    for (const dem::ModelParam& p : dem::kModelParams)
        if (p.pairOverride)
        {
            const auto row = table.find(std::string(p.key));
            ASSERT_NE(row, table.end())
                << "'" << p.key << "' may be given in a [[pair]] but is not in its table";
            EXPECT_EQ(row->second[0], std::string(p.unit)) << "unit of '" << p.key << "'";
            EXPECT_EQ(row->second[1], "mixed") << "default of '" << p.key << "'";
        }
    for (const auto& [key, cells] : table)
    {
        const dem::ModelParam* p = dem::findModelParam(key);
        EXPECT_TRUE((p && p->pairOverride) || listed(io::kPairOwnKeys, key))
            << "'" << key << "' is in docs/scene-format.md's [[pair]] table but a pair cannot take it";
    }
}

TEST(MaterialKeys, ExclusiveWithNamesADeclaredKey)
{
    for (const dem::ModelParam& p : dem::kModelParams)
    {
        if (!p.exclusiveWith.empty())
        {
            EXPECT_NE(dem::findModelParam(p.exclusiveWith), nullptr) << p.key << ": " << p.exclusiveWith;
        }
    }
}

TEST(MaterialKeys, MaterialDefaultsAreTheDeclaredOnes)
{
    const dem::Material m;
    for (const dem::ModelParam& p : dem::kModelParams)
    {
        if (p.flag)
            EXPECT_EQ(m.*p.flag, p.defaultValue != 0) << p.key;
        else
            EXPECT_EQ(m.*p.field, p.defaultValue) << p.key;
    }
}

TEST(MaterialKeys, KeyOfAnotherModelIsRefusedWithWhatTheModelReads)
{
    const std::string thorntonDamped =
        errorOf(kSimulation + material("a", kThornton + "yield_stress = 1e6\nrestitution = 0.5\n") + kSphere);
    EXPECT_NE(
        thorntonDamped.find("'restitution' is not read by model = \"thornton\" (it reads: youngs_modulus, "
                            "poisson_ratio, yield_stress; material 'a')"),
        std::string::npos)
        << thorntonDamped;
    EXPECT_NE(errorOf(kSimulation +
                      material("a", "model = \"hertz\"\nyoungs_modulus = 1e9\npoisson_ratio = 0.3\n"
                                    "yield_stress = 1e6\n") +
                      kSphere)
                  .find("'yield_stress' is not read by model = \"hertz\""),
              std::string::npos);
    EXPECT_NE(errorOf(kSimulation +
                      material("a", "kn = 1e3\nrolling_model = \"none\"\nrolling_friction = 1e-4\n") +
                      kSphere)
                  .find("'rolling_friction' is not read by rolling_model = \"none\" (it reads: nothing;"),
              std::string::npos);
    EXPECT_NE(errorOf(kSimulation + material("a", "kn = 1e3\nrolling_damping_ratio = 0.2\n") + kSphere)
                  .find("'rolling_damping_ratio' is not read by rolling_model = \"constant_torque\""),
              std::string::npos);
    // A model not registered is named with the list of those that are.
    EXPECT_NE(errorOf(kSimulation + material("a", "model = \"plastic\"\n") + kSphere).find("'model'"),
              std::string::npos);
}

TEST(MaterialKeys, MissingOrOutOfRangeValueNamesTheMaterialAndTheRange)
{
    const std::string missing = errorOf(kSimulation + material("a", kThornton) + kSphere);
    EXPECT_NE(
        missing.find("'yield_stress' is required by model = \"thornton\": give a value in (0, E / (pi (1 - "
                     "nu^2)) = "),
        std::string::npos)
        << missing;
    EXPECT_NE(missing.find("material 'a'"), std::string::npos) << missing;
    const std::string above =
        errorOf(kSimulation + material("a", kThornton + "yield_stress = 1e9\n") + kSphere);
    EXPECT_NE(above.find("'yield_stress' must be in (0, E / (pi (1 - nu^2)) = 3.49"), std::string::npos)
        << above;
    EXPECT_NE(above.find("(got 1e+09; material 'a')"), std::string::npos) << above;
    EXPECT_NE(
        errorOf(kSimulation + material("a", "kn = 1e3\nrolling_model = \"viscous\"\n") + kSphere)
            .find(
                "'rolling_viscous_coefficient' is required by rolling_model = \"viscous\": give a value > 0 "
                "s/m"),
        std::string::npos);
    // A required key misspelt is named as the unknown key, with the one meant.
    EXPECT_NE(errorOf(kSimulation + material("a", "kn_ = 1e3\n") + kSphere)
                  .find("unknown key 'kn_' (did you mean 'kn'?)"),
              std::string::npos);
    EXPECT_NE(errorOf(kSimulation + material("a", "kn = 1e3\nfriction = -0.1\n") + kSphere)
                  .find("'friction' must be >= 0 (got -0.1; material 'a')"),
              std::string::npos);
    EXPECT_NE(
        errorOf(kSimulation +
                material("a", "kn = 1e3\nrolling_friction = 1e-4\nrolling_friction_dimensionless = 0.1\n") +
                kSphere)
            .find("'rolling_friction_dimensionless' cannot be > 0 together with 'rolling_friction'"),
        std::string::npos);
}

TEST(MaterialKeys, PairTakesItsValuesAsBothMaterialsWould)
{
    const dem::World& world =
        load(kSimulation + material("a", "kn = 1e3\nrolling_friction = 1e-4\n") +
             material("b", "kn = 2e3\nrolling_friction_dimensionless = 0.1\n") +
             "[[pair]]\nfirst = \"b\"\nsecond = \"a\"\nrestitution = 0.3\nfriction = 0.7\n"
             "rolling_friction = 3e-4\n" +
             kSphere)
            .world;
    for (const auto& [i, j] : {std::pair{0u, 1u}, std::pair{1u, 0u}})
    {
        const dem::PairParams& p = world.pairs(i, j);
        EXPECT_EQ(p.dampingRatio, dem::dampingRatioFromRestitution(0.3)); // ((x + x) / 2 is x exactly)
        EXPECT_EQ(p.mu, 0.7);
        EXPECT_EQ(p.rollingLength, 3e-4);
        EXPECT_EQ(p.rollingDimensionless, 0); // (a length replaces the dimensionless value)
        EXPECT_EQ(p.kn, 2 * 1e3 * 2e3 / 3e3); // the materials' own values stay mixed
    }
    EXPECT_EQ(world.pairs(0, 0).mu, 0.5);
}

TEST(MaterialKeys, PairKeyTheModelDoesNotReadOrAPairTwiceIsRefused)
{
    const std::string thornton = kSimulation + material("a", kThornton + "yield_stress = 1e6\n") + kSphere;
    EXPECT_NE(errorOf(thornton + "[[pair]]\nfirst = \"a\"\nsecond = \"a\"\nrestitution = 0.5\n")
                  .find("'restitution' is not read by the pair's model = \"thornton\" (pair 'a'-'a')"),
              std::string::npos);
    const std::string linear =
        kSimulation + material("a", "kn = 1e3\n") + material("b", "kn = 1e3\n") + kSphere;
    EXPECT_NE(errorOf(linear + "[[pair]]\nfirst = \"a\"\nsecond = \"b\"\nrolling_friction = 1e-4\n")
                  .find("'rolling_friction' is not read by the pair's rolling_model = \"none\""),
              std::string::npos);
    EXPECT_NE(errorOf(linear + "[[pair]]\nfirst = \"a\"\nsecond = \"b\"\nkn = 1e4\n")
                  .find("'kn' is a material's key: a [[pair]] takes restitution, friction, rolling_friction"),
              std::string::npos);
    EXPECT_NE(errorOf(linear + "[[pair]]\nfirst = \"a\"\nsecond = \"b\"\nfriction = 0.1\n" +
                      "[[pair]]\nfirst = \"b\"\nsecond = \"a\"\nfriction = 0.2\n")
                  .find("[[pair]] #2: 'second' repeats the pair 'b'-'a' of an earlier [[pair]]"),
              std::string::npos);
}
