// The output writers: the particle fields chosen in [output], the CSV switched off, exact output
// times (step count x dt) in every time column, and walls named in the contact CSV.
#include "dem/contact_diagnostics.h"
#include "io/contact_output.h"
#include "io/dem_scene.h"
#include "io/output_options.h"
#include "io/particle_output.h"
#include "io/thermo_output.h"
#include "io/wall_output.h"

#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

using namespace veridem;

namespace
{
std::filesystem::path freshDirectory(const std::string& name)
{
    const auto d = std::filesystem::temp_directory_path() / ("veridem_output_test_" + name);
    std::filesystem::remove_all(d);
    std::filesystem::create_directories(d);
    return d;
}

std::vector<std::string> lines(const std::filesystem::path& path)
{
    std::ifstream in(path);
    std::vector<std::string> out;
    for (std::string line; std::getline(in, line);)
        out.push_back(line);
    return out;
}

/// Two glass spheres overlapping by 1 um on a floor they touch, after one step.
io::DemScene twoSpheres(const std::string& output)
{
    const std::string text = R"([simulation]
dt = 1e-5
duration = 1
[output]
)" + output + R"(
[[material]]
name = "glass"
density = 2500
kn = 1e3
[[wall]]
name = "floor"
material = "glass"
normal = [0, 0, 1]
[[sphere]]
material = "glass"
radius = 0.01
position = [0, 0, 0.01]
[[sphere]]
material = "glass"
radius = 0.01
position = [0.019999, 0, 0.01]
)";
    io::DemScene s =
        io::readDemScene(toml::parse(std::string_view{text}, std::string_view{"s.toml"}), "s.toml");
    dem::step(s.world, s.dt);
    return s;
}
} // namespace

TEST(OutputTime, IsTheExactDecimalProductOfStepsAndDt)
{
    // In floating point 60000 * 1e-5 = 0.6000000000000001 and 3 * 0.1 = 0.30000000000000004.
    EXPECT_EQ(io::outputTime(60000, 1e-5), 0.6);
    EXPECT_EQ(io::outputTime(3, 0.1), 0.3);
    EXPECT_EQ(io::outputTime(0, 1e-5), 0.0);
    EXPECT_EQ(io::outputTime(123456789, 3.3e-7), 40.74074037);
    EXPECT_EQ(io::outputTime(7, 2.5e-3), 0.0175);
    // Far from round numbers it is the product to within an ulp or two.
    EXPECT_NEAR(io::outputTime(987654321, 1.2345678901234e-6), 987654321 * 1.2345678901234e-6, 1e-12);
}

TEST(ParticleOutput, WritesTheChosenFieldsInCsvAndVtk)
{
    io::DemScene s =
        twoSpheres(R"(particle_fields = ["radius", "mass", "material", "force", "torque", "coordination"])");
    const auto dir = freshDirectory("fields");
    s.world.stepCount = 60000; // (an output at step 60000 of 1e-5 s: t must read 0.6)
    io::ParticleRecorder recorder(dir, s.output);
    recorder.record(s.world);
    recorder.close();
    const std::vector<std::string> csv = lines(dir / "particles.csv");
    ASSERT_EQ(csv.size(), 3u);
    EXPECT_EQ(csv[0], "t,id,x,y,z,radius,mass,material,fx,fy,fz,tx,ty,tz,coordination");
    EXPECT_EQ(csv[1].rfind("0.6,0,", 0), 0u) << csv[1];
    // mass = density 4/3 pi r^3; one contact with the other sphere (the floor is not counted).
    char mass[64];
    std::snprintf(mass, sizeof mass, "%.17g", 2500 * 4.0 / 3.0 * M_PI * 1e-6);
    EXPECT_DOUBLE_EQ(std::stod(csv[1].substr(csv[1].find(",0.01,") + 6)), std::stod(mass));
    EXPECT_NE(csv[1].find(",glass,"), std::string::npos);
    EXPECT_EQ(csv[1].substr(csv[1].rfind(',') + 1), "1");
    // The force column is the step's contact force: the pair pushes sphere 0 towards -x.
    EXPECT_LT(s.world.particles.force[0].x, 0);
    const std::vector<std::string> vtp = lines(dir / "particles_000000.vtp");
    std::string all;
    for (const auto& l : vtp)
        all += l + "\n";
    for (const char* name :
         {"\"id\"", "\"radius\"", "\"mass\"", "\"material\"", "\"force\"", "\"torque\"", "\"coordination\""})
        EXPECT_NE(all.find(std::string("Name=") + name), std::string::npos) << name;
    EXPECT_EQ(all.find("Name=\"velocity\""), std::string::npos);
}

TEST(ParticleOutput, TheDefaultKeepsTodaysColumnsAndTheCsvCanBeOff)
{
    io::DemScene s = twoSpheres("");
    auto dir = freshDirectory("default");
    {
        io::ParticleRecorder recorder(dir, s.output);
        recorder.record(s.world);
        recorder.close();
    }
    EXPECT_EQ(lines(dir / "particles.csv")[0], "t,id,x,y,z,vx,vy,vz,wx,wy,wz");
    io::DemScene off = twoSpheres("particles_csv = false");
    dir = freshDirectory("off");
    io::ParticleRecorder recorder(dir, off.output);
    recorder.record(off.world);
    EXPECT_EQ(recorder.csvBytes(), 0u);
    recorder.close();
    EXPECT_FALSE(std::filesystem::exists(dir / "particles.csv"));
    EXPECT_TRUE(std::filesystem::exists(dir / "particles_000000.vtp"));
}

TEST(OutputTime, ThermoWallsAndContactsPrintExactTimesAndWallNames)
{
    io::DemScene s = twoSpheres("contacts_csv = true");
    s.world.wallContacts.setRecordLoads(true);
    dem::step(s.world, s.dt);
    s.world.stepCount = 60000;
    const auto dir = freshDirectory("times");
    const std::vector<dem::ContactRecord> contacts = dem::evaluateContacts(s.world, 0.0);
    {
        io::ThermoRecorder thermo(dir, s.output);
        thermo.record(s.world, contacts);
        thermo.close();
        io::WallLoadRecorder walls(dir, s.output);
        walls.record(s.world);
        walls.close();
        io::ContactRecorder network(dir, s.output);
        network.record(s.world, contacts);
    }
    EXPECT_EQ(lines(dir / "thermo.csv")[1].rfind("0.6,2,", 0), 0u) << lines(dir / "thermo.csv")[1];
    EXPECT_EQ(lines(dir / "walls.csv")[1].rfind("0.6,floor,", 0), 0u);
    const std::vector<std::string> csv = lines(dir / "contacts_000000.csv");
    ASSERT_EQ(csv.size(), 4u); // header, the pair, two sphere-floor contacts
    EXPECT_EQ(csv[0], "t,id,partner,wall,overlap,cx,cy,cz,nx,ny,nz,fnx,fny,fnz,ftx,fty,ftz");
    EXPECT_EQ(csv[1].rfind("0.6,0,1,,", 0), 0u) << csv[1];
    EXPECT_EQ(csv[2].rfind("0.6,0,,floor,", 0), 0u) << csv[2];
    EXPECT_FALSE(std::filesystem::exists(dir / "contacts_000000.vtp")); // (contacts = false)
}
