// What a distributed step exchanges (docs/performance.md, "Communication"): a dense bed of N
// spheres (r 0.9-1.1 mm on a cubic lattice of pitch 2.2 mm with a jitter of 0.1 mm, in a cube,
// or 50 x 50 a layer with --flat), cut by recursive bisection (distributed/bisection.h, weight 1) and
// exchanged as distributed/halo.h does, with halo = r_max + skin, skin 0.2 mm (the bed's).
//
//   mpirun -np P veridem_halo_bench [--particles N] [--steps S] [--flat]
//     each rank holds every P-th sphere, decomposes, exchanges (migration and ghosts, timed) and
//     then times S steps' exchanges (refreshGhosts and returnGhostForces, MPI_Wtime, after a
//     barrier); prints per rank its owned spheres, ghosts, neighbour ranks, bytes sent a step and
//     the exchange time a step (median of S), and the largest of each over the ranks.
//   veridem_halo_bench --parts P [--particles N] [--flat]
//     one process, no exchange: the decomposition into P parts and, per part, the ghosts it
//     would receive and its neighbour parts (the model's inputs for any P).
#include "bench_args.h"
#include "distributed/exchange_plan.h"
#include "distributed/halo.h"
#include "distributed/mpi_collective.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <random>
#include <set>
#include <string>
#include <vector>

using namespace veridem;

namespace
{

constexpr Real kPitch = 2.2e-3, kJitter = 1e-4; // [m]
constexpr Real kHalo = 1.1e-3 + 2e-4;           // [m] r_max + skin

/// Sphere i of the bed (every rank makes the same one: fixed generator, seeded by i).
void addSphere(dem::ParticleStore& p, std::size_t i, std::size_t side, std::size_t layer)
{
    std::mt19937_64 g(i * 0x9E3779B97F4A7C15ull + 1);
    const auto unit = [&] { return static_cast<Real>(g() >> 11) * 0x1.0p-53; };
    const std::size_t ix = i % side, iy = (i / side) % layer, iz = i / (side * layer);
    const Vec3 x{kPitch * Real(ix) + kJitter * (2 * unit() - 1),
                 kPitch * Real(iy) + kJitter * (2 * unit() - 1),
                 kPitch * Real(iz) + kJitter * (2 * unit() - 1)};
    p.add(x, {}, {}, 0.9e-3 + 0.2e-3 * unit(), 2500, 0);
    p.id.back() = static_cast<std::uint32_t>(i);
}

struct Bed
{
    std::size_t side = 0, layer = 0; // spheres along x, along y
};

Bed bedShape(std::size_t n, bool flat)
{
    if (flat)
        return {50, 50};
    const auto side = static_cast<std::size_t>(std::ceil(std::cbrt(double(n))));
    return {side, side};
}

int partsMode(std::size_t n, int parts, bool flat)
{
    const Bed bed = bedShape(n, flat);
    dem::ParticleStore p;
    p.reserve(n);
    for (std::size_t i = 0; i < n; ++i)
        addSphere(p, i, bed.side, bed.layer);
    const std::vector<std::uint32_t> weight(n, 1);
    const distributed::Decomposition d =
        distributed::bisect(p.position, weight, parts, distributed::SerialCollective{});
    std::vector<std::size_t> owned(parts, 0), ghosts(parts, 0);
    std::vector<std::set<int>> neighbours(parts);
    for (std::size_t i = 0; i < n; ++i)
    {
        const int o = d.owner(p.position[i]);
        ++owned[o];
        d.forEachPartNear(p.position[i], p.radius[i] + kHalo,
                          [&](int q)
                          {
                              if (q == o)
                                  return;
                              ++ghosts[q];
                              neighbours[q].insert(o);
                          });
    }
    double ratioSum = 0, ratioMax = 0, neighbourSum = 0, neighbourMax = 0;
    for (int q = 0; q < parts; ++q)
    {
        const double r = double(ghosts[q]) / double(owned[q]);
        ratioSum += r;
        ratioMax = std::max(ratioMax, r);
        neighbourSum += double(neighbours[q].size());
        neighbourMax = std::max(neighbourMax, double(neighbours[q].size()));
    }
    std::printf(
        "bed of %zu spheres (%s), %d parts: %.0f spheres a part; ghosts / owned %.4f mean, %.4f max; "
        "neighbour parts %.1f mean, %.0f max; a step's exchange %.0f B a part (mean: 72 B a ghost in, "
        "48 B a ghost back)\n",
        n, flat ? "flat, 50 x 50 a layer" : "cube", parts, double(n) / parts, ratioSum / parts, ratioMax,
        neighbourSum / parts, neighbourMax, (ratioSum / parts) * double(n) / parts * 120);
    return 0;
}

int mpiMode(std::size_t n, int steps, bool flat)
{
    const distributed::MpiCollective comm;
    const int me = comm.rank(), ranks = comm.size();
    const Bed bed = bedShape(n, flat);
    dem::ParticleStore p;
    p.reserve(n / std::size_t(ranks) + 1);
    for (std::size_t i = std::size_t(me); i < n; i += std::size_t(ranks))
        addSphere(p, i, bed.side, bed.layer);
    const std::vector<std::uint32_t> weight(p.size(), 1);
    MPI_Barrier(MPI_COMM_WORLD);
    double t0 = MPI_Wtime();
    const distributed::Decomposition d = distributed::bisect(p.position, weight, ranks, comm);
    const double cut = MPI_Wtime() - t0;
    MPI_Barrier(MPI_COMM_WORLD);
    t0 = MPI_Wtime();
    const distributed::Halo h = distributed::exchangeParticles(p, p.size(), d, kHalo, comm);
    const double exchange = MPI_Wtime() - t0;
    std::vector<double> times;
    for (int s = 0; s < steps + 10; ++s)
    {
        MPI_Barrier(MPI_COMM_WORLD);
        t0 = MPI_Wtime();
        distributed::refreshGhosts(p, h, comm);
        distributed::returnGhostForces(p, h, comm);
        if (s >= 10) // (the first 10: warm-up)
            times.push_back(MPI_Wtime() - t0);
    }
    std::sort(times.begin(), times.end());
    const double median = times.empty() ? 0 : times[times.size() / 2];
    std::size_t sentGhosts = 0;
    for (const auto& s : h.sent)
        sentGhosts += s.size();
    const double stepBytes = double(sentGhosts) * double(distributed::kMotionBytes) +
                             double(h.ghosts()) * distributed::kForceBytes;
    double mine[4] = {double(h.ghosts()) / double(h.owned), stepBytes, median, double(h.neighbours())};
    std::printf(
        "rank %d of %d: %zu owned, %zu ghosts (%.4f of owned) from %d neighbour(s); decomposition %.3f s, "
        "migration and ghosts %.3f s (%llu B sent); a step's exchanges %.0f B sent, %.1f us (median of %d)\n",
        me, ranks, h.owned, h.ghosts(), mine[0], h.neighbours(), cut, exchange,
        static_cast<unsigned long long>(h.bytesSent), stepBytes, median * 1e6, steps);
    std::fflush(stdout);
    MPI_Allreduce(MPI_IN_PLACE, mine, 4, MPI_DOUBLE, MPI_MAX, MPI_COMM_WORLD);
    if (me == 0)
        std::printf(
            "largest over %d ranks: ghosts / owned %.4f, %.0f B sent a step, exchanges %.1f us a step, "
            "%.0f neighbours\n",
            ranks, mine[0], mine[1], mine[2] * 1e6, mine[3]);
    return 0;
}

} // namespace

int main(int argc, char** argv)
{
    std::size_t n = 1000000;
    int steps = 200, parts = 0;
    bool flat = false;
    try
    {
        for (int a = 1; a < argc; ++a)
        {
            const std::string arg = argv[a];
            const auto value = [&]
            {
                if (a + 1 >= argc)
                    throw std::runtime_error(arg + ": expected a value");
                return std::string(argv[++a]);
            };
            if (arg == "--particles")
                n = std::size_t(bench::wholeNumber(arg, value(), 1, 100000000));
            else if (arg == "--steps")
                steps = int(bench::wholeNumber(arg, value(), 1, 1000000));
            else if (arg == "--parts")
                parts = int(bench::wholeNumber(arg, value(), 1, 65536));
            else if (arg == "--flat")
                flat = true;
            else
                throw std::runtime_error(arg + ": unknown option (usage: [mpirun -np P] veridem_halo_bench "
                                               "[--particles N] [--steps S] [--flat] [--parts P])");
        }
    }
    catch (const std::exception& e)
    {
        std::fprintf(stderr, "veridem_halo_bench: %s\n", e.what());
        return 2;
    }
    if (parts > 0)
        return partsMode(n, parts, flat);
    MPI_Init(&argc, &argv);
    const int code = mpiMode(n, steps, flat);
    MPI_Finalize();
    return code;
}
