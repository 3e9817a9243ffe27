#include "fdem/scenarios.h"

#include "fdem/mesher.h"

#include <chrono>
#include <cmath>

namespace veridem::fdem
{

World makeSlidingBlockWorld(const SlidingBlockSetup& s)
{
    WorldSettings settings;
    settings.timeStep = s.timeStep;
    settings.gravity = {0, -s.gravity};
    settings.contact.normalPenalty = s.penaltyFactor * s.youngsModulus;
    settings.contact.tangentialPenalty = s.penaltyFactor * s.youngsModulus;
    settings.contact.friction = s.friction;
    settings.contact.normalDampingRatio = s.normalDampingRatio;
    World world(settings);
    Material m{s.density, s.youngsModulus, s.poissonRatio, 0, StressLaw::FiniteStrain, PlaneModel::Strain};
    // eta_v from the damping ratio of the highest mode: xi = eta_v omega_max / (2 (lambda + 2 mu)),
    // omega_max = 2 / dt_e with dt_e = 0.98 h_min / c_p (time_step.h).
    const Real cell = s.side / s.cells;
    const Real omegaMax = 2 / (0.98 * (cell / std::sqrt(2.0)) / pWaveSpeed(m));
    m.viscosity = 2 * s.highestModeDampingRatio * pWaveModulus(m) / omegaMax;
    const auto material = world.addMaterial(m, "block");
    const Real travel = s.velocity * s.velocity / (2 * s.friction * s.gravity);
    const Real baseStart = -2 * s.side, baseLength = travel + 4 * s.side;
    // The base is rigid (all nodes fixed); its cell size sets only the potential's altitude H and how
    // many base triangles a block edge overlaps, so it may be coarser than the block.
    const Real baseCell = s.baseCellFactor * cell;
    const int baseCells = static_cast<int>(std::ceil(baseLength / baseCell));
    world.addBody({"base",
                   meshRectangle({baseStart, -baseCell}, {baseCells * baseCell, baseCell}, baseCells, 1),
                   material,
                   {},
                   true});
    world.addBody({"block", meshRectangle({0, 0}, {s.side, s.side}, s.cells, s.cells), material, {}, false});
    return world;
}

SlidingBlockResult runSlidingBlock(const SlidingBlockSetup& s)
{
    const auto wallStart = std::chrono::steady_clock::now();
    SlidingBlockResult r;
    World world = makeSlidingBlockWorld(s);
    const std::uint32_t block = 1;
    while (world.time() < s.settleTime)
        world.step();
    ContactParameters sliding = world.settings().contact;
    sliding.normalDampingRatio = s.slidingNormalDampingRatio;
    world.setContactParameters(sliding);
    world.setBodyVelocity(block, {s.velocity, 0});
    const Real start = world.time();
    const Real x0 = world.bodyState(block).centroid.x;
    const Energies e0 = world.energies();
    r.kineticEnergy = 0.5 * world.bodyState(block).mass * s.velocity * s.velocity;
    const Real stopTimeTheory = s.velocity / (s.friction * s.gravity);
    Real belowSince = -1, xBelow = 0, ratioSum = 0, workAtStop = 0, dampingAtStop = 0;
    std::uint64_t ratioCount = 0;
    const int checkEvery = std::max(1, static_cast<int>(std::lround(1e-5 / s.timeStep)));
    while (world.time() - start < 2 * stopTimeTheory + 1)
    {
        world.step();
        if (world.stepCount() % checkEvery)
            continue;
        const BodyState b = world.bodyState(block);
        const FrictionDiagnostics& d = world.frictionDiagnostics();
        if (b.velocity.x > 0.01 * s.velocity && d.cap > 0)
        {
            ratioSum += d.tangentialForce / d.cap;
            ++ratioCount;
        }
        if (length(b.velocity) < s.stopSpeed)
        {
            if (belowSince < 0)
            {
                belowSince = world.time();
                xBelow = b.centroid.x;
                const Energies e = world.energies();
                workAtStop = e.frictionWork - e0.frictionWork;
                dampingAtStop = e.normalDampingWork - e0.normalDampingWork;
            }
            else if (world.time() - belowSince >= s.stopHold)
            {
                r.stopped = true;
                break;
            }
        }
        else
            belowSince = -1;
    }
    if (r.stopped)
    {
        r.stopDistance = xBelow - x0;
        r.stopTime = belowSince - start;
        r.frictionWork = workAtStop;
        r.dampingWork = dampingAtStop;
        const Real xHold = world.bodyState(block).centroid.x;
        const Real until = world.time() + s.creepTime;
        while (world.time() < until)
            world.step();
        r.creep = world.bodyState(block).centroid.x - xHold;
    }
    r.meanCapRatio = ratioCount ? ratioSum / static_cast<Real>(ratioCount) : 0;
    r.steps = world.stepCount();
    r.triangles = 2 * static_cast<std::size_t>(s.cells) * static_cast<std::size_t>(s.cells);
    r.wallSeconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - wallStart).count();
    return r;
}

} // namespace veridem::fdem
