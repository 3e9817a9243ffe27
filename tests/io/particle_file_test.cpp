// [[particles]] files: columns by header (the state file a run writes, plain packing files),
// the legacy 'x y z' form, ids, and every error a user can meet, each naming file, line and cause.
#include "core/error.h"
#include "io/dem_scene.h"
#include "io/particle_state.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <string>

using namespace veridem;

namespace
{
std::filesystem::path directory()
{
    const auto d = std::filesystem::temp_directory_path() / "veridem_particle_file_test";
    std::filesystem::create_directories(d);
    return d;
}

/// Writes `text` to DIR/name; returns the path.
std::string write(const std::string& name, const std::string& text)
{
    const auto path = directory() / name;
    std::ofstream(path) << text;
    return path.string();
}

const std::string kMaterials = R"([simulation]
dt = 1e-5
duration = 0.01
gravity = [0, 0, 0]
[[material]]
name = "glass"
density = 2500
kn = 1e3
[[material]]
name = "steel"
density = 7800
kn = 1e3
)";

/// Loads a scene whose text is kMaterials + `tables`, from the file DIR/scene.toml.
io::DemScene load(const std::string& tables)
{
    const std::string file = write("scene.toml", kMaterials + tables);
    return io::readDemScene(toml::parse(std::string_view{kMaterials + tables}, std::string_view{file}), file);
}

std::string errorOf(const std::string& tables)
{
    try
    {
        load(tables);
    }
    catch (const InputError& e)
    {
        return e.what();
    }
    return "(no error)";
}

std::string fileTable(const std::string& name, const std::string& keys = "material = \"glass\"\n")
{
    return "[[particles]]\nfile = \"" + name + "\"\n" + keys;
}
} // namespace

TEST(ParticleFile, ReadsAPackingFileWithUnitsTabsSpacesAndCarriageReturns)
{
    // The shape of the DEM8 benchmark's bed files: a header with units, a tab and spaces, CRLF.
    write("packing.txt", "Radius[m]\tPosX[m] PosY[m] PosZ[m]\r\n 0.001 0.01 0.02 0.03\r\n"
                         " 0.002\t-0.01 0.02 0.03\r\n\r\n");
    const io::DemScene s = load(fileTable("packing.txt")); // (relative to the scene file)
    const auto& p = s.world.particles;
    ASSERT_EQ(p.size(), 2u);
    EXPECT_EQ(p.radius[0], 0.001);
    EXPECT_EQ(p.radius[1], 0.002);
    EXPECT_EQ(p.position[1].x, -0.01);
    EXPECT_EQ(p.position[1].z, 0.03);
    EXPECT_EQ(p.material[1], 0u);
    EXPECT_EQ(p.id[1], 1u);
}

TEST(ParticleFile, TheLegacyXyzFormStillLoads)
{
    write("xyz.txt", "# a comment\n0 0 0\n0.1 0 0\n");
    const io::DemScene s =
        load(fileTable("xyz.txt", "material = \"steel\"\nradius = 0.01\nvelocity = [1, 0, 0]\n"));
    ASSERT_EQ(s.world.particles.size(), 2u);
    EXPECT_EQ(s.world.particles.radius[1], 0.01);
    EXPECT_EQ(s.world.particles.velocity[1].x, 1.0);
    EXPECT_EQ(s.world.particles.material[1], 1u);
}

TEST(ParticleFile, AStateFileRoundTripsEveryBitIdMaterialAndFlag)
{
    io::DemScene first = load(R"([[sphere]]
material = "steel"
radius = 0.0011
position = [0.1, 0.2, 0.3]
velocity = [0.1, -0.3, 1e-17]
angular_velocity = [3.3, 0, -2]
[[sphere]]
material = "glass"
radius = 0.00123456789
position = [-0.1, 0.2, 0.3]
fixed = true
)");
    first.world.particles.id = {7, 3}; // (ids with gaps, as after outlets)
    first.world.stepCount = 60000;
    const std::string state = (directory() / "state.csv").string();
    io::writeParticleState(state, first.world, 1e-5);
    std::ifstream in(state);
    std::string comment;
    std::getline(in, comment);
    EXPECT_EQ(comment, "# veridem state at t = 0.6 s (step 60000)");
    const io::DemScene again = load(fileTable("state.csv", ""));
    const auto &a = first.world.particles, &b = again.world.particles;
    ASSERT_EQ(b.size(), 2u);
    for (std::size_t i = 0; i < 2; ++i)
    {
        EXPECT_EQ(b.id[i], a.id[i]);
        EXPECT_EQ(b.material[i], a.material[i]);
        EXPECT_EQ(b.radius[i], a.radius[i]);
        EXPECT_EQ(b.mass[i], a.mass[i]);
        EXPECT_EQ(b.fixed[i], a.fixed[i]);
        for (const auto field : {&dem::ParticleStore::position, &dem::ParticleStore::velocity,
                                 &dem::ParticleStore::angularVelocity})
        {
            EXPECT_EQ((b.*field)[i].x, (a.*field)[i].x);
            EXPECT_EQ((b.*field)[i].y, (a.*field)[i].y);
            EXPECT_EQ((b.*field)[i].z, (a.*field)[i].z);
        }
    }
}

TEST(ParticleFile, IdsFromAFileAreKeptAndTheOthersTakeFreeOnes)
{
    write("ids.csv", "id,radius,x,y,z\n0,0.01,0,0,0\n2,0.01,0.1,0,0\n");
    const io::DemScene s = load(R"([[sphere]]
material = "glass"
radius = 0.01
position = [0, 0.5, 0]
)" + fileTable("ids.csv") + R"([[sphere]]
material = "glass"
radius = 0.01
position = [0, 1, 0]
)");
    // [[sphere]] tables come first in the store, then the files; 0 and 2 are the file's.
    EXPECT_EQ(s.world.particles.id, (std::vector<std::uint32_t>{1, 3, 0, 2}));
}

TEST(ParticleFile, ErrorsNameTheFileTheLineAndWhatWasExpected)
{
    const std::string where = (directory() / "bad.txt").string();
    const auto bad = [&](const std::string& text, const std::string& keys = "material = \"glass\"\n")
    {
        write("bad.txt", text);
        return errorOf(fileTable("bad.txt", keys));
    };
    EXPECT_NE(bad("radius x y z\n0.01 0 0 0\n0.01 0 0\n")
                  .find(where + ":3: expected 4 columns (radius x y z), found 3"),
              std::string::npos);
    EXPECT_NE(bad("radius x y z\n0.01 0 abc 0\n").find(where + ":2: column 'y': 'abc' is not a number"),
              std::string::npos);
    EXPECT_NE(bad("radius x y z\n0.01 0 0 nan\n").find(where + ":2: column 'z' must be finite"),
              std::string::npos);
    EXPECT_NE(bad("radius x y z\n0 0 0 0\n").find(where + ":2: column 'radius' must be > 0 m (got 0)"),
              std::string::npos);
    EXPECT_NE(bad("radius x y z\n-1e-3 0 0 0\n").find(where + ":2: column 'radius' must be > 0 m"),
              std::string::npos);
    EXPECT_NE(bad("material radius x y z\nsand 0.01 0 0 0\n", "")
                  .find(where + ":2: unknown material 'sand' (the scene's [[material]] names: glass, steel)"),
              std::string::npos);
    EXPECT_NE(bad("radius x y z\n0.01 0 0 0\n", "").find("'material' is missing: give material = "),
              std::string::npos);
    EXPECT_NE(bad("x y z\n0 0 0\n").find("'radius' is missing: give radius = <m> or a radius column"),
              std::string::npos);
    EXPECT_NE(bad("material radius x y z\nglass 0.01 0 0 0\n").find("'material' is also a column of"),
              std::string::npos);
    EXPECT_NE(bad("radius x y zz\n").find(where + ":1: unknown column 'zz' (known: id material radius x y z"),
              std::string::npos);
    EXPECT_NE(bad("Radius[mm] x y z\n").find(where + ":1: column 'Radius[mm]' must be in [m]"),
              std::string::npos);
    EXPECT_NE(bad("radius x y z vx\n").find("give all three of 'vx', 'vy' and 'vz' or none"),
              std::string::npos);
    EXPECT_NE(bad("radius x\n").find(where + ":1: the header has no 'y' column"), std::string::npos);
    EXPECT_NE(bad("id radius x y z\n4 0.01 0 0 0\n4 0.01 1 0 0\n").find(where + ":3: id 4 is also on line 2"),
              std::string::npos);
    EXPECT_NE(bad("id radius x y z\n-4 0.01 0 0 0\n").find("column 'id': '-4' is not a whole number"),
              std::string::npos);
    EXPECT_NE(bad("0 0 0\n1 1\n", "material = \"glass\"\nradius = 0.01\n")
                  .find(where + ":2: expected 3 columns (x y z), found 2"),
              std::string::npos);
    // The DEM8 bed files end in a projectile row of other columns: rows = N reads the bed only.
    const std::string packing = "radius x y z\n0.01 0 0 0\n0.01 1 0 0\n5 0.01 0.01 0 0 0.06\n";
    EXPECT_NE(bad(packing).find("found 6 (to read only the rows before it, give rows = N"),
              std::string::npos);
    write("bad.txt", packing);
    EXPECT_EQ(load(fileTable("bad.txt", "material = \"glass\"\nrows = 2\n")).world.particles.size(), 2u);
    EXPECT_NE(
        bad("radius x y z\n0.01 0 0 0\n", "material = \"glass\"\nrows = 9\n").find("'rows' asks for 9 rows"),
        std::string::npos);
}

TEST(ParticleFile, AnIdGivenByTwoFilesIsRefused)
{
    write("a.csv", "id,radius,x,y,z\n5,0.01,0,0,0\n");
    write("b.csv", "id,radius,x,y,z\n5,0.01,1,0,0\n");
    EXPECT_NE(
        errorOf(fileTable("a.csv") + fileTable("b.csv")).find("id 5 is given by two [[particles]] files"),
        std::string::npos);
}

TEST(ParticleFile, ARadiusWindowGivesEachSizeItsMaterial)
{
    // The DEM8 drum's file: two sizes of two materials in one file, read by two tables.
    write("mixture.txt", "Radius[m] PosX[m] PosY[m] PosZ[m]\n 0.002 0 0 0\n 0.001 0.1 0 0\n 0.001 0.2 0 0\n");
    const io::DemScene s = load(fileTable("mixture.txt", "material = \"glass\"\nmax_radius = 0.0015\n") +
                                fileTable("mixture.txt", "material = \"steel\"\nmin_radius = 0.0015\n"));
    const auto& p = s.world.particles;
    ASSERT_EQ(p.size(), 3u);
    // File order within each table, the first table's rows first.
    EXPECT_EQ(p.radius, (std::vector<Real>{0.001, 0.001, 0.002}));
    EXPECT_EQ(p.material, (std::vector<std::uint32_t>{0, 0, 1}));
    EXPECT_EQ(p.position[0].x, 0.1);
    EXPECT_NE(errorOf(fileTable("mixture.txt", "min_radius = 0.002\nmax_radius = 0.001\n"))
                  .find("'max_radius' must exceed min_radius"),
              std::string::npos);
    EXPECT_NE(errorOf(fileTable("xyz.txt", "radius = 0.01\nmin_radius = 0.001\n")).find("min_radius"),
              std::string::npos);
}
