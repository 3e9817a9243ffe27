#include "core/error.h"
#include "fdem/broadphase.h"
#include "fdem/elements/cst.h"
#include "fdem/mesher.h"
#include "fdem/scene.h"
#include "fdem/scene_runner.h"
#include "fdem/time_step.h"
#include "fdem/world.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <random>

namespace veridem::fdem
{
namespace
{

TEST(TimeStep, ElementLimitIsTheRuleOfThumb)
{
    // BENCHMARKS 1a: 10x10 block of 0.05 m, nu = 0.25 plane strain: dt_crit = 5.15e-6 s (power iteration)
    const Material m{2650, 1e9, 0.25, 0, StressLaw::FiniteStrain, PlaneModel::Strain};
    EXPECT_NEAR(pWaveSpeed(m), 672.9, 0.05);
    const Real h = 0.005 / std::sqrt(2.0);
    EXPECT_NEAR(elementTimeStep(h, pWaveSpeed(m), 0), 0.98 * h / pWaveSpeed(m), 1e-20);
    EXPECT_NEAR(elementTimeStep(h, pWaveSpeed(m), 0), 5.15e-6, 0.02 * 5.15e-6);
    EXPECT_NEAR(dampingFactor(0), 1, 1e-15);
    EXPECT_NEAR(dampingFactor(0.75), 0.5, 1e-15); // sqrt(1 + 0.5625) - 0.75
    EXPECT_NEAR(contactTimeStep(0.04, 1e10, 0), 2 * std::sqrt(0.04 / 1e10), 1e-20);

    WorldSettings s;
    s.contact.normalPenalty = 1e10;
    World w(s);
    const auto mat = w.addMaterial(m);
    w.addBody({"block", meshRectangle({0, 0}, {0.05, 0.05}, 10, 10), mat, {}, false});
    const TimeStepLimit limit = stableTimeStep(w);
    EXPECT_NEAR(limit.element, 5.15e-6, 0.02 * 5.15e-6);
    // contact: the lightest nodes (corners) belong to 2 triangles with the alternating diagonals:
    // m = 2 rho A0 / 3 with A0 = 1.25e-5 m^2; k = 4 * 3 p L / H with L the diagonal, H = L / 2
    const Real k = 12 * 1e10 * (0.005 * std::sqrt(2.0)) / h;
    EXPECT_NEAR(limit.contact, 2 * std::sqrt(2 * 2650 * 1.25e-5 / 3 / k), 1e-12);
    EXPECT_EQ(limit.limit, std::min(limit.element, limit.contact));
}

TEST(Broadphase, FindsTheSamePairsAsBruteForce)
{
    std::mt19937 rng(7);
    std::uniform_real_distribution<Real> pos(0, 1), side(0.001, 0.06);
    std::vector<BoundingBox> boxes(600);
    for (std::size_t i = 0; i < boxes.size(); ++i)
    {
        const Vec2 lo{pos(rng), pos(rng) * 0.3};
        boxes[i] = {lo, lo + Vec2{side(rng), side(rng) / 3}, static_cast<std::uint32_t>(i % 7), i % 3 != 0};
    }
    boxes[5] = {{0.2, 0.1}, {0.9, 0.12}, 1, true}; // one long box (a coarse base cell) among small ones
    const Real buffer = 0.004;
    std::vector<std::pair<std::uint32_t, std::uint32_t>> expected;
    for (std::uint32_t i = 0; i < boxes.size(); ++i)
        for (std::uint32_t j = i + 1; j < boxes.size(); ++j)
        {
            const auto &a = boxes[i], &b = boxes[j];
            const Real gapX = std::max(a.lo.x - b.hi.x, b.lo.x - a.hi.x),
                       gapY = std::max(a.lo.y - b.hi.y, b.lo.y - a.hi.y);
            if (a.group != b.group && (a.active || b.active) && gapX <= buffer && gapY <= buffer)
                expected.emplace_back(i, j);
        }
    EXPECT_EQ(findCandidatePairs(boxes, buffer), expected);
    EXPECT_GT(expected.size(), 100u);
}

TEST(World, RejectsNonPhysicalMaterials)
{
    WorldSettings s;
    s.contact.normalPenalty = 1e9;
    World w(s);
    EXPECT_THROW(w.addMaterial({-1, 1e9, 0.25, 0, StressLaw::Linear, PlaneModel::Strain}), InputError);
    EXPECT_THROW(w.addMaterial({2000, 0, 0.25, 0, StressLaw::Linear, PlaneModel::Strain}), InputError);
    EXPECT_THROW(w.addMaterial({2000, 1e9, 0.5, 0, StressLaw::Linear, PlaneModel::Strain}), InputError);
    s.contact.friction = 0.5; // friction without a tangential penalty
    EXPECT_THROW(World{s}, InputError);
}

TEST(World, FreeFallFollowsGravityExactly)
{
    WorldSettings s;
    s.timeStep = 1e-5;
    s.contact.normalPenalty = 1e9;
    World w(s);
    const auto m = w.addMaterial({1000, 1e8, 0.3, 0, StressLaw::FiniteStrain, PlaneModel::Strain});
    const auto b = w.addBody({"b", meshRectangle({0, 0}, {0.1, 0.1}, 3, 3), m, {0.5, 0}, false});
    for (int i = 0; i < 1000; ++i)
        w.step();
    const BodyState st = w.bodyState(b);
    // central difference: v_{n+1/2} = v0 + (n+1) g dt; x_n = x0 + dt sum v = x0 + g dt^2 n (n+1)/2
    EXPECT_NEAR(st.velocity.y, -9.81 * 1000 * 1e-5, 1e-12);
    EXPECT_NEAR(st.centroid.y - 0.05, -9.81 * 1e-10 * 1000 * 1001 / 2, 1e-12);
    EXPECT_NEAR(st.centroid.x - 0.05, 0.5 * 0.01, 1e-12);
}

TEST(World, SupportReactionEqualsTheLoadOfAStretchedBar)
{
    // A bar L x w (nu = 0, linear law, no viscosity, no gravity) held at x = 0 (nodes at rest) and
    // pulled at x = L at speed v, every free node started at v x / L: the strain stays uniform,
    // eps_n = v n dt / L after n steps, and the forces of step n + 1 (at x_n) on each end are the bar's
    // load sigma w = E (eps + eps^2 / 2) w (T = 2 mu E_xx, E_xx = eps + eps^2 / 2, width unchanged for
    // nu = 0). The support's load is that of the step, not a sum over the steps.
    constexpr Real barLength = 0.1, width = 0.02, modulus = 1e9, speed = 1, dt = 1e-7;
    WorldSettings s;
    s.timeStep = dt;
    s.gravity = {0, 0};
    s.contact.normalPenalty = 1e10;
    World w(s);
    const auto m = w.addMaterial({1000, modulus, 0, 0, StressLaw::Linear, PlaneModel::Stress});
    const auto b = w.addBody({"bar", meshRectangle({0, 0}, {barLength, width}, 5, 2), m, {}, false});
    ASSERT_EQ(w.prescribeNodes(b, {-1e-9, -1}, {1e-9, 1}, {0, 0}), 3u);
    ASSERT_EQ(w.prescribeNodes(b, {barLength - 1e-9, -1}, {barLength + 1e-9, 1}, {speed, 0}), 3u);
    for (std::uint32_t n = 0; n < w.nodes().size(); ++n)
        w.setNodeVelocity(n, {speed * w.nodes().position[n].x / barLength, 0});
    constexpr int steps = 100;
    for (int i = 0; i < steps; ++i)
        w.step();
    const Real eps = speed * (steps - 1) * dt / barLength; // the strain the last step's forces saw
    const Real load = modulus * (eps + 0.5 * eps * eps) * width;
    Vec2 held{}, pulled{};
    for (std::uint32_t n = 0; n < w.nodes().size(); ++n)
    {
        const Real x = w.nodes().referencePosition[n].x;
        if (x < 1e-9)
            held += w.nodes().force[n];
        else if (x > barLength - 1e-9)
            pulled += w.nodes().force[n];
        else // free nodes of a uniform stress field carry no net force
            EXPECT_LT(length(w.nodes().force[n]), 1e-9 * load);
    }
    // Tolerance: eps = 1e-4; the positions gather ~2e-16 m of round-off over the steps against
    // displacement differences eps h = 2e-6 m across an element: 1e-10 of the load (measured 2e-10).
    EXPECT_NEAR(held.x, load, 1e-9 * load); // the elements pull the held end towards +x
    EXPECT_NEAR(pulled.x, -load, 1e-9 * load);
    EXPECT_NEAR(w.prescribedForce(b).x, 0, 1e-9 * load); // both ends belong to the bar
    EXPECT_NEAR(held.y, 0, 1e-9 * load);
}

toml::table parse(const std::string& text)
{
    return toml::parse(text);
}

const char* kScene = R"(
[simulation]
type = "fdem2d"
dt = 1e-6
duration = 0.01
gravity = [0.0, -9.81]
[contact]
normal_penalty = 1e10
friction = 0.5
[[material]]
name = "rock"
density = 2650.0
youngs_modulus = 1e9
poisson_ratio = 0.25
[[body]]
name = "block"
material = "rock"
velocity = [1.0, 0.0]
rectangle = { origin = [0.0, 0.0], size = [0.05, 0.05], nx = 2, ny = 2 }
)";

TEST(Scene, ReadsAValidScene)
{
    const Scene s = readScene(parse(kScene), "test.toml");
    ASSERT_EQ(s.bodies.size(), 1u);
    EXPECT_EQ(s.bodies[0].mesh.triangles.size(), 8u);
    EXPECT_EQ(s.bodies[0].velocity, (Vec2{1, 0}));
    EXPECT_EQ(s.settings.contact.tangentialPenalty, 1e10); // defaults to the normal penalty
}

void expectError(const std::string& text, const std::string& fragment)
{
    try
    {
        readScene(parse(text), "test.toml");
        FAIL() << "expected InputError containing '" << fragment << "'";
    }
    catch (const InputError& e)
    {
        const std::string message = e.what();
        EXPECT_NE(message.find(fragment), std::string::npos) << message;
        EXPECT_EQ(message.find('\n'), std::string::npos) << message;
    }
}

TEST(Scene, BadInputGivesOneLineErrors)
{
    std::string s = kScene;
    expectError(std::string(s).replace(s.find("friction"), 8, "frictoin"), "did you mean 'friction'");
    expectError(std::string(s).replace(s.find("density = 2650.0"), 16, "density = -1.0"), "density");
    expectError(std::string(s).replace(s.find("poisson_ratio = 0.25"), 20, "poisson_ratio = 0.6"),
                "poisson_ratio");
    expectError(std::string(s).replace(s.find("velocity = [1.0, 0.0]"), 21, "velocity = [1.0]"),
                "2 finite numbers");
    expectError(std::string(s).replace(s.find("nx = 2"), 6, "nx = 0"), "nx");
    expectError(std::string(s).replace(s.find("material = \"rock\""), 17, "material = \"ice\""),
                "unknown material");
}

TEST(Scene, ReadsAGmshMeshRelativeToTheSceneFile)
{
    std::string s = kScene;
    s.replace(s.find("rectangle = {"), s.find('\n', s.find("rectangle = {")) - s.find("rectangle = {"),
              "mesh = \"square_v41.msh\"");
    const Scene scene = readScene(parse(s), std::string(VERIDEM_FDEM_TEST_DATA) + "/scene.toml");
    ASSERT_EQ(scene.bodies.size(), 1u);
    EXPECT_EQ(scene.bodies[0].mesh.triangles.size(), 4u);
}

TEST(Scene, ReadsAPolygonBodyAndRejectsTwoGeometries)
{
    std::string s = kScene;
    const auto at = s.find("rectangle = {");
    const auto end = s.find('\n', at);
    std::string polygon = s;
    polygon.replace(at, end - at, "polygon = [[0.0, 0.0], [0.05, 0.0], [0.05, 0.05], [0.0, 0.05]]");
    const Scene scene = readScene(parse(polygon), "test.toml");
    EXPECT_EQ(scene.bodies[0].mesh.triangles.size(), 2u);
    std::string both = s;
    both.insert(end, "\npolygon = [[0.0, 0.0], [0.05, 0.0], [0.05, 0.05]]");
    expectError(both, "exactly one of");
    std::string notTable = s;
    notTable.replace(at, end - at, "rectangle = 5");
    expectError(notTable, "rectangle");
}

TEST(Scene, EdgeLengthRefinesAPolygonAndMeshesADisc)
{
    std::string s = kScene;
    const auto at = s.find("rectangle = {");
    const auto end = s.find('\n', at);
    const auto with = [&](const std::string& geometry)
    {
        std::string t = s;
        t.replace(at, end - at, geometry);
        return t;
    };
    // The 0.05 m square at h = 0.01 m: 5 pieces per side, interior nodes, area kept.
    const Scene square = readScene(
        parse(with("polygon = [[0.0, 0.0], [0.05, 0.0], [0.05, 0.05], [0.0, 0.05]]\nedge_length = 0.01")),
        "test.toml");
    const TriangleMesh& m = square.bodies[0].mesh;
    EXPECT_GT(m.points.size(), 20u); // 20 on the outline, the rest inside
    Real area = 0;
    for (const auto& t : m.triangles)
        area += signedArea(m.points[t[0]], m.points[t[1]], m.points[t[2]]);
    EXPECT_NEAR(area, 0.0025, 1e-15);
    // A disc of radius 0.02 m (clear of nothing else: one body) at h = 0.005 m: 26 outline points.
    const Scene disc = readScene(
        parse(with("disc = { centre = [0.1, 0.1], radius = 0.02 }\nedge_length = 0.005")), "test.toml");
    EXPECT_GT(disc.bodies[0].mesh.triangles.size(), 40u);
    expectError(with("disc = { centre = [0.1, 0.1], radius = 0.02 }"), "edge_length");
    expectError(with("disc = { centre = [0.1, 0.1], radius = -0.02 }\nedge_length = 0.005"), "radius");
    expectError(with("disc = { centre = [0.1, 0.1], radius = 0.02, r = 1.0 }\nedge_length = 0.005"), "'r'");
    expectError(with("polygon = [[0.0, 0.0], [0.05, 0.0], [0.05, 0.05]]\nedge_length = 0.0"), "edge_length");
    expectError(with("polygon = [[0.0, 0.0], [0.05, 0.0], [0.05, 0.05]]\nedge_length = 1e-7"),
                "triangles (at most");
    expectError(std::string(s).insert(end, "\nedge_length = 0.01"), "applies to a 'polygon' or a 'disc'");
}

TEST(SceneRunner, RefusesATimeStepAboveTheLimitAndRunsBelowIt)
{
    std::string s = kScene;
    s.replace(s.find("dt = 1e-6"), 9, "dt = 1e-4");
    const auto out = std::filesystem::temp_directory_path() / "veridem_fdem_runner_test";
    try
    {
        runScene(parse(s), "test.toml", out, false, false);
        FAIL() << "expected InputError";
    }
    catch (const InputError& e)
    {
        EXPECT_NE(std::string(e.what()).find("exceeds the stable limit"), std::string::npos) << e.what();
    }
    std::string ok = kScene;
    ok.replace(ok.find("duration = 0.01"), 15, "duration = 1e-4");
    EXPECT_EQ(runScene(parse(ok), "test.toml", out, false, false), 0);
    EXPECT_TRUE(std::filesystem::exists(out / "series.pvd"));
    EXPECT_TRUE(std::filesystem::exists(out / "bodies.csv"));
    EXPECT_TRUE(std::filesystem::exists(out / "frame_00001.vtu"));
    std::filesystem::remove_all(out);
}

} // namespace
} // namespace veridem::fdem
