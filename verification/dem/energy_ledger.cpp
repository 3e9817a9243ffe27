// The energy ledger (dem/energy_ledger.h, docs/measurements.md) closes: 324 spheres poured into a
// box under gravity, with normal damping, friction, EPSD rolling resistance and a side wall moving
// inward at constant speed, so that every term of
//     E_kin + E_elastic - W_gravity - W_walls + D_normal + D_tangential + D_friction + D_rolling
// is active. Every term is accumulated from the law's own force terms, none as a residual, so the
// balance checks the integrator and the ledger together: its residual is velocity Verlet's energy
// error. Two runs of the scene: without a tangential dashpot the residual is second order (it
// shrinks ~4x when dt halves, checked); with the default tangential dashpot a first-order part
// remains (measured ~1.7x per halving, docs/measurements.md), so only its size is bounded.
// A third run, two JKR spheres that touch, stick and break, checks D_adhesion (the energy a
// breaking contact loses) and bounds the residual by the force jumps' first-order error.
#include "dem/energy_ledger.h"

#include "dem/models/cohesion.h"
#include "support.h"

#include <cstdio>
#include <random>

namespace veridem::verify
{
namespace
{

struct LedgerRun
{
    Real residual = 0;    // at the end [J]
    Real maxResidual = 0; // largest |residual| over the run [J]
    dem::EnergyLedgerState state;
    Real kinetic = 0; // at the end [J]
    std::uint64_t steps = 0;
};

constexpr Real kRadius = 2e-3;    // mean sphere radius [m]
constexpr Real kBox = 0.03;       // box side [m]
constexpr Real kWallSpeed = 0.05; // the moving wall's inward speed [m/s]

World pourWorld(bool tangentialDashpot)
{
    Material m;
    m.name = "beads";
    m.density = 2500;
    m.normalStiffness = 2e3;
    m.restitution = 0.5;
    m.friction = 0.4;
    m.rollingModel = dem::RollingModel::Epsd;
    m.rollingFrictionLength = 0.1 * kRadius;
    if (!tangentialDashpot)
        m.tangentialDampingRatio = 0;
    World world = worldWith(m, {0, 0, -kG});
    const auto plane = [&](const char* name, Vec3 point, Vec3 normal, Vec3 velocity)
    {
        dem::Wall w;
        w.name = name;
        w.shape = dem::PlaneShape{point, normal};
        w.motion.velocity = velocity;
        world.walls.push_back(w);
    };
    plane("floor", {0, 0, 0}, {0, 0, 1}, {});
    plane("x0", {0, 0, 0}, {1, 0, 0}, {});
    plane("x1", {kBox, 0, 0}, {-1, 0, 0}, {-kWallSpeed, 0, 0}); // moves inward
    plane("y0", {0, 0, 0}, {0, 1, 0}, {});
    plane("y1", {0, kBox, 0}, {0, -1, 0}, {});
    std::mt19937 random(7);
    std::uniform_real_distribution<Real> unit(-1.0, 1.0);
    const Real spacing = kBox / 6;
    for (int layer = 0; layer < 9; ++layer)
        for (int a = 0; a < 6; ++a)
            for (int b = 0; b < 6; ++b)
            {
                const Vec3 x{(a + 0.5) * spacing, (b + 0.5) * spacing, 1.5 * kRadius + layer * spacing};
                const Vec3 v{0.1 * unit(random), 0.1 * unit(random), 0.1 * unit(random)};
                const Vec3 w{20 * unit(random), 20 * unit(random), 20 * unit(random)};
                const Real r = kRadius * (1 + 0.1 * unit(random));
                world.particles.add(x, v, w, r, m.density, 0);
            }
    return world;
}

LedgerRun run(Real dt, Real duration, bool tangentialDashpot, const CaseContext& context)
{
    World world = pourWorld(tangentialDashpot);
    dem::prepare(world);
    dem::EnergyLedger ledger;
    ledger.start(world);
    world.observer = &ledger;
    LedgerRun out;
    runFor(world, duration, dt, context, "energy_ledger",
           [&](const World& w)
           {
               const Real r = ledger.residual(w);
               out.maxResidual = std::max(out.maxResidual, std::abs(r));
           });
    out.residual = ledger.residual(world);
    out.state = ledger.state;
    out.kinetic = dem::kineticEnergy(world);
    out.steps = world.stepCount;
    return out;
}

Real dissipatedOf(const LedgerRun& run)
{
    return run.state.normalDamping + run.state.tangentialDamping + run.state.friction + run.state.rolling;
}

/// Two JKR spheres (R = 1 mm, E = 1e7 Pa, nu = 0.3, gamma = `gamma` [J/m^2], e = 0.5) meeting
/// head-on at 0.2 m/s, run for 1.5 ms at dt = 1 us (t_c / 300): they touch, stick, rebound and
/// break. Returns the ledger's state, residual and the final kinetic energy.
LedgerRun jkrCollision(Real gamma)
{
    Material m;
    m.name = "adhesive";
    m.normalModel = dem::NormalModel::Jkr;
    m.youngsModulus = 1e7;
    m.poissonRatio = 0.3;
    m.surfaceEnergy = gamma;
    m.restitution = 0.5;
    m.friction = 0;
    World world = worldWith(m, {0, 0, 0});
    const Real r = 1e-3, half = r + 5e-6;
    world.particles.add({-half, 0, 0}, {0.1, 0, 0}, {}, r, 2500, 0);
    world.particles.add({half, 0, 0}, {-0.1, 0, 0}, {}, r, 2500, 0);
    dem::prepare(world);
    dem::EnergyLedger ledger;
    ledger.start(world);
    world.observer = &ledger;
    for (int s = 0; s < 1500; ++s)
        dem::step(world, 1e-6);
    LedgerRun out;
    out.residual = ledger.residual(world);
    out.state = ledger.state;
    out.kinetic = dem::kineticEnergy(world);
    out.steps = world.stepCount;
    return out;
}

/// The JKR part: D_adhesion is the closed-form breaking energy, and the residual stays within the
/// bound of the force's jumps at touch and at the break (docs/measurements.md, JKR).
void addJkrQuantities(CaseResult& r)
{
    const LedgerRun jkr = jkrCollision(0.1), hertz = jkrCollision(0.0);
    const Real w = 0.2, rStar = 0.5e-3, modulus = 1e7 / (2 * (1 - 0.3 * 0.3)), dt = 1e-6;
    const Real breaking = dem::jkrBreakingEnergy(modulus, rStar, w);
    r.quantities.push_back(relativeQuantity("JKR pull-off: D_adhesion (one break)", "J", breaking,
                                            jkr.state.adhesion, 1e-12, "U(delta_c), closed form"));
    const Real mass = sphereMass(2500, 1e-3);
    const Real speedOut = std::sqrt(2 * jkr.kinetic / (0.5 * mass));
    const Real jumps =
        (4.0 / 3.0 * kPi * w * rStar * 0.2 + 5.0 / 6.0 * kPi * w * rStar * speedOut) * 0.5 * dt;
    const Real bound = jumps + 2 * std::abs(hertz.residual);
    r.quantities.push_back(absoluteQuantity(
        "JKR pull-off: |residual| / (jump bound + 2 |residual without adhesion|)", "", 0,
        std::abs(jkr.residual) / bound, 1.0, "force jumps |F| |v| dt / 2 at touch and break"));
    char note[160];
    std::snprintf(note, sizeof note,
                  "JKR pull-off: residual %.3g J, dissipated %.3g J (adhesion %.3g J); "
                  "without adhesion residual %.3g J",
                  jkr.residual, dissipatedOf(jkr) + jkr.state.adhesion, jkr.state.adhesion, hertz.residual);
    r.notes.push_back(note);
}

CaseResult runCase(const CaseContext& context)
{
    // m* of two beads ~4.2e-5 kg, kn = 2e3 N/m: t_c = pi sqrt(m*/kn) ~ 4.6e-4 s; dt ~ t_c / 30.
    const Real dt = 1.5e-5, duration = 0.12;
    CaseResult r;
    const auto line = [&](const std::string& name, Real a, Real b)
    { r.notes.push_back(name + ": " + std::to_string(a) + " J (dt), " + std::to_string(b) + " J (dt/2)"); };
    for (const bool dashpot : {false, true})
    {
        const LedgerRun coarse = run(dt, duration, dashpot, context);
        const LedgerRun fine = run(0.5 * dt, duration, dashpot, context);
        const std::string tag = dashpot ? " (tangential dashpot)" : " (no tangential dashpot)";
        const Real dissipated = dissipatedOf(coarse);
        const Real ratio = coarse.maxResidual / fine.maxResidual;
        if (!dashpot)
        {
            // Velocity Verlet's energy error per contact event is O((omega dt)^2), (pi/30)^2 ~ 1e-2
            // of the event's energy at worst, and the errors of successive events largely cancel
            // (a symplectic scheme): 1e-3 of the energy dissipated (measured 4.2e-4).
            r.quantities.push_back(absoluteQuantity("max |residual| / D" + tag, "", 0,
                                                    coarse.maxResidual / dissipated, 1e-3,
                                                    "Verlet's O((omega dt)^2) energy error"));
            // Second order: halving dt divides the residual by 4 (measured 3.93; 2.5-5.5 accepted:
            // the residual is a sum over many contact events of either sign).
            r.quantities.push_back(
                absoluteQuantity("max residual ratio dt / (dt/2)" + tag, "", 4.0, ratio, 1.5, "O(dt^2)"));
        }
        else
        {
            // The tangential dashpot adds a first-order part (docs/measurements.md): bounded by
            // 3e-3 of the energy dissipated (measured 1.5e-3), and it must shrink with dt.
            r.quantities.push_back(absoluteQuantity("max |residual| / D" + tag, "", 0,
                                                    coarse.maxResidual / dissipated, 3e-3,
                                                    "first-order part of the tangential dashpot"));
            r.quantities.push_back(absoluteQuantity("max residual ratio dt / (dt/2)" + tag, "", 1.3, ratio,
                                                    0.0, "shrinks with dt (>= 1.3x per halving)"));
            r.quantities.back().atLeast = true;
        }
        line("initial energy" + tag, coarse.state.initialEnergy, fine.state.initialEnergy);
        line("kinetic energy at the end" + tag, coarse.kinetic, fine.kinetic);
        line("elastic energy at the end" + tag, coarse.state.elasticEnergy, fine.state.elasticEnergy);
        line("work of gravity" + tag, coarse.state.gravityWork, fine.state.gravityWork);
        line("work of the walls" + tag, coarse.state.wallWork, fine.state.wallWork);
        line("normal damping" + tag, coarse.state.normalDamping, fine.state.normalDamping);
        line("tangential damping" + tag, coarse.state.tangentialDamping, fine.state.tangentialDamping);
        line("friction" + tag, coarse.state.friction, fine.state.friction);
        line("rolling" + tag, coarse.state.rolling, fine.state.rolling);
        line("residual at the end" + tag, coarse.residual, fine.residual);
        line("max |residual|" + tag, coarse.maxResidual, fine.maxResidual);
    }
    addJkrQuantities(r);
    return r;
}

} // namespace

VERIDEM_CASE({.name = "energy_ledger",
              .summary = "324 spheres poured with damping, friction, EPSD rolling and a moving wall: the "
                         "energy ledger balances (second order without a tangential dashpot); a JKR "
                         "pull-off balances with D_adhesion",
              .reference = "docs/measurements.md (ledger derivation)",
              .labels = {"dem", "quick"},
              .run = runCase});

} // namespace veridem::verify
