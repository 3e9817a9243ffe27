// Fragments of cracked bodies (fdem/fragments.h) and fragments.csv.
#include "fdem/fragments.h"
#include "fdem/mesher.h"
#include "fdem/output.h"
#include "fdem/world.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <string>

namespace veridem::fdem
{
namespace
{

/// Two 0.01 m square cells (4 triangles) with one joint on their shared vertical edge, and a
/// separate block. The right cell's nodes are pulled along +x at 0.1 m/s until the joint breaks.
World pulledPair(bool pull)
{
    WorldSettings s;
    s.gravity = {0, 0};
    s.timeStep = 1e-6;
    s.contact.normalPenalty = 1e11;
    World w(s);
    Material m{2500, 1e10, 0, 0, StressLaw::Linear, PlaneModel::Stress};
    m.fracture.tensileStrength = 3e6;
    m.fracture.fractureEnergy = m.fracture.shearFractureEnergy = 50;
    m.fracture.cohesion = 6e6;
    m.fracture.penalty = 1e11;
    m.fracture.curve = SofteningCurve::Linear;
    const auto mat = w.addMaterial(m, "rock");
    BodyDefinition b{"pair", meshRectangle({0, 0}, {0.02, 0.01}, 2, 1, DiagonalPattern::Right), mat};
    b.cracks = true;
    b.crackRegion = true;
    b.crackMin = {0.01 - 1e-9, -1e-9};
    b.crackMax = {0.01 + 1e-9, 0.01 + 1e-9};
    w.addBody(b);
    w.addBody({"block", meshRectangle({0.1, 0}, {0.03, 0.01}, 3, 1), mat});
    for (std::uint32_t t = 0; t < 4; ++t) // the pair's triangles come first
    {
        const auto& ids = w.triangles().nodes[t];
        const Real cx =
            (w.nodes().position[ids[0]].x + w.nodes().position[ids[1]].x + w.nodes().position[ids[2]].x) / 3;
        for (auto n : ids)
            w.prescribeNode(n, {cx > 0.01 && pull ? 0.1 : 0.0, 0});
    }
    // o_c = o_p + 2 G_f / f_t = 6e-7 + 3.3e-5 m: broken after ~340 steps of 1e-7 m.
    for (int i = 0; i < 1000 && pull && w.fractureState().broken == 0; ++i)
        w.step();
    return w;
}

TEST(Fragments, AnIntactBodyIsOneFragmentAndABrokenJointMakesTwo)
{
    const World intact = pulledPair(false);
    const auto one = findFragments(intact);
    ASSERT_EQ(one.size(), 2u); // the pair (tied by its joint) and the block
    EXPECT_EQ(one[0].body, 0u);
    EXPECT_EQ(one[0].triangles, 4u);
    EXPECT_NEAR(one[0].area, 2e-4, 1e-18);
    EXPECT_NEAR(one[0].mass, 2500 * 2e-4, 1e-15);
    EXPECT_EQ(one[1].body, 1u);
    EXPECT_NEAR(one[1].area, 3e-4, 1e-18);

    const World broken = pulledPair(true);
    ASSERT_EQ(broken.fractureState().broken, 1u);
    const auto three = findFragments(broken);
    ASSERT_EQ(three.size(), 3u);
    for (int k = 0; k < 2; ++k)
    {
        EXPECT_EQ(three[k].body, 0u);
        EXPECT_EQ(three[k].triangles, 2u);
        EXPECT_NEAR(three[k].area, 1e-4, 1e-18);
        EXPECT_NEAR(three[k].equivalentDiameter, std::sqrt(4e-4 / 3.141592653589793), 1e-15);
    }
    EXPECT_NEAR(three[0].centroid.x, 0.005, 1e-12); // the held cell
    EXPECT_GT(three[1].centroid.x, 0.015);          // the pulled one moved on

    const auto file = std::filesystem::temp_directory_path() / "veridem_fragments_test.csv";
    writeFragments(broken, file);
    std::ifstream in(file);
    std::string header, row;
    std::getline(in, header);
    EXPECT_EQ(header, "fragment,body,name,triangles,area,mass,x,y,equivalent_diameter,passing");
    int rows = 0;
    std::string firstRow;
    while (std::getline(in, row))
        if (rows++ == 0)
            firstRow = row;
    EXPECT_EQ(rows, 3);
    // Two equal halves: the first row of the pair passes everything of its body (fraction 1).
    EXPECT_EQ(firstRow.substr(firstRow.rfind(',') + 1), "1");
    std::filesystem::remove(file);
}

} // namespace
} // namespace veridem::fdem
