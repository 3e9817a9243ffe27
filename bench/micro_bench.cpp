// Google Benchmark micro-benchmarks (docs/performance.md): the contact law alone, the pair-force
// loop (scalar and four-lane paths), the cross-block sums, and the neighbour search.
//
//   ./build/release/bench/veridem_micro_bench [--benchmark_filter=REGEX]
#include "dem/contact_law.h"
#include "dem/forces.h"
#include "dem/spatial_sort.h"
#include "dem/world.h"

#include <benchmark/benchmark.h>

#include <random>
#include <vector>

using namespace veridem;
using namespace veridem::dem;

namespace
{

Material benchMaterial()
{
    Material m;
    m.name = "glass";
    m.normalStiffness = 1000;
    m.normalDampingRate = 5955.04;
    m.friction = 0.5;
    return m;
}

/// side^3 spheres (r = 1 mm) on a jittered cubic lattice of spacing 1.995 mm: about three touching
/// pairs per sphere, as in the settled bed; random velocities and spins; Morton-sorted.
World latticeWorld(int side)
{
    World world;
    world.addMaterial(benchMaterial());
    world.neighbors.skin = 0.5e-3;
    std::mt19937_64 random(7);
    std::uniform_real_distribution<Real> jitter(-0.01e-3, 0.01e-3), speed(-0.01, 0.01), spin(-10, 10);
    const Real spacing = 1.995e-3;
    for (int z = 0; z < side; ++z)
        for (int y = 0; y < side; ++y)
            for (int x = 0; x < side; ++x)
                world.particles.add({x * spacing + jitter(random), y * spacing + jitter(random),
                                     z * spacing + jitter(random)},
                                    {speed(random), speed(random), speed(random)},
                                    {spin(random), spin(random), spin(random)}, 1e-3, 2500, 0);
    sortParticlesSpatially(world);
    prepare(world);
    return world;
}

/// The contact law alone on 1024 contacts held in L1 (no gathering of particle data).
void contactLaw(benchmark::State& state)
{
    std::vector<Material> materials{benchMaterial()};
    PairTable table;
    table.build(materials);
    const PairParams& params = table(0, 0);
    std::mt19937_64 random(3);
    std::uniform_real_distribution<Real> unit(-1, 1);
    std::vector<ContactInput> inputs(1024);
    std::vector<ContactHistory> histories(1024);
    for (auto& in : inputs)
    {
        in.normal = normalizedOrZero(Vec3{unit(random), unit(random), unit(random)});
        in.overlap = 1e-6 * (1.5 + unit(random));
        in.relativeVelocity = 0.01 * Vec3{unit(random), unit(random), unit(random)};
        in.effectiveMass = 5e-6;
        in.effectiveRadius = 5e-4;
    }
    for (auto& h : histories)
        h.tangentialSpring = 1e-7 * Vec3{unit(random), unit(random), unit(random)};
    for (auto _ : state)
        for (std::size_t k = 0; k < inputs.size(); ++k)
        {
            ContactHistory h = histories[k];
            benchmark::DoNotOptimize(evaluateContact(params, inputs[k], h, 1e-5));
        }
    state.SetItemsProcessed(state.iterations() * static_cast<std::int64_t>(inputs.size()));
}
BENCHMARK(contactLaw);

/// Stage 3 for pairs: every slot of a lattice bed (about half of them touching).
void pairForces(benchmark::State& state, bool batched)
{
    World world = latticeWorld(static_cast<int>(state.range(0)));
    world.exec.batchedContactKernel = batched;
    for (auto _ : state)
        computePairForces(world, 1e-5);
    state.SetItemsProcessed(state.iterations() * static_cast<std::int64_t>(world.particles.size()));
    state.counters["slots/particle"] =
        static_cast<double>(world.neighbors.size()) / static_cast<double>(world.particles.size());
}
BENCHMARK_CAPTURE(pairForces, scalar, false)->Arg(16)->Arg(28);
BENCHMARK_CAPTURE(pairForces, batched, true)->Arg(16)->Arg(28);

/// Stage 4: the per-particle sums of the cross-block contacts in a fixed order.
void crossBlockSums(benchmark::State& state)
{
    World world = latticeWorld(static_cast<int>(state.range(0)));
    computePairForces(world, 1e-5);
    for (auto _ : state)
        addCrossBlockForces(world, 0, world.particles.size());
    state.SetItemsProcessed(state.iterations() * static_cast<std::int64_t>(world.particles.size()));
}
BENCHMARK(crossBlockSums)->Arg(16)->Arg(28);

/// Neighbour search: a full rebuild of the Verlet list with history merge.
void neighbourRebuild(benchmark::State& state)
{
    World world = latticeWorld(static_cast<int>(state.range(0)));
    for (auto _ : state)
        world.neighbors.rebuild(world.particles, world.pairHistory);
    state.SetItemsProcessed(state.iterations() * static_cast<std::int64_t>(world.particles.size()));
}
BENCHMARK(neighbourRebuild)->Arg(16)->Arg(28);

} // namespace

BENCHMARK_MAIN();
