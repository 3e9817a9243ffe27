// The particle exchanges of distributed/halo.h under `mpirun -np N` (CTest: N = 1, 2, 4). Every rank
// starts with every N-th particle of one reproducible cloud (radii 0.9-1.1 mm, all the store's
// arrays set from the particle's id), decomposes over MPI and exchanges. Checked on each rank
// against the whole cloud held in one process:
//   - it owns exactly the particles whose position its region holds, each with its row unchanged
//     bit for bit (migration moves every array);
//   - its ghosts are exactly the other ranks' particles within r_i + halo of its region, each an
//     exact copy of its owner's row;
//   - after every owner moves its particles (a new position, velocity and angular velocity from
//     the id), refreshGhosts gives every ghost its owner's new motion bit for bit;
//   - after every rank writes a force and torque from (id, rank) on its ghosts, returnGhostForces
//     adds to each owner exactly the sum over the ranks holding its ghost (small integers:
//     the sums are exact in any order), and zeroes the ghosts' sums.
// Exit 0 when every rank passes.
#include "distributed/halo.h"
#include "distributed/mpi_collective.h"
#include "point_clouds.h"

#include <cstdio>
#include <cstring>
#include <map>
#include <string>

using namespace veridem;
using namespace veridem::distributed;

namespace
{

constexpr Real kHalo = 1.5e-3; // [m] r_max + skin

bool same(const Vec3& a, const Vec3& b)
{
    return std::memcmp(&a, &b, sizeof a) == 0;
}

bool sameBits(Real a, Real b)
{
    return std::memcmp(&a, &b, sizeof a) == 0;
}

/// Particle `id` of the cloud with every array set from its id.
void addParticle(dem::ParticleStore& p, const Vec3& x, std::uint32_t id)
{
    const Real r = 0.9e-3 + 0.2e-3 * Real(id % 97) / 96;
    p.add(x, {0.01 * Real(id % 5), -0.02, 0.003 * Real(id % 3)}, {Real(id % 7), 1, -2}, r,
          2500 + Real(id % 11), id % 3);
    p.id.back() = id;
    p.fixed.back() = static_cast<std::uint8_t>(id % 13 == 0);
}

Vec3 moved(const Vec3& x, std::uint32_t id)
{
    return x + Vec3{1e-5 * Real(id % 17), -1e-5, 2e-6 * Real(id % 5)};
}

/// The failure messages of this rank (empty: passed).
std::vector<std::string> check(const MpiCollective& comm)
{
    std::vector<std::string> failures;
    const auto fail = [&](const std::string& m)
    {
        if (failures.size() < 10)
            failures.push_back(m);
    };
    const auto cloud = clouds::makeCloud(20000, 11);
    const std::size_t n = cloud.position.size();
    dem::ParticleStore whole, mine;
    for (std::size_t i = 0; i < n; ++i)
    {
        addParticle(whole, cloud.position[i], std::uint32_t(i));
        if (int(i % std::size_t(comm.size())) == comm.rank())
            addParticle(mine, cloud.position[i], std::uint32_t(i));
    }
    std::vector<std::uint32_t> weight;
    for (std::size_t i = 0; i < mine.size(); ++i)
        weight.push_back(cloud.weight[mine.id[i]]);
    const Decomposition d = bisect(mine.position, weight, comm.size(), comm);
    const Halo h = exchangeParticles(mine, mine.size(), d, kHalo, comm);
    const int me = comm.rank();

    // Owned and ghost sets against the whole cloud.
    std::map<std::uint32_t, std::size_t> owned, ghost;
    for (std::size_t k = 0; k < mine.size(); ++k)
        (k < h.owned ? owned : ghost)[mine.id[k]] = k;
    if (owned.size() + ghost.size() != mine.size())
        fail("a particle is held twice");
    std::size_t expectOwned = 0, expectGhosts = 0;
    for (std::size_t i = 0; i < n; ++i)
    {
        const auto id = std::uint32_t(i);
        const bool isMine = d.owner(whole.position[i]) == me;
        const bool isGhost = !isMine && distanceSquared(d.region[me], whole.position[i]) <
                                            (whole.radius[i] + kHalo) * (whole.radius[i] + kHalo);
        expectOwned += isMine;
        expectGhosts += isGhost;
        const auto& set = isMine ? owned : ghost;
        if (!isMine && !isGhost)
        {
            if (owned.count(id) || ghost.count(id))
                fail("particle " + std::to_string(id) + " is held but not needed");
            continue;
        }
        const auto at = set.find(id);
        if (at == set.end())
        {
            fail("particle " + std::to_string(id) + (isMine ? " is not owned" : " has no ghost"));
            continue;
        }
        const std::size_t k = at->second;
        if (!same(mine.position[k], whole.position[i]) || !same(mine.velocity[k], whole.velocity[i]) ||
            !same(mine.angularVelocity[k], whole.angularVelocity[i]) ||
            !sameBits(mine.radius[k], whole.radius[i]) || !sameBits(mine.mass[k], whole.mass[i]) ||
            !sameBits(mine.invMass[k], whole.invMass[i]) ||
            !sameBits(mine.invInertia[k], whole.invInertia[i]) || mine.material[k] != whole.material[i] ||
            mine.fixed[k] != whole.fixed[i] || !same(mine.positionRadius[k], whole.positionRadius[i]))
            fail("particle " + std::to_string(id) + ": its row changed in the exchange");
    }
    if (owned.size() != expectOwned || ghost.size() != expectGhosts)
        fail("owned " + std::to_string(owned.size()) + " (expected " + std::to_string(expectOwned) +
             "), ghosts " + std::to_string(ghost.size()) + " (expected " + std::to_string(expectGhosts) +
             ")");

    // Motion: owners move, ghosts follow.
    for (std::size_t k = 0; k < h.owned; ++k)
    {
        mine.position[k] = moved(mine.position[k], mine.id[k]);
        mine.velocity[k] = mine.velocity[k] * 2;
        mine.angularVelocity[k] = mine.angularVelocity[k] * -1;
    }
    refreshGhosts(mine, h, comm);
    for (std::size_t k = h.owned; k < mine.size(); ++k)
    {
        const std::uint32_t i = mine.id[k];
        if (!same(mine.position[k], moved(whole.position[i], i)) ||
            !same(mine.velocity[k], whole.velocity[i] * 2) ||
            !same(mine.angularVelocity[k], whole.angularVelocity[i] * -1) ||
            !same(mine.positionRadius[k], Vec3(mine.positionRadiusRow(k))) ||
            !sameBits(mine.positionRadius[k].pad, mine.radius[k]))
            fail("ghost " + std::to_string(i) + ": its motion is not its owner's");
    }

    // Forces: each ghost's share goes back to its owner and is added there.
    for (std::size_t k = 0; k < mine.size(); ++k)
    {
        const bool isGhost = k >= h.owned;
        const Real f = isGhost ? Real(1 + me) : Real(100);
        mine.force[k] = Vec3{f, 2 * f, Real(mine.id[k] % 5)};
        mine.torque[k] = Vec3{-f, 0, isGhost ? 1.0 : 0.0};
    }
    returnGhostForces(mine, h, comm);
    // Expected: 100 + the sum of (1 + rank) over the ranks holding a ghost of the particle.
    for (std::size_t k = 0; k < h.owned; ++k)
    {
        const std::uint32_t i = mine.id[k];
        Real ranksSum = 0, holders = 0;
        d.forEachPartNear(whole.position[i], whole.radius[i] + kHalo,
                          [&](int part)
                          {
                              if (part != me)
                              {
                                  ranksSum += 1 + part;
                                  holders += 1;
                              }
                          });
        const Real f = 100 + ranksSum;
        const Vec3 expectF{f, 2 * f, Real(i % 5) * (1 + holders)}, expectT{-f, 0, holders};
        if (!same(Vec3(mine.force[k]), expectF) || !same(Vec3(mine.torque[k]), expectT))
            fail("particle " + std::to_string(i) + ": the ghosts' forces did not add up on its owner");
    }
    for (std::size_t k = h.owned; k < mine.size(); ++k)
        if (!same(Vec3(mine.force[k]), Vec3{}) || !same(Vec3(mine.torque[k]), Vec3{}))
            fail("a ghost's sums were not zeroed after they went back");

    std::printf("rank %d of %d: %zu owned, %zu ghosts from %d neighbour(s), %llu bytes sent\n", me,
                comm.size(), h.owned, h.ghosts(), h.neighbours(),
                static_cast<unsigned long long>(h.bytesSent));
    return failures;
}

} // namespace

int main(int argc, char** argv)
{
    MPI_Init(&argc, &argv);
    int failed = 0;
    {
        const MpiCollective comm;
        const std::vector<std::string> failures = check(comm);
        for (const std::string& f : failures)
            std::fprintf(stderr, "rank %d: %s\n", comm.rank(), f.c_str());
        failed = failures.empty() ? 0 : 1;
        MPI_Allreduce(MPI_IN_PLACE, &failed, 1, MPI_INT, MPI_SUM, MPI_COMM_WORLD);
        if (comm.rank() == 0)
            std::printf("%s: particle exchanges on %d rank(s) (migration, ghosts, motion, forces)\n",
                        failed ? "FAIL" : "PASS", comm.size());
    }
    MPI_Finalize();
    return failed ? 1 : 0;
}
