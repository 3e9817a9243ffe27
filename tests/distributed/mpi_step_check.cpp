// Distributed steps (distributed/rank_step.h) under `mpirun -np N` (CTest: N = 1, 2, 4), each against
// the same world stepped in one process on every rank (the reference). Checked:
//   - bowling ball (BENCHMARKS 5 #2): a ball launched sliding (v0 = 2 m/s, no spin, mu = 0.3) on a
//     floor crosses the boundary between two ranks' regions while it slides (the regions are cut
//     along x by 64 frozen markers far from its path), so its floor contact's tangential spring
//     must migrate with it. Its one contact is the floor, so its motion is the reference's bit for
//     bit; and it reaches v_f = 5/7 v0 (1e-6, as the verification case: angular momentum about the
//     contact point is kept to round-off) at t* = 2 v0 / (7 mu g) (0.5 %). With N >= 2 the ball
//     must have changed rank (else the check proves nothing). Run twice: with the exchanges of the
//     step only, and with one after every 5th step too (as at a flow event), where the ball must
//     migrate (checked) with its force and torque (the next kick-drift reads them).
//   - a pour: 2,156 spheres with EPSD rolling springs rain into a box (4 walls and a floor; the
//     example box_fill, filled higher) for 1,500 steps, through impacts and the first contacts of the heap.
//     Every particle is owned by one rank (ids 0..N-1 once each); a second run on the same rank count gives
//     the same bits; another thread count gives the same bits; and against the reference the positions differ
//     by at most 1e-12 m (6.7e-10 of the radius) and the kinetic energy by at most 1e-9 relative: each
//     particle's contact sum has another order on N ranks (round-off, ~1e-16 relative a step), which the
//     impacts amplify. Measured: 2.1e-14 m and 7e-14 on 2 ranks, 1.6e-14 m and 1.6e-13 on 4; the bounds leave
//     a factor 50 on the positions (and ~10^4 on the energy, whose sum over 2,156 terms is less sensitive to
//     one particle's order than to the number of particles in contact at the last step).
//   - load balance: a column of spheres falls onto a floor; its regions, cut along z at the start,
//     follow the particles down when cut again every 10th exchange (the busiest rank within 10 %
//     of the mean cost), and the same column with the first cut kept is unbalanced (> 1.5: the
//     case tests the cuts).
// Exit 0 when every rank passes.
#include "dem/world.h"
#include "distributed/mpi_collective.h"
#include "distributed/rank_gather.h"
#include "distributed/rank_step.h"
#include "exec/thread_pool.h"

#include <cmath>
#include <cstdio>
#include <cstring>
#include <random>
#include <string>
#include <vector>

using namespace veridem;
using namespace veridem::distributed;

namespace
{

std::vector<std::string> failures;
void fail(const std::string& m)
{
    if (failures.size() < 20)
        failures.push_back(m);
}

dem::Wall plane(const char* name, Vec3 point, Vec3 normal)
{
    dem::Wall w;
    w.name = name;
    w.shape = dem::PlaneShape{point, normal};
    return w;
}

bool sameBits(const Vec3& a, const Vec3& b)
{
    return std::memcmp(&a, &b, sizeof a) == 0;
}

constexpr Real kG = 9.81;

// --- bowling ball

constexpr Real kBallRadius = 6.35e-3, kV0 = 2.0, kMu = 0.3;

dem::World bowlingWorld()
{
    dem::World world;
    dem::Material steel;
    steel.name = "steel";
    steel.density = 7800;
    steel.normalStiffness = 1e5;
    steel.restitution = 0.8;
    steel.friction = kMu;
    world.addMaterial(steel);
    world.gravity = {0, 0, -kG};
    world.walls.push_back(plane("floor", {0, 0, 0}, {0, 0, 1}));
    const Real m = 7800 * 4.0 / 3.0 * 3.14159265358979 * std::pow(kBallRadius, 3);
    world.particles.add({0, 0, kBallRadius - m * kG / 1e5}, {kV0, 0, 0}, {}, kBallRadius, 7800, 0);
    // Frozen markers along x from -0.5 to 1.0 m, 0.2 m beside the path: the cuts fall on x (the
    // longest axis) at their quantiles, 0.25 m for two ranks, which the ball passes at ~0.14 s.
    for (int k = 0; k < 64; ++k)
    {
        world.particles.add({-0.5 + 1.5 * k / 63.0, 0.2, 0.5}, {}, {}, kBallRadius, 7800, 0);
        world.particles.fixed.back() = 1;
    }
    dem::prepare(world);
    return world;
}

/// The ball's state on every rank (from its owner), by one collective.
struct BallState
{
    Vec3 x, v, w;
    int owner = -1;
};
BallState ballState(const dem::World& world, const RankStep* ranks, const Collective& comm)
{
    std::vector<double> values(10, -1e300);
    const std::size_t n = ranks ? ranks->owned() : world.particles.size();
    for (std::size_t i = 0; i < n; ++i)
        if (world.particles.id[i] == 0)
        {
            const Vec3 q[3] = {world.particles.position[i], world.particles.velocity[i],
                               world.particles.angularVelocity[i]};
            for (int k = 0; k < 3; ++k)
            {
                values[3 * k] = q[k].x;
                values[3 * k + 1] = q[k].y;
                values[3 * k + 2] = q[k].z;
            }
            values[9] = comm.rank();
        }
    if (ranks)
        comm.max(values);
    return {{values[0], values[1], values[2]},
            {values[3], values[4], values[5]},
            {values[6], values[7], values[8]},
            int(values[9])};
}

/// `betweenSteps`: an exchange of particles after every 5th step as well (RankStep::admit, as at a
/// flow event), so that the ball migrates between steps, where its force and torque (the step's
/// totals, read by the next kick-drift) must travel with it; that it did is checked (with N >= 2).
void bowlingBall(const Collective& comm, bool betweenSteps)
{
    const Real dt = 1e-5, duration = 0.3;
    const auto steps = static_cast<std::uint64_t>(std::llround(duration / dt));
    dem::World reference = bowlingWorld();
    dem::World world = bowlingWorld();
    RankStep ranks(comm, 1000000); // (the regions stay as first cut)
    ranks.distribute(world);
    const int firstOwner = ballState(world, &ranks, comm).owner;
    Real tStar = -1, previousSlip = kV0, previousT = 0;
    bool identical = true, migratedBetweenSteps = false;
    for (std::uint64_t s = 0; s < steps; ++s)
    {
        dem::step(reference, dt);
        dem::step(world, dt);
        if (betweenSteps && (s + 1) % 5 == 0)
        {
            const int before = ballState(world, &ranks, comm).owner;
            ranks.admit(world, dem::ParticleStore{});
            migratedBetweenSteps = migratedBetweenSteps || ballState(world, &ranks, comm).owner != before;
        }
        const BallState b = ballState(world, &ranks, comm);
        if (identical && !(sameBits(b.x, reference.particles.position[0]) &&
                           sameBits(b.v, reference.particles.velocity[0]) &&
                           sameBits(b.w, reference.particles.angularVelocity[0])))
        {
            identical = false;
            fail(std::string("bowling ball") + (betweenSteps ? " (exchanges between steps)" : "") +
                 ": step " + std::to_string(s + 1) + ": the ball's state differs from one process's (x " +
                 std::to_string(b.x.x) + " m, v " + std::to_string(b.v.x) + " against " +
                 std::to_string(reference.particles.velocity[0].x) + " m/s)");
        }
        const Real slip = b.v.x - kBallRadius * b.w.y;
        if (tStar < 0 && slip <= 0)
            tStar = previousT + (world.time - previousT) * previousSlip / (previousSlip - slip);
        previousSlip = slip;
        previousT = world.time;
    }
    const BallState end = ballState(world, &ranks, comm);
    const Real vFinal = end.v.x, tTheory = 2 * kV0 / (7 * kMu * kG);
    if (!(std::abs(vFinal / (5.0 / 7.0 * kV0) - 1) < 1e-6))
        fail("bowling ball: v_f = " + std::to_string(vFinal) +
             " m/s, expected 5/7 v0 = " + std::to_string(5.0 / 7.0 * kV0));
    if (!(std::abs(tStar / tTheory - 1) < 5e-3))
        fail("bowling ball: t* = " + std::to_string(tStar) + " s, expected " + std::to_string(tTheory));
    if (comm.size() > 1 && betweenSteps && !migratedBetweenSteps)
        fail("bowling ball (exchanges between steps): the ball never migrated between steps (no such "
             "migration "
             "was checked)");
    if (comm.size() > 1 && end.owner == firstOwner)
        fail("bowling ball: the ball stayed on rank " + std::to_string(end.owner) +
             " (x = " + std::to_string(end.x.x) + " m): no migration was checked");
    if (comm.rank() == 0)
        std::printf("bowling ball%s: v_f / (5/7 v0) - 1 = %.2e, t* / theory - 1 = %.2e, ranks %d -> %d, %llu "
                    "exchanges, identical to one process: %s\n",
                    betweenSteps ? " (exchanges between steps)" : "", vFinal / (5.0 / 7.0 * kV0) - 1,
                    tStar / tTheory - 1, firstOwner, end.owner,
                    static_cast<unsigned long long>(ranks.exchanges()), identical ? "yes" : "no");
}

// --- the pour

dem::World pourWorld()
{
    dem::World world;
    dem::Material glass;
    glass.name = "glass";
    glass.density = 2500;
    glass.normalStiffness = 500;
    glass.restitution = 0.5;
    glass.friction = 0.4;
    glass.rollingModel = dem::RollingModel::Epsd;
    glass.rollingFrictionDimensionless = 0.05;
    world.addMaterial(glass);
    world.gravity = {0, 0, -kG};
    world.neighbors.skin = 3e-4;
    world.walls.push_back(plane("floor", {0, 0, 0}, {0, 0, 1}));
    world.walls.push_back(plane("west", {0, 0, 0}, {1, 0, 0}));
    world.walls.push_back(plane("east", {0.05, 0, 0}, {-1, 0, 0}));
    world.walls.push_back(plane("south", {0, 0, 0}, {0, 1, 0}));
    world.walls.push_back(plane("north", {0, 0.05, 0}, {0, -1, 0}));
    std::mt19937_64 random(7);
    std::uniform_real_distribution<Real> jitter(-1e-4, 1e-4);
    for (Real z = 0.003; z < 0.04; z += 3.4e-3)
        for (Real y = 0.003; y < 0.048; y += 3.4e-3)
            for (Real x = 0.003; x < 0.048; x += 3.4e-3)
                world.particles.add({x + jitter(random), y + jitter(random), z + jitter(random)},
                                    {0, 0, -0.5}, {}, 1.5e-3, 2500, 0);
    dem::prepare(world);
    return world;
}

/// The whole world of a distributed run, on every rank (gathered on 0, then its rows sent on).
dem::ParticleStore gathered(const dem::World& world, const RankStep& ranks)
{
    std::optional<dem::World> whole = gatherWorld(world, ranks);
    std::vector<double> rows;
    std::uint64_t n[1] = {whole ? whole->particles.size() : 0};
    ranks.comm().sum(n);
    rows.assign(n[0] * 9, -1e300);
    if (whole)
        for (std::size_t i = 0; i < n[0]; ++i)
        {
            const dem::ParticleStore& p = whole->particles;
            const Vec3 q[3] = {p.position[i], p.velocity[i], p.angularVelocity[i]};
            for (int k = 0; k < 3; ++k)
            {
                rows[9 * i + 3 * k] = q[k].x;
                rows[9 * i + 3 * k + 1] = q[k].y;
                rows[9 * i + 3 * k + 2] = q[k].z;
            }
        }
    ranks.comm().max(rows);
    dem::ParticleStore out;
    for (std::size_t i = 0; i < n[0]; ++i)
        out.add({rows[9 * i], rows[9 * i + 1], rows[9 * i + 2]},
                {rows[9 * i + 3], rows[9 * i + 4], rows[9 * i + 5]},
                {rows[9 * i + 6], rows[9 * i + 7], rows[9 * i + 8]}, 1.5e-3, 2500, 0);
    return out;
}

dem::ParticleStore runPour(std::uint64_t steps, int threads, RankStep& ranks)
{
    exec::setThreads(threads);
    dem::World world = pourWorld();
    ranks.distribute(world);
    dem::advance(world, 2e-5, steps);
    return gathered(world, ranks);
}

void pour(const Collective& comm)
{
    constexpr std::uint64_t kSteps = 1500;
    exec::setThreads(1);
    dem::World reference = pourWorld();
    dem::advance(reference, 2e-5, kSteps);
    const dem::ParticleStore& r = reference.particles;

    RankStep first(comm), second(comm), threaded(comm);
    const dem::ParticleStore a = runPour(kSteps, 1, first);
    const dem::ParticleStore b = runPour(kSteps, 1, second);
    const dem::ParticleStore c = runPour(kSteps, 2, threaded);
    exec::setThreads(1);
    if (a.size() != r.size())
        return fail("pour: " + std::to_string(a.size()) + " particles gathered, " + std::to_string(r.size()) +
                    " stepped");
    Real largest = 0, energy = 0, energyReference = 0;
    bool repeatable = true, threadFree = true;
    for (std::size_t i = 0; i < r.size(); ++i) // (gathered by id: the reference's order)
    {
        largest = std::max(largest, length(a.position[i] - r.position[i]));
        energy += 0.5 * r.mass[i] * lengthSquared(a.velocity[i]);
        energyReference += 0.5 * r.mass[i] * lengthSquared(r.velocity[i]);
        repeatable = repeatable && sameBits(a.position[i], b.position[i]) &&
                     sameBits(a.velocity[i], b.velocity[i]) &&
                     sameBits(a.angularVelocity[i], b.angularVelocity[i]);
        threadFree = threadFree && sameBits(a.position[i], c.position[i]) &&
                     sameBits(a.velocity[i], c.velocity[i]) &&
                     sameBits(a.angularVelocity[i], c.angularVelocity[i]);
    }
    const Real energyDifference = std::abs(energy / energyReference - 1);
    if (!repeatable)
        fail("pour: a second run on " + std::to_string(comm.size()) + " ranks gave other bits");
    if (!threadFree)
        fail("pour: 2 threads a rank gave other bits than 1");
    if (!(largest <= 1e-12))
        fail("pour: positions differ from one process's by up to " + std::to_string(largest) +
             " m (bound 1e-12 m)");
    if (!(energyDifference <= 1e-9))
        fail("pour: kinetic energy differs from one process's by " + std::to_string(energyDifference) +
             " relative (bound 1e-9)");
    if (comm.rank() == 0)
        std::printf(
            "pour: %zu particles, %llu exchanges, %llu cuts; largest position difference %.3g m, kinetic "
            "energy %.3g relative; repeatable %s, threads %s\n",
            r.size(), static_cast<unsigned long long>(first.exchanges()),
            static_cast<unsigned long long>(first.cuts()), largest, energyDifference,
            repeatable ? "yes" : "NO", threadFree ? "same" : "DIFFER");
}

// --- load balance

/// A column of 1,440 spheres (6 x 6 x 40, 2.5 mm apart, 13 mm wide and 10 cm tall, its foot 2 cm
/// up) falling 0.15 s onto a floor (the whole column has landed): cut along z at the start, below
/// and above z = 7 cm, its regions must follow the particles down.
dem::World columnWorld()
{
    dem::World world;
    dem::Material glass;
    glass.name = "glass";
    glass.density = 2500;
    glass.normalStiffness = 500;
    glass.restitution = 0.5;
    glass.friction = 0.4;
    world.addMaterial(glass);
    world.gravity = {0, 0, -kG};
    world.walls.push_back(plane("floor", {0, 0, 0}, {0, 0, 1}));
    for (int k = 0; k < 40; ++k)
        for (int j = 0; j < 6; ++j)
            for (int i = 0; i < 6; ++i)
                world.particles.add({2.5e-3 * i, 2.5e-3 * j, 0.02 + 2.5e-3 * k}, {}, {}, 1e-3, 2500, 0);
    return world;
}

/// The largest rank's share of the particles' cost (1 + touching candidates, as the cut weighs
/// them) over the mean share [-].
double costImbalance(const dem::World& world, const RankStep& ranks)
{
    std::vector<std::uint64_t> cost(static_cast<std::size_t>(ranks.comm().size()), 0);
    std::uint64_t mine = ranks.owned();
    const dem::NeighborList& list = world.neighbors;
    for (std::size_t a = 0; a < list.activeFirst.size(); ++a)
        mine += (list.activeFirst[a] < ranks.owned()) + (list.activeSecond[a] < ranks.owned());
    cost[static_cast<std::size_t>(ranks.comm().rank())] = mine;
    ranks.comm().sum(cost);
    std::uint64_t total = 0, largest = 0;
    for (const std::uint64_t c : cost)
    {
        total += c;
        largest = std::max(largest, c);
    }
    return double(largest) * double(cost.size()) / double(total);
}

void loadBalance(const Collective& comm)
{
    if (comm.size() == 1)
        return;
    double imbalance[2] = {0, 0}; // cut every 10th exchange; never cut again
    std::uint64_t cuts = 0;
    for (int k = 0; k < 2; ++k)
    {
        dem::World world = columnWorld();
        RankStep ranks(comm, k == 0 ? 10 : 1000000);
        ranks.distribute(world);
        dem::advance(world, 2e-5, 7500);
        imbalance[k] = costImbalance(world, ranks);
        if (k == 0)
            cuts = ranks.cuts();
    }
    // Bisection keeps each part within the largest particle weight per level of its share
    // (distributed/bisection.h): a particle's weight is at most ~14 here, 2 levels, against a share of
    // ~2,000 or more: 1.5 %; the cost moves on between cuts (10 exchanges): 10 % in all.
    if (!(imbalance[0] <= 1.10))
        fail("load balance: the busiest rank has " + std::to_string(imbalance[0]) +
             " of the mean cost with the regions cut every 10th exchange (bound 1.10)");
    if (!(imbalance[1] > 1.5))
        fail("load balance: the regions never cut again are balanced too (" + std::to_string(imbalance[1]) +
             " of the mean): the column does not test the cuts");
    if (comm.rank() == 0)
        std::printf(
            "load balance: a falling column, busiest rank's cost / mean %.3f with %llu cuts, %.3f with "
            "the first cut kept\n",
            imbalance[0], static_cast<unsigned long long>(cuts), imbalance[1]);
}

} // namespace

int main(int argc, char** argv)
{
    MPI_Init(&argc, &argv);
    int status = 0;
    {
        const MpiCollective comm;
        try
        {
            bowlingBall(comm, false);
            bowlingBall(comm, true);
            pour(comm);
            loadBalance(comm);
        }
        catch (const std::exception& e)
        {
            fail(std::string("exception: ") + e.what());
        }
        for (const std::string& f : failures)
            std::fprintf(stderr, "rank %d: FAIL %s\n", comm.rank(), f.c_str());
        std::uint64_t failed[1] = {failures.size()};
        comm.sum(failed);
        status = failed[0] == 0 ? 0 : 1;
        if (comm.rank() == 0)
            std::printf("%s on %d ranks\n", status == 0 ? "PASS" : "FAIL", comm.size());
    }
    MPI_Finalize();
    return status;
}
