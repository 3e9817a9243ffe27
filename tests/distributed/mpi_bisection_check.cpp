// The domain decomposition is the same bits however the particles are spread over MPI ranks
// (distributed/bisection.h): run under `mpirun -np N` (CTest: N = 1, 2, 4), every rank holds a share of
// one reproducible cloud (every N-th particle, then contiguous ranges), cuts it over MPI into
// 1-16 parts, and compares every cut, region and cost bit for bit with the decomposition of the
// whole cloud in one process. Exit 0 when every rank agrees, 1 otherwise.
#include "distributed/bisection.h"
#include "distributed/mpi_collective.h"
#include "point_clouds.h"

#include <cstdio>
#include <cstring>

using namespace veridem;
using namespace veridem::distributed;

namespace
{

bool sameBits(Real a, Real b)
{
    return std::memcmp(&a, &b, sizeof a) == 0;
}

bool sameBox(const Box& a, const Box& b)
{
    for (int k = 0; k < 3; ++k)
        if (!sameBits(component(a.lo, k), component(b.lo, k)) ||
            !sameBits(component(a.hi, k), component(b.hi, k)))
            return false;
    return true;
}

/// Empty if equal, else what differs.
const char* difference(const Decomposition& a, const Decomposition& b)
{
    if (a.nodes.size() != b.nodes.size() || a.region.size() != b.region.size())
        return "tree size";
    for (std::size_t k = 0; k < a.nodes.size(); ++k)
        if (a.nodes[k].axis != b.nodes[k].axis || !sameBits(a.nodes[k].cut, b.nodes[k].cut) ||
            a.nodes[k].below != b.nodes[k].below || a.nodes[k].above != b.nodes[k].above)
            return "a cut";
    for (std::size_t p = 0; p < a.region.size(); ++p)
        if (!sameBox(a.region[p], b.region[p]) || a.cost[p] != b.cost[p])
            return "a region or a cost";
    if (!sameBox(a.bounds, b.bounds))
        return "the bounds";
    return "";
}

} // namespace

int main(int argc, char** argv)
{
    MPI_Init(&argc, &argv);
    int failures = 0;
    {
        const MpiCollective comm;
        const auto cloud = clouds::makeCloud(30000, 7);
        for (int split = 0; split < 2; ++split)
        {
            clouds::Cloud mine;
            const std::size_t n = cloud.position.size(), ranks = std::size_t(comm.size()),
                              me = std::size_t(comm.rank());
            for (std::size_t i = 0; i < n; ++i)
                if (split == 0 ? i % ranks == me : i * ranks / n == me)
                {
                    mine.position.push_back(cloud.position[i]);
                    mine.weight.push_back(cloud.weight[i]);
                }
            for (int parts : {1, 2, 3, 4, 7, 16})
            {
                const Decomposition whole = bisect(cloud.position, cloud.weight, parts, SerialCollective{});
                const Decomposition shared = bisect(mine.position, mine.weight, parts, comm);
                const char* diff = difference(whole, shared);
                if (*diff)
                {
                    std::fprintf(stderr, "rank %d of %d, %s split, %d parts: %s differs from one process\n",
                                 comm.rank(), comm.size(), split == 0 ? "interleaved" : "contiguous", parts,
                                 diff);
                    ++failures;
                }
            }
        }
        int all = failures;
        MPI_Allreduce(MPI_IN_PLACE, &all, 1, MPI_INT, MPI_SUM, MPI_COMM_WORLD);
        failures = all;
        if (comm.rank() == 0)
            std::printf("%s: decomposition on %d rank(s) %s the one-process one (2 splits x 6 part counts)\n",
                        failures ? "FAIL" : "PASS", comm.size(),
                        failures ? "differs from" : "is bit-identical to");
    }
    MPI_Finalize();
    return failures ? 1 : 0;
}
