// Google Benchmark micro-benchmarks (docs/performance.md): the contact law alone, the pair-force
// loop (scalar and four-lane paths), the cross-block sums, the neighbour search, and the wall
// stage per contact on a triangle-mesh floor against an analytic plane and on a meshed drum against
// the analytic cylinder.
//
//   ./build/release/bench/veridem_micro_bench [--benchmark_filter=REGEX]
#include "dem/contact_law.h"
#include "dem/forces.h"
#include "dem/spatial_sort.h"
#include "dem/world.h"

#include <benchmark/benchmark.h>

#include <cmath>
#include <ctime>
#include <memory>
#include <random>
#include <string>
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

/// A full rebuild of the Verlet list on 20,000 spheres placed at random (overlaps allowed) at a
/// solid fraction of 0.2: all of radius 0.1 mm (Arg 1), or with the same total count a mixture
/// of size ratio 10 in which the large spheres (r = 1 mm) hold half the solid volume (Arg 10:
/// 20 large, 19,980 small). Time per sphere of each: the mixture should cost about what the
/// monodisperse set costs (dem/pair_search.h).
void neighbourRebuildSizeRatio(benchmark::State& state)
{
    const int ratio = static_cast<int>(state.range(0));
    const std::size_t n = 20000, large = ratio > 1 ? 20 : 0;
    const Real small = 0.1e-3, big = small * ratio;
    const Real volume =
        (Real(n - large) * small * small * small + Real(large) * big * big * big) * 4.18879 / 0.2;
    const Real side = std::cbrt(volume);
    ParticleStore p;
    std::mt19937 rng(3);
    std::uniform_real_distribution<double> x(0, side);
    for (std::size_t i = 0; i < n; ++i)
        p.add({x(rng), x(rng), x(rng)}, {}, {}, i < large ? big : small, 2500, 0);
    NeighborList list;
    ContactHistoryStore history{false};
    list.skin = 0.2 * small;
    for (auto _ : state)
        list.rebuild(p, history);
    state.SetItemsProcessed(state.iterations() * static_cast<std::int64_t>(n));
    state.counters["pairs/sphere"] = static_cast<double>(list.size()) / static_cast<double>(n);
}
BENCHMARK(neighbourRebuildSizeRatio)->Arg(1)->Arg(10);

/// side^2 spheres (r = 1 mm, at rest, 2.5 mm apart: no pair contacts) resting on the floor z = 0
/// with the overlap of their weight. The floor is an analytic plane or (mesh) a flat square of
/// triangles, two per 3.1 mm cell, so that the spheres sit on faces, edges and vertices alike.
World floorWorld(int side, bool mesh)
{
    World world;
    world.addMaterial(benchMaterial());
    world.neighbors.skin = 0.5e-3;
    world.gravity = {0, 0, -9.81};
    const Real spacing = 2.5e-3, radius = 1e-3, density = 2500;
    const Real overlap = density * 4.0 / 3.0 * 3.14159265358979 * radius * radius * radius * 9.81 / 1000;
    for (int y = 0; y < side; ++y)
        for (int x = 0; x < side; ++x)
            world.particles.add({x * spacing, y * spacing, radius - overlap}, {}, {}, radius, density, 0);
    Wall floor;
    floor.name = "floor";
    if (!mesh)
        floor.shape = PlaneShape{{0, 0, 0}, {0, 0, 1}};
    else
    {
        const Real cell = 3.1e-3, start = -3e-3;
        const int cells = static_cast<int>((side * spacing - 2 * start) / cell) + 1;
        // (Each corner from its grid indices, so that the cells' shared corners weld: one surface.)
        const auto at = [&](int i, int j) { return Vec3{start + i * cell, start + j * cell, 0}; };
        std::vector<Vec3> corners;
        for (int j = 0; j < cells; ++j)
            for (int i = 0; i < cells; ++i)
                corners.insert(corners.end(), {at(i, j), at(i + 1, j), at(i + 1, j + 1), at(i, j),
                                               at(i + 1, j + 1), at(i, j + 1)});
        MeshReport report; // (an open boundary: expected for a floor)
        MeshShape shape;
        shape.mesh = std::make_shared<const TriangleMesh>(buildTriangleMesh(corners, "floor", report));
        shape.farthestVertex = shape.mesh->farthestVertex(shape.pivot);
        floor.shape = std::move(shape);
    }
    world.walls.push_back(std::move(floor));
    prepare(world);
    return world;
}

/// This thread's CPU time [s]: a process sharing the cores with others is not charged for the time
/// it waits for one, so the ratio of two stages stays readable on a loaded machine.
double threadSeconds()
{
    timespec t{};
    clock_gettime(CLOCK_THREAD_CPUTIME_ID, &t);
    return static_cast<double>(t.tv_sec) + 1e-9 * static_cast<double>(t.tv_nsec);
}

/// Spheres (r = 1 mm) resting with the overlap of their weight inside a drum of radius 45 mm and
/// length 0.2 m about +y: the analytic cylinder, or (mesh) its side as 96 segments around (the
/// geometry of scripts/make_meshes.py drum) and 68 rings of 2.9 mm, two triangles per quad. One
/// sphere on each quad of the lowest 25 segments (the bottom +-47 degrees), at a quarter of its
/// width from its edge at the lower angle and in the middle of its ring; for the mesh it rests on
/// the quad's plane (the chord, R cos(pi/96) from the axis). The fold to the next quad (3.75
/// degrees) is 0.74 mm from the centre's foot, inside the disc of radius sqrt((r + skin)^2 - h^2)
/// = 1.1 mm that the contact can reach before the next rebuild: no candidate is flat.
World drumWorld(bool mesh)
{
    World world;
    world.addMaterial(benchMaterial());
    world.neighbors.skin = 0.5e-3;
    world.gravity = {0, 0, -9.81};
    const Real pi = 3.14159265358979323846, drumRadius = 0.045, length = 0.2, radius = 1e-3, density = 2500;
    const int segments = 96, rings = 68;
    const Real overlap = density * 4.0 / 3.0 * pi * radius * radius * radius * 9.81 / 1000;
    const auto angle = [&](Real q) { return 2 * pi * q / segments; };
    for (int k = 0; k < rings; ++k)
        for (int q = segments * 3 / 4 - 12; q <= segments * 3 / 4 + 12; ++q) // about the bottom (-z)
        {
            const Real a = angle(q + 0.25), y = (k + 0.5) * length / rings, lift = radius - overlap;
            Vec3 centre{(drumRadius - lift) * std::cos(a), y, (drumRadius - lift) * std::sin(a)};
            if (mesh) // the foot on the quad's chord plane (normal at the quad's middle angle), lifted along
                      // it
            {
                const Real middle = angle(q + 0.5), chord = drumRadius * std::cos(pi / segments);
                const Real foot = chord / std::cos(a - middle);
                centre = Vec3{foot * std::cos(a), y, foot * std::sin(a)} -
                         lift * Vec3{std::cos(middle), 0, std::sin(middle)};
            }
            world.particles.add(centre, {}, {}, radius, density, 0);
        }
    Wall drum;
    drum.name = "drum";
    if (!mesh)
        drum.shape = CylinderShape{{0, 0, 0}, {0, 1, 0}, drumRadius, length, true};
    else
    {
        const auto at = [&](int q, int k) {
            return Vec3{drumRadius * std::cos(angle(q)), k * length / rings, drumRadius * std::sin(angle(q))};
        };
        std::vector<Vec3> corners;
        for (int k = 0; k < rings; ++k)
            for (int q = 0; q < segments; ++q)
            {
                const Vec3 a = at(q, k), b = at((q + 1) % segments, k), c = at((q + 1) % segments, k + 1),
                           d = at(q, k + 1);
                corners.insert(corners.end(), {a, b, c, a, c, d});
            }
        MeshReport report; // (open ends: expected for the drum's side alone)
        MeshShape shape;
        shape.mesh = std::make_shared<const TriangleMesh>(buildTriangleMesh(corners, "drum", report));
        shape.farthestVertex = shape.mesh->farthestVertex(shape.pivot);
        drum.shape = std::move(shape);
    }
    world.walls.push_back(std::move(drum));
    prepare(world);
    return world;
}

/// Stage 4b (computeWallForces) on the same resting spheres on an analytic wall (`analytic`) and
/// on its mesh (`meshed`), timed back to back in each iteration (thread CPU time) so that both
/// see the same state of the machine: ns per touching contact of each and their ratio.
void wallContactRatio(benchmark::State& state, World& analytic, World& meshed, const char* analyticName)
{
    const std::size_t n = analytic.particles.size();
    double analyticSeconds = 0, meshSeconds = 0;
    std::size_t analyticContacts = 0, meshContacts = 0;
    for (auto _ : state)
    {
        const double t0 = threadSeconds();
        analyticContacts += computeWallForces(analytic, 1e-5, 0, n).touching;
        const double t1 = threadSeconds();
        meshContacts += computeWallForces(meshed, 1e-5, 0, n).touching;
        const double t2 = threadSeconds();
        analyticSeconds += t1 - t0;
        meshSeconds += t2 - t1;
        state.SetIterationTime(t2 - t0);
    }
    const double analyticPerContact =
        analyticSeconds / static_cast<double>(std::max<std::size_t>(analyticContacts, 1));
    const double meshPerContact = meshSeconds / static_cast<double>(std::max<std::size_t>(meshContacts, 1));
    state.counters[std::string(analyticName) + "_ns/contact"] = 1e9 * analyticPerContact;
    state.counters["mesh_ns/contact"] = 1e9 * meshPerContact;
    state.counters["mesh/" + std::string(analyticName)] = meshPerContact / analyticPerContact;
    state.counters["contacts/sphere"] = static_cast<double>(meshContacts) /
                                        static_cast<double>(n * static_cast<std::size_t>(state.iterations()));
}

/// The flat floor: 4096 spheres on the plane and on the meshed floor (the target: mesh/plane <= 2;
/// every candidate is flat, docs/performance.md).
void wallContactMeshOverPlane(benchmark::State& state)
{
    World plane = floorWorld(64, false), mesh = floorWorld(64, true);
    wallContactRatio(state, plane, mesh, "plane");
}
BENCHMARK(wallContactMeshOverPlane)->UseManualTime();

/// The curved drum: 1700 spheres on the analytic cylinder and on its 96-segment mesh (no flat
/// candidate: the general mesh path).
void wallContactCurvedMeshOverCylinder(benchmark::State& state)
{
    World cylinder = drumWorld(false), mesh = drumWorld(true);
    wallContactRatio(state, cylinder, mesh, "cylinder");
}
BENCHMARK(wallContactCurvedMeshOverCylinder)->UseManualTime();

} // namespace

BENCHMARK_MAIN();
