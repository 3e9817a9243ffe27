// The same bits on any thread count and across a checkpoint, in a scene where every loop of the step
// has work: a jointed block dropped onto a fixed platen breaks joints along its base, and the free
// edges of the cracks meet through the potential contact with friction and the normal dashpot.
#include "exec/thread_pool.h"
#include "fdem/checkpoint.h"
#include "fdem/mesher.h"
#include "fdem/time_step.h"
#include "fdem/world.h"

#include <gtest/gtest.h>

#include <filesystem>

namespace veridem::fdem
{

namespace
{

/// A 0.1 m square block of 40 x 40 cells (3200 triangles, 4720 joints, 9600 nodes: several chunks of
/// every parallel loop) falling at 3 m/s onto a fixed platen it starts touching, its right edge
/// pulled at 10 m/s: the tension wave (rho c_p v ~ 50 MPa > f_t = 3 MPa) opens the joints next to
/// that edge past o_c ~ 2 G_f / f_t in ~3 us, while the base slides and sticks on the platen.
World droppedBlock()
{
    WorldSettings s;
    s.timeStep = 2e-8; // below the stable limit of these 2.5 mm cells with p = 1e11 Pa joints
    s.contact.normalPenalty = 1e11;
    s.contact.tangentialPenalty = 1e11;
    s.contact.friction = 0.5;
    s.contact.normalDampingRatio = 0.2;
    s.contact.tangentialDampingRatio = 0.2;
    World w(s);
    Material m{2500, 1e10, 0.2, 0, StressLaw::FiniteStrain, PlaneModel::Strain};
    m.fracture.tensileStrength = 3e6;
    m.fracture.fractureEnergy = 50;
    m.fracture.shearFractureEnergy = 80;
    m.fracture.cohesion = 6e6;
    m.fracture.frictionAngle = 0.5;
    m.fracture.penalty = 1e11;
    m.fracture.curve = SofteningCurve::Linear;
    const auto rock = w.addMaterial(m, "rock");
    BodyDefinition platen{"platen", meshRectangle({-0.01, -0.01}, {0.12, 0.01}, 6, 1), rock};
    platen.fixed = true;
    w.addBody(platen);
    BodyDefinition block{
        "block", meshRectangle({0, 0}, {0.1, 0.1}, 40, 40, DiagonalPattern::Right), rock, {0.3, -3}};
    block.cracks = true;
    const auto id = w.addBody(block);
    w.prescribeNodes(id, {0.1 - 1e-9, -1}, {1, 1}, {10, -3});
    return w;
}

void expectSameBits(const World& a, const World& b)
{
    ASSERT_EQ(a.nodes().size(), b.nodes().size());
    for (std::size_t n = 0; n < a.nodes().size(); ++n)
    {
        ASSERT_EQ(a.nodes().position[n], b.nodes().position[n]) << n;
        ASSERT_EQ(a.nodes().velocity[n], b.nodes().velocity[n]) << n;
        ASSERT_EQ(a.nodes().force[n], b.nodes().force[n]) << n;
    }
    EXPECT_EQ(a.fractureState().broken, b.fractureState().broken);
    EXPECT_EQ(a.fractureState().jointWork, b.fractureState().jointWork);
    EXPECT_EQ(a.fractureState().energyReleased, b.fractureState().energyReleased);
    EXPECT_EQ(a.energies().frictionWork, b.energies().frictionWork);
    EXPECT_EQ(a.energies().normalDampingWork, b.energies().normalDampingWork);
    EXPECT_EQ(a.frictionDiagnostics().contacts, b.frictionDiagnostics().contacts);
    EXPECT_EQ(a.frictionDiagnostics().tangentialForce, b.frictionDiagnostics().tangentialForce);
    EXPECT_EQ(a.coupleCount(), b.coupleCount());
    EXPECT_EQ(a.detections(), b.detections());
}

constexpr int kSteps = 600; // 12 us

} // namespace

TEST(Threads, TheStableStepCoversTheScene)
{
    const World w = droppedBlock();
    EXPECT_LT(w.timeStep(), stableTimeStep(w).limit);
}

TEST(Threads, ContactsAndCracksHaveTheSameBitsOnOneTwoAndThreeThreads)
{
    const auto run = [](int threads)
    {
        exec::ThreadCountOverride override(threads);
        World w = droppedBlock();
        for (int i = 0; i < kSteps; ++i)
            w.step();
        return w;
    };
    const World one = run(1);
    // Every loop had work: joints broke, edge contacts carried friction and the dashpot dissipated.
    EXPECT_GT(one.fractureState().broken, 0u);
    EXPECT_GT(one.frictionDiagnostics().contacts, 0u);
    EXPECT_GT(one.energies().frictionWork, 0);
    EXPECT_GT(one.detections(), 1u);
    for (int threads : {2, 3})
    {
        SCOPED_TRACE(threads);
        expectSameBits(one, run(threads));
    }
}

TEST(Threads, ARestartWithCracksOpenKeepsTheBits)
{
    const auto file = std::filesystem::temp_directory_path() / "veridem_fdem_crack_restart.ckpt";
    const std::uint64_t hash = 0x5eed;
    World straight = droppedBlock();
    for (int i = 0; i < kSteps / 2; ++i)
        straight.step();
    ASSERT_GT(straight.fractureState().broken, 0u); // the checkpoint holds open cracks
    writeCheckpoint(file, straight, hash, {});
    for (int i = kSteps / 2; i < kSteps; ++i)
        straight.step();

    World restarted = droppedBlock();
    readCheckpoint(file, restarted, hash);
    std::filesystem::remove(file);
    for (int i = kSteps / 2; i < kSteps; ++i)
        restarted.step();
    EXPECT_GT(straight.fractureState().broken, 0u);
    EXPECT_EQ(straight.stepCount(), restarted.stepCount());
    EXPECT_EQ(straight.time(), restarted.time());
    expectSameBits(straight, restarted);
}

} // namespace veridem::fdem
