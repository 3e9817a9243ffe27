// The cohesive law and the joint elements (fracture/cohesive_law.h, fracture/joints.h).
#include "core/error.h"
#include "exec/thread_pool.h"
#include "fdem/fracture/cohesive_law.h"
#include "fdem/fracture/joints.h"
#include "fdem/mesher.h"
#include "fdem/scene.h"
#include "fdem/time_step.h"
#include "fdem/world.h"

#include <gtest/gtest.h>

#include <cmath>

namespace veridem::fdem
{
namespace
{

constexpr SofteningCurve kCurves[] = {SofteningCurve::Munjiza, SofteningCurve::Linear,
                                      SofteningCurve::Exponential};

TEST(CohesiveLaw, SofteningCurvesRunFromOneToZeroAndDecrease)
{
    for (auto curve : kCurves)
    {
        EXPECT_NEAR(softening(curve, 0), 1, 1e-15);
        EXPECT_NEAR(softening(curve, 1), 0, 1e-15);
        for (int i = 0; i < 1000; ++i)
            EXPECT_GE(softening(curve, i / 1000.0), softening(curve, (i + 1) / 1000.0));
    }
    // Closed forms of the areas: linear 1/2; exponential ((1 - e^-5)/5 - e^-5)/(1 - e^-5).
    EXPECT_NEAR(softeningArea(SofteningCurve::Linear), 0.5, 1e-15);
    const Real e5 = std::exp(-5.0);
    EXPECT_NEAR(softeningArea(SofteningCurve::Exponential), ((1 - e5) / 5 - e5) / (1 - e5), 1e-13);
    // Munjiza's curve: against a 200 000-interval trapezoid sum (error ~ 1e-10 for a smooth curve).
    Real trapezoid = 0;
    const int n = 200000;
    for (int i = 0; i < n; ++i)
        trapezoid += 0.5 *
                     (softening(SofteningCurve::Munjiza, Real(i) / n) +
                      softening(SofteningCurve::Munjiza, Real(i + 1) / n)) /
                     n;
    EXPECT_NEAR(softeningArea(SofteningCurve::Munjiza), trapezoid, 1e-9);
}

CohesiveConstants law(SofteningCurve curve)
{
    FractureParameters f;
    f.tensileStrength = 3e6;
    f.fractureEnergy = 50;
    f.shearFractureEnergy = 80;
    f.cohesion = 6e6;
    f.frictionAngle = 0.5;
    f.penalty = 1e11;
    f.curve = curve;
    return cohesiveConstants(f);
}

TEST(CohesiveLaw, ModeIFollowsTheCurveAndDissipatesGf)
{
    const Real h = 0.01;
    for (auto curve : kCurves)
    {
        const CohesiveConstants k = law(curve);
        const Real op = 2 * h * 3e6 / 1e11;
        EXPECT_NEAR(cohesiveTraction(op, 0, h, 0, k).normal, 3e6, 1e-6); // the peak is f_t at o_p
        EXPECT_NEAR(cohesiveTraction(0.5 * op, 0, h, 0, k).normal, 0.75 * 3e6, 1e-6);
        // Work over the softening branch, integrated by the trapezoid rule on a path of 1e5 steps:
        // equal to G_f within the rule's O(step^2) error (1e-6 here; Munjiza's curve has a steep start).
        Real damage = 0, work = 0, previous = 3e6;
        const int steps = 100000;
        const Real oc = op + k.normalSoftening;
        for (int i = 1; i <= steps; ++i)
        {
            const CohesiveResult r = cohesiveTraction(op + (oc - op) * i / steps, 0, h, damage, k);
            work += 0.5 * (r.normal + previous) * (oc - op) / steps;
            previous = r.normal;
            damage = r.damage;
        }
        EXPECT_NEAR(work / 50, 1, 1e-6);
        EXPECT_EQ(damage, 1);
        EXPECT_EQ(previous, 0);
    }
}

TEST(CohesiveLaw, DamageIsIrreversibleAndShearFollowsMohrCoulomb)
{
    const Real h = 0.01;
    const CohesiveConstants k = law(SofteningCurve::Linear);
    const Real op = 2 * h * 3e6 / 1e11;
    const CohesiveResult half = cohesiveTraction(op + 0.5 * k.normalSoftening, 0, h, 0, k);
    EXPECT_NEAR(half.damage, 0.5, 1e-12);
    EXPECT_NEAR(half.normal, 1.5e6, 1e-3);
    // Unloading to o_p / 2 keeps D = 0.5: the scaled pre-peak curve z(D) f_t g(1/2).
    const CohesiveResult back = cohesiveTraction(0.5 * op, 0, h, half.damage, k);
    EXPECT_NEAR(back.damage, 0.5, 1e-12);
    EXPECT_NEAR(back.normal, 0.5 * 0.75 * 3e6, 1e-3);
    // Compression: linear penalty p o / h, and the shear strength c + sigma_c tan(phi).
    const Real o = -1e-6, sigmaC = 1e11 * 1e-6 / h;
    const Real fs = 6e6 + sigmaC * std::tan(0.5);
    const Real sp = 2 * h * fs / 1e11;
    const CohesiveResult r = cohesiveTraction(o, -sp, h, 0, k);
    EXPECT_NEAR(r.normal, -sigmaC, 1e-6);
    EXPECT_NEAR(r.tangential, -fs, 1e-6);
    EXPECT_EQ(r.damage, 0);
    // Mixed mode: D = sqrt(D_n^2 + D_s^2).
    const Real sp0 = 2 * h * 6e6 / 1e11;
    const CohesiveResult m =
        cohesiveTraction(op + 0.3 * k.normalSoftening, sp0 + 0.4 * k.shearSoftening, h, 0, k);
    EXPECT_NEAR(m.damage, 0.5, 1e-12);
}

TEST(Joints, SplittingAllInteriorEdgesGivesEachTriangleItsNodes)
{
    const TriangleMesh mesh = meshRectangle({0, 0}, {2, 1}, 2, 1, DiagonalPattern::Right);
    const SplitMesh all = splitForJoints(mesh, [](Vec2, Vec2) { return true; });
    EXPECT_EQ(all.mesh.points.size(), 12u); // 4 triangles x 3 corners
    EXPECT_EQ(all.jointNodes.size(), 3u);   // two diagonals and the middle vertical edge
    for (const auto& j : all.jointNodes)
    {
        EXPECT_EQ(all.mesh.points[j[0]].x, all.mesh.points[j[2]].x); // b0 is a0's copy
        EXPECT_EQ(all.mesh.points[j[1]].y, all.mesh.points[j[3]].y); // b1 is a1's copy
        EXPECT_NE(j[0], j[2]);
    }
    // Only the middle edge (x = 1): two halves that keep their inner nodes, 8 nodes.
    const SplitMesh middle = splitForJoints(
        mesh, [](Vec2 p, Vec2 q) { return std::abs(p.x - 1) < 1e-12 && std::abs(q.x - 1) < 1e-12; });
    EXPECT_EQ(middle.jointNodes.size(), 1u);
    EXPECT_EQ(middle.mesh.points.size(), 8u);
}

World crackingWorld(Real fractureEnergy, bool region)
{
    WorldSettings s;
    s.contact.normalPenalty = 1e11;
    World w(s);
    Material m{2500, 1e10, 0, 0, StressLaw::Linear, PlaneModel::Stress};
    m.fracture = law(SofteningCurve::Linear).p;
    m.fracture.fractureEnergy = fractureEnergy;
    const auto mat = w.addMaterial(m, "rock");
    BodyDefinition b{"bar", meshRectangle({0, 0}, {0.1, 0.01}, 10, 1, DiagonalPattern::Right), mat};
    b.cracks = true;
    b.crackRegion = region;
    b.crackMin = {0.2, 0.2}; // outside the bar
    b.crackMax = {0.3, 0.3};
    w.addBody(b);
    return w;
}

TEST(Joints, BadInputIsRefusedWithTheBodyAndTheSizeThatWouldWork)
{
    EXPECT_NO_THROW(crackingWorld(50, false));
    // Linear softening: h_max = 2 E G_f / f_t^2; the altitude across the vertical joints is 0.01 m,
    // so G_f below f_t^2 h / (2 E) = 4.5 J/m^2 snaps back.
    try
    {
        crackingWorld(4, false);
        FAIL() << "a snap-back was accepted";
    }
    catch (const InputError& e)
    {
        EXPECT_NE(std::string(e.what()).find("body 'bar'"), std::string::npos) << e.what();
        EXPECT_NE(std::string(e.what()).find("at most 0.00888"), std::string::npos) << e.what();
    }
    EXPECT_THROW(crackingWorld(0, false), InputError);
    try
    {
        crackingWorld(50, true);
        FAIL() << "an empty crack region was accepted";
    }
    catch (const InputError& e)
    {
        EXPECT_NE(std::string(e.what()).find("selects no interior edge"), std::string::npos) << e.what();
    }
}

TEST(Joints, ABodyThatCracksMovesRigidlyWithoutForcesAndHasAJointTimeStep)
{
    World w = crackingWorld(50, false);
    EXPECT_EQ(w.joints().size(), 19u); // 9 vertical edges and 10 diagonals
    w.setBodyVelocity(0, {1, 0.5});
    for (int i = 0; i < 100; ++i)
        w.step();
    const FractureState f = w.fractureState();
    EXPECT_EQ(f.broken, 0u);
    EXPECT_NEAR(f.jointWork, 0, 1e-12);
    for (std::size_t j = 0; j < w.joints().size(); ++j)
        for (int k = 0; k < 2; ++k)
            EXPECT_NEAR(w.joints().opening[j][k], 0, 1e-15); // a translation opens nothing
    const TimeStepLimit limit = stableTimeStep(w);
    EXPECT_LT(limit.joint, limit.element);
    EXPECT_EQ(limit.limit, std::min({limit.element, limit.contact, limit.joint}));
}

TEST(Joints, ABrokenJointsFacesMeetThroughTheContact)
{
    // Two cells with one joint on the shared edge; every node prescribed. The right cell moves away
    // until the joint breaks, then comes back 1 um past closing: the crack faces must push it back
    // (the potential contact), and the couple of the two triangles exists only after the break.
    WorldSettings s;
    s.gravity = {0, 0};
    s.timeStep = 1e-6;
    s.contact.normalPenalty = 1e10;
    World w(s);
    Material m{2500, 1e10, 0, 0, StressLaw::Linear, PlaneModel::Stress};
    m.fracture = law(SofteningCurve::Linear).p;
    w.addMaterial(m, "rock");
    BodyDefinition b{"pair", meshRectangle({0, 0}, {0.02, 0.01}, 2, 1, DiagonalPattern::Right), 0};
    b.cracks = true;
    b.crackRegion = true;
    b.crackMin = {0.01 - 1e-9, -1e-9};
    b.crackMax = {0.01 + 1e-9, 0.01 + 1e-9};
    w.addBody(b);
    ASSERT_EQ(w.joints().size(), 1u);
    const auto tied = w.joints().triangles[0];
    const auto coupled = [&]()
    {
        for (const Couple& c : w.couples())
            if ((c.first == tied[0] && c.second == tied[1]) || (c.first == tied[1] && c.second == tied[0]))
                return true;
        return false;
    };
    std::vector<std::uint32_t> moving;
    const auto prescribe = [&](Real v)
    {
        moving.clear();
        for (std::uint32_t t = 0; t < w.triangles().size(); ++t)
        {
            const auto& ids = w.triangles().nodes[t];
            const Real cx = (w.nodes().referencePosition[ids[0]].x + w.nodes().referencePosition[ids[1]].x +
                             w.nodes().referencePosition[ids[2]].x) /
                            3;
            for (auto n : ids)
            {
                w.prescribeNode(n, {cx > 0.01 ? v : 0, 0});
                if (cx > 0.01)
                    moving.push_back(n);
            }
        }
    };
    prescribe(0.01); // 1e-8 m per step; o_c = 3.4e-5 m
    int steps = 0;
    while (w.fractureState().broken == 0 && steps < 10000)
    {
        w.step();
        ++steps;
        EXPECT_EQ(coupled(), w.fractureState().broken == 1); // listed from the breaking step on
    }
    ASSERT_EQ(w.fractureState().broken, 1u);
    prescribe(-0.01);
    for (int i = 0; i < steps + 100; ++i) // back to 1e-6 m of overlap
        w.step();
    EXPECT_TRUE(coupled());
    Real fx = 0;
    for (auto n : moving)
        fx += w.nodes().force[n].x;
    EXPECT_GT(fx, 0); // the contact pushes the right cell back out
}

TEST(Joints, TheSameBitsOnOneAndTwoThreads)
{
    // A 40 x 40 block (3200 triangles, 4720 joints: several chunks of the element and joint loops)
    // whose right edge is pulled at 5 m/s: the wave (rho c v = 25 MPa > f_t) breaks joints at once.
    const auto run = [](int threads)
    {
        exec::ThreadCountOverride override(threads);
        WorldSettings s;
        s.gravity = {0, 0};
        s.timeStep = 5e-8;
        s.contact.normalPenalty = 1e10;
        World w(s);
        Material m{2500, 1e10, 0.2, 0, StressLaw::FiniteStrain, PlaneModel::Strain};
        m.fracture = law(SofteningCurve::Munjiza).p;
        w.addMaterial(m, "rock");
        BodyDefinition b{"block", meshRectangle({0, 0}, {0.1, 0.1}, 40, 40), 0};
        b.cracks = true;
        w.addBody(b);
        w.prescribeNodes(0, {-1, -1}, {1e-9, 1}, {0, 0});
        w.prescribeNodes(0, {0.1 - 1e-9, -1}, {1, 1}, {5, 0});
        for (int i = 0; i < 300; ++i)
            w.step();
        return w;
    };
    const World one = run(1), two = run(2);
    EXPECT_GT(one.fractureState().broken, 0u);
    EXPECT_EQ(one.fractureState().broken, two.fractureState().broken);
    EXPECT_EQ(one.fractureState().jointWork, two.fractureState().jointWork);
    ASSERT_EQ(one.nodes().size(), two.nodes().size());
    for (std::size_t n = 0; n < one.nodes().size(); ++n)
    {
        ASSERT_EQ(one.nodes().position[n], two.nodes().position[n]) << n;
        ASSERT_EQ(one.nodes().velocity[n], two.nodes().velocity[n]) << n;
    }
}

const char* kCrackScene = R"(
[simulation]
type = "fdem2d"
dt = 1e-7
duration = 0.001
[contact]
normal_penalty = 1e10
[[material]]
name = "rock"
density = 2500.0
youngs_modulus = 1e10
poisson_ratio = 0.2
tensile_strength = 3e6
fracture_energy = 50.0
cohesion = 6e6
internal_friction_degrees = 30.0
softening = "linear"
[[body]]
name = "slab"
material = "rock"
cracks = true
crack_box_min = [0.0, 0.0]
crack_box_max = [0.02, 0.01]
rectangle = { origin = [0.0, 0.0], size = [0.04, 0.01], nx = 4, ny = 1, pattern = "right" }
)";

std::string buildError(const std::string& text)
{
    try
    {
        buildWorld(readScene(toml::parse(text), "crack.toml"), false);
    }
    catch (const InputError& e)
    {
        const std::string message = e.what();
        EXPECT_EQ(message.find('\n'), std::string::npos) << message;
        return message;
    }
    return "";
}

TEST(Joints, SceneKeysAreReadAndCheckedBeforeTheRun)
{
    const Scene scene = readScene(toml::parse(kCrackScene), "crack.toml");
    const FractureParameters& f = scene.materials[0].fracture;
    EXPECT_EQ(f.tensileStrength, 3e6);
    EXPECT_EQ(f.shearFractureEnergy, 50); // defaults to fracture_energy
    EXPECT_EQ(f.penalty, 1e11);           // defaults to 10 E
    EXPECT_NEAR(f.frictionAngle, 0.5235987755982988, 1e-15);
    EXPECT_EQ(f.curve, SofteningCurve::Linear);
    EXPECT_TRUE(scene.bodies[0].cracks && scene.bodies[0].crackRegion);
    // The region (x <= 0.02) holds the diagonals of cells 0 and 1 and the vertical edge at x = 0.01
    // (the one at x = 0.02 has its midpoint on the box's edge: inside).
    const World world = buildWorld(scene, false);
    EXPECT_EQ(world.joints().size(), 4u);
    std::string s = kCrackScene;
    EXPECT_NE(
        buildError(std::string(s).replace(s.find("tensile_strength = 3e6"), 22, "tensile_strength = 0.0"))
            .find("body 'slab' cracks: its material's tensile_strength must be > 0"),
        std::string::npos);
    EXPECT_NE(
        buildError(std::string(s).replace(s.find("fracture_energy = 50.0"), 22, "fracture_energy = 1.0"))
            .find("use elements of at most"),
        std::string::npos);
    EXPECT_NE(buildError(std::string(s).replace(s.find("crack_box_min = [0.0, 0.0]"), 26,
                                                "crack_box_min = [0.5, 0.0]"))
                  .find("crack_box_max"),
              std::string::npos); // max below min
    EXPECT_NE(
        buildError(std::string(s).replace(s.find("softening = \"linear\""), 20, "softening = \"cubic\""))
            .find("softening"),
        std::string::npos);
    EXPECT_NE(buildError(std::string(s).replace(s.find("cracks = true"), 13, "cracks = false"))
                  .find("needs cracks = true"),
              std::string::npos);
}

} // namespace
} // namespace veridem::fdem
