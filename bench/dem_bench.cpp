// veridem_bench: the reference many-sphere benchmark of issue 5 (docs/performance.md).
// (Above 500 lines: one driver for every benchmark scene, whose options, scene builders and report
// are read together when comparing runs; the scenes share the bed's material and walls.)
//
//   veridem_bench [--scene bed|gas|turntable|drum] [--file XYZ] [--tile N] [--steps S] [--threads T]
//                 [--warmup W] [--profile] [--repeat R] [--no-sort] [--no-fusion] [--spin-ns NS]
//                 [--mesh STL] [--omega W] [--fill N] [--write-xyz OUT]
//   veridem_bench --core-probe
//
// bed / gas: spheres read from an .xyz file (x y z per line, metres), radius 1 mm, density 2500,
//   linear spring-dashpot kn = 1000 N/m, kt = 2/7 kn, gamma_n = 5955.04 1/s (e = 0.5 for a pair),
//   tangential damping 2/7 of normal, mu = 0.5, no rolling friction, box walls x = 0, L; y = 0, L;
//   floor z = 0 (same law), gravity 9.81, dt = 1e-5 s, skin 0.5 mm. --tile N repeats the bed
//   N x N times side by side (box N L x N L), e.g. --tile 7 gives 980,000 spheres.
//   --periodic: the bed periodic in x and y over the box instead of the four side walls (the pairs
//   through the faces in dem/periodic.h's list; their count is printed).
// turntable: one steel ball rolling on a turntable (the paper's Test 1 set-up with rolling
//   friction), the cost of long single-particle verification runs.
// drum: the bed's spheres and law inside a closed triangle-mesh drum (--mesh STL, from
//   scripts/make_meshes.py drum: a cylinder about +y from the origin) turning at --omega rad/s
//   about +y through the origin (default 4; 0: at rest), no other walls. The spheres come from
//   --file, or with --fill N from a jittered cubic lattice (spacing 2.2 mm) filling the drum from
//   the bottom. --write-xyz OUT writes the centres after the run (%.17g): a fill settled with
//   --omega 0 is the bed that the rotating runs, here and in LIGGGHTS
//   (bench/lammps/drum_liggghts.in), start from. Prints the bed's centre of mass and the mesh's
//   bytes (peak RSS per particle is given without them).
// --warmup W: W steps before the timed ones (not timed), e.g. to set a drum's bed turning.
//
// The particles are renumbered in Morton order of cells before the run (sortParticlesSpatially),
// unless --no-sort. Prints particle-steps/s, peak memory (getrusage), memory per particle, the time split by
// stage and the kinetic energy at the end. Nothing is written during the timed loop. A 12 ms probe
// before and after it (core_probe.h) shows whether the run had a whole CPU core. --no-fusion: the
// general step stages only (Execution::fusedSteps off), to measure what the fused paths pay. --spin-ns: how
// long a waiting thread of the pool spins before it blocks (exec::setSpinNanoseconds; 0: at once).
#include "app/mpi_launch.h"
#include "core_probe.h"
#include "dem/forces.h"
#include "dem/models/normal.h"
#include "dem/paper_balls.h" // verification/: the paper's turntable ball
#include "dem/spatial_sort.h"
#include "dem/world.h"
#include "distributed/rank_gather.h"
#include "distributed/rank_step.h"
#include "exec/isa.h"
#include "exec/thread_pool.h"
#include "io/surface_mesh_reader.h"

#include <algorithm>
#include <charconv>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <malloc.h> // mallinfo2 (glibc)
#include <memory>
#include <random>
#include <sstream>
#include <stdexcept>
#include <string>
#include <sys/resource.h>
#include <unistd.h> // isatty
#include <vector>

using namespace veridem;
using namespace veridem::dem;

namespace
{

struct Options
{
    std::string scene = "bed";
    std::string model = "linear"; // --model: the bed's contact law, "linear" or "hertz" (bedWorld)
    std::string file;
    std::string mesh;     // --mesh: the drum's STL
    std::string writeXyz; // --write-xyz: the centres after the run
    double omega = 4;     // --omega: the drum's angular velocity about +y [rad/s]
    long fill = 0;        // --fill: spheres on a lattice in the drum instead of --file
    long warmup = 0;      // --warmup: untimed steps before the timed loop
    int tile = 1;
    long steps = 10000;
    int threads = 1;
    int repeat = 1;
    bool profile = false;
    bool periodic = false;                // --periodic: the bed periodic in x and y (no side walls)
    bool sort = true;                     // renumber particles in Morton order of cells before the run
    bool fusion = true;                   // --no-fusion: Execution::fusedSteps off (the general stages)
    bool probeOnly = false;               // --core-probe: print one core probe (core_probe.h) and exit
    long spinNs = exec::kSpinNanoseconds; // --spin-ns: the pool's spin before blocking [ns]
};

[[noreturn]] void usage()
{
    std::fprintf(
        stderr,
        "usage: veridem_bench [--scene bed|gas|turntable|drum] [--model linear|hertz] [--file XYZ] [--tile "
        "N]\n"
        "                     [--steps S] [--warmup W] [--threads T] [--repeat R] [--profile] [--no-sort]\n"
        "                     [--no-fusion] [--spin-ns NS] [--mesh STL] [--omega W] [--fill N] [--write-xyz "
        "OUT]\n"
        "                     [--periodic]\n"
        "       veridem_bench --core-probe   (how much of a CPU core this process gets; no run)\n");
    std::exit(2);
}

Options parse(int argc, char** argv)
{
    Options o;
    for (int a = 1; a < argc; ++a)
    {
        const std::string arg = argv[a];
        auto value = [&]() -> std::string
        {
            if (a + 1 >= argc)
                usage();
            return argv[++a];
        };
        // A whole number from `least` to 1e9, or a message naming the option.
        auto number = [&](long least) -> long
        {
            const std::string text = value();
            long n = 0;
            const char* const last = text.data() + text.size();
            const auto [stop, error] = std::from_chars(text.data(), last, n);
            if (error != std::errc() || stop != last || n < least || n > 1000000000L)
                throw std::runtime_error(arg + ": expected a whole number from " + std::to_string(least) +
                                         " to 1e9, got '" + text + "'");
            return n;
        };
        auto count = [&] { return number(1); };
        if (arg == "--scene")
            o.scene = value();
        else if (arg == "--model")
            o.model = value();
        else if (arg == "--file")
            o.file = value();
        else if (arg == "--tile")
            o.tile = static_cast<int>(count());
        else if (arg == "--steps")
            o.steps = count();
        else if (arg == "--warmup")
            o.warmup = number(0);
        else if (arg == "--mesh")
            o.mesh = value();
        else if (arg == "--write-xyz")
            o.writeXyz = value();
        else if (arg == "--fill")
            o.fill = count();
        else if (arg == "--omega")
        {
            const std::string text = value();
            char* stop = nullptr;
            o.omega = std::strtod(text.c_str(), &stop);
            if (text.empty() || *stop != '\0' || !std::isfinite(o.omega))
                throw std::runtime_error("--omega: expected a number [rad/s], got '" + text + "'");
        }
        else if (arg == "--threads")
            o.threads = static_cast<int>(count());
        else if (arg == "--spin-ns")
            o.spinNs = number(0);
        else if (arg == "--repeat")
            o.repeat = static_cast<int>(count());
        else if (arg == "--no-sort")
            o.sort = false;
        else if (arg == "--no-fusion")
            o.fusion = false;
        else if (arg == "--periodic")
            o.periodic = true;
        else if (arg == "--profile")
            o.profile = true;
        else if (arg == "--core-probe")
            o.probeOnly = true;
        else
            usage();
    }
    if (o.scene != "bed" && o.scene != "gas" && o.scene != "turntable" && o.scene != "drum")
        throw std::runtime_error("--scene: expected bed, gas, turntable or drum, got '" + o.scene + "'");
    if (o.scene == "drum" && o.mesh.empty())
        throw std::runtime_error("--scene drum: expected --mesh STL (scripts/make_meshes.py drum)");
    if (o.scene == "drum" && o.fill > 0 && !o.file.empty())
        throw std::runtime_error("--scene drum: expected --file or --fill, not both");
    if (o.scene == "drum" && o.fill == 0 && o.file.empty())
        throw std::runtime_error("--scene drum: expected --file XYZ or --fill N");
    if (o.model != "linear" && o.model != "hertz")
        throw std::runtime_error("--model: expected linear or hertz, got '" + o.model + "'");
    if (o.file.empty())
        o.file = std::string(VERIDEM_SHARED_BENCH_DIR) +
                 (o.scene == "gas" ? "/random_gas_20k.xyz" : "/settled_bed_20k.xyz");
    return o;
}

double peakResidentBytes()
{
    rusage usage{};
    getrusage(RUSAGE_SELF, &usage);
    return static_cast<double>(usage.ru_maxrss) * 1024.0; // Linux: kilobytes
}

double cpuSeconds()
{
    rusage usage{};
    getrusage(RUSAGE_SELF, &usage);
    return static_cast<double>(usage.ru_utime.tv_sec + usage.ru_stime.tv_sec) +
           1e-6 * static_cast<double>(usage.ru_utime.tv_usec + usage.ru_stime.tv_usec);
}

double currentResidentBytes()
{
    std::ifstream statm("/proc/self/statm");
    double pages = 0, resident = 0;
    statm >> pages >> resident;
    return resident * 4096.0;
}

std::vector<Vec3> readXyz(const std::string& path)
{
    std::ifstream in(path);
    if (!in)
        throw std::runtime_error("cannot open " + path);
    std::vector<Vec3> points;
    std::string line;
    for (long number = 1; std::getline(in, line); ++number)
    {
        // Blank lines and lines starting with '#' are skipped; anything else must be x y z [m].
        const std::size_t start = line.find_first_not_of(" \t\r");
        if (start == std::string::npos || line[start] == '#')
            continue;
        std::istringstream row(line);
        Vec3 x;
        std::string rest;
        if (!(row >> x.x >> x.y >> x.z) || (row >> rest))
            throw std::runtime_error(path + ":" + std::to_string(number) +
                                     ": expected three numbers x y z [m], got '" + line + "'");
        points.push_back(x);
    }
    if (points.empty())
        throw std::runtime_error(path + ": no sphere centres (expected lines of x y z [m])");
    return points;
}

Wall plane(const char* name, Vec3 point, Vec3 normal)
{
    Wall w;
    w.name = name;
    w.shape = PlaneShape{point, normal};
    return w;
}

constexpr Real kBedRadius = 1e-3, kBedDensity = 2500; // [m], [kg/m^3]

/// The bed's material (--model linear or hertz).
Material bedMaterial(const Options& o)
{
    Material m;
    m.name = "glass";
    m.density = kBedDensity;
    m.normalStiffness = 1000;
    m.tangentialStiffnessRatio = 2.0 / 7.0;
    m.normalDampingRate = 5955.04; // e = 0.5 for a pair of equal spheres
    m.friction = 0.5;
    if (o.model == "hertz")
    {
        // Hertz-Mindlin, the same law as bench/lammps/bed_hertz.in (LAMMPS `granular hertz/material`,
        // tangential `mindlin NULL`, damping `tsuji` with `limit_damping`, whose eta_n = alpha(e)
        // sqrt(m* (4/3) E* a) is veridem's 2 sqrt(5/6) beta sqrt(m* 2 E* a) when beta = alpha /
        // sqrt(5); both clip Fn at 0, and the restitution given here is the one whose beta for the
        // clipped law is that, for Tsuji's alpha(0.5) = 0.34074). E* = E / (2 (1 - nu^2)) = 2.75e7 Pa
        // between two spheres: the contact stiffness 2 E* sqrt(R* delta) is ~1000 N/m, the linear
        // bed's kn, at its ~0.5 um overlaps. eta_t = (2/7) eta_n.
        const double e = 0.5;
        const double alpha = 1.2728 - 4.2783 * e + 11.087 * e * e - 22.348 * std::pow(e, 3) +
                             27.467 * std::pow(e, 4) - 18.022 * std::pow(e, 5) + 4.8218 * std::pow(e, 6);
        const double beta = alpha / std::sqrt(5.0);
        m.normalModel = NormalModel::Hertz;
        m.youngsModulus = 5e7;
        m.poissonRatio = 0.3;
        m.restitution = hertzRestitutionOfClippedDamping(beta);
        m.normalDampingRate = -1;
        m.tangentialDampingRatio = 2.0 / 7.0;
    }
    m.rollingModel = RollingModel::None;
    return m;
}

/// The reference bed (or gas) of issue 5, tiled n x n side by side.
World bedWorld(const Options& o)
{
    const std::vector<Vec3> base = readXyz(o.file);
    const Real box = 0.1, radius = kBedRadius, density = kBedDensity;
    World world;
    world.addMaterial(bedMaterial(o));
    world.gravity = {0, 0, -9.81};
    world.neighbors.skin = 0.5e-3;
    const Real side = box * o.tile;
    if (o.periodic) // the side walls' planes are the periodic faces (dem/periodic.h)
    {
        world.domain.min = {0, 0, 0};
        world.domain.max = {side, side, box};
        world.domain.periodic = {true, true, false};
    }
    else
    {
        world.walls.push_back(plane("x0", {0, 0, 0}, {1, 0, 0}));
        world.walls.push_back(plane("x1", {side, 0, 0}, {-1, 0, 0}));
        world.walls.push_back(plane("y0", {0, 0, 0}, {0, 1, 0}));
        world.walls.push_back(plane("y1", {0, side, 0}, {0, -1, 0}));
    }
    world.walls.push_back(plane("floor", {0, 0, 0}, {0, 0, 1}));
    world.particles.reserve(base.size() * static_cast<std::size_t>(o.tile * o.tile));
    for (int ty = 0; ty < o.tile; ++ty)
        for (int tx = 0; tx < o.tile; ++tx)
            for (const Vec3& x : base)
                world.particles.add(x + Vec3{tx * box, ty * box, 0}, {}, {}, radius, density, 0);
    return world;
}

/// Up to n centres of a cubic lattice (spacing 2.2 mm, jittered by up to 0.05 mm, a fixed seed)
/// inside the closed drum [x^2 + z^2 < R^2, y in (ylo, yhi)] with 0.5 mm to spare, lowest first.
std::vector<Vec3> drumFill(const TriangleMesh& drum, long n)
{
    const Real spacing = 2.2e-3, margin = kBedRadius + 0.5e-3;
    const Real radius = 0.5 * (drum.upper.x - drum.lower.x) - margin;
    const Real ylo = drum.lower.y + margin, yhi = drum.upper.y - margin;
    std::mt19937_64 random(11);
    std::uniform_real_distribution<Real> jitter(-0.05e-3, 0.05e-3);
    std::vector<Vec3> points;
    const int across = static_cast<int>(radius / spacing);
    for (int iz = -across; iz <= across; ++iz)
        for (Real y = ylo; y <= yhi; y += spacing)
            for (int ix = -across; ix <= across; ++ix)
            {
                const Vec3 x{ix * spacing + jitter(random), y + jitter(random),
                             iz * spacing + jitter(random)};
                if (x.x * x.x + x.z * x.z < radius * radius && x.y > ylo && x.y < yhi)
                    points.push_back(x);
            }
    std::stable_sort(points.begin(), points.end(), [](const Vec3& a, const Vec3& b) { return a.z < b.z; });
    if (points.size() < static_cast<std::size_t>(n))
        throw std::runtime_error("--fill " + std::to_string(n) + ": the drum holds only " +
                                 std::to_string(points.size()) + " lattice sites");
    points.resize(static_cast<std::size_t>(n));
    return points;
}

/// The bed's spheres and law in a closed mesh drum turning about +y through the origin.
World drumWorld(const Options& o)
{
    World world;
    world.addMaterial(bedMaterial(o));
    world.gravity = {0, 0, -9.81};
    world.neighbors.skin = 0.5e-3;
    MeshReport report;
    MeshShape shape;
    shape.mesh = std::make_shared<const TriangleMesh>(buildTriangleMesh(io::readStl(o.mesh), o.mesh, report));
    for (const std::string& warning : report.warnings)
        std::fprintf(stderr, "veridem_bench: warning: %s\n", warning.c_str());
    shape.farthestVertex = shape.mesh->farthestVertex(shape.pivot);
    Wall drum;
    drum.name = "drum";
    drum.motion.angularVelocity = {0, o.omega, 0};
    const std::vector<Vec3> centres = o.fill > 0 ? drumFill(*shape.mesh, o.fill) : readXyz(o.file);
    drum.shape = std::move(shape);
    world.walls.push_back(std::move(drum));
    world.particles.reserve(centres.size());
    for (const Vec3& x : centres)
        world.particles.add(x, {}, {}, kBedRadius, kBedDensity, 0);
    return world;
}

/// The mesh's bytes (TriangleMesh::memoryBytes), 0 without a mesh wall.
double meshBytes(const World& world)
{
    double bytes = 0;
    for (const Wall& w : world.walls)
        if (const auto* m = std::get_if<MeshShape>(&w.shape))
            bytes += static_cast<double>(m->mesh->memoryBytes());
    return bytes;
}

/// The paper's flat-turntable ball (verify::flatTurntableBall: steel, a = 6.35 mm, type A rolling
/// friction, as the verification cases run it) rolling on a turntable turning at 10 rad/s: the
/// paper's Test 1 set-up with a push.
World turntableWorld()
{
    World world;
    const Material m = verify::flatTurntableBall();
    world.addMaterial(m);
    Wall table;
    table.name = "turntable";
    table.shape = PlaneShape{{0, 0, 0}, {0, 0, 1}, 0.2};
    table.motion.angularVelocity = {0, 0, 10};
    world.walls.push_back(table);
    const Real a = verify::kFlatBallRadius;
    const Real mass = m.density * 4.0 / 3.0 * 3.14159265358979 * a * a * a;
    const Real overlap = mass * 9.81 / m.normalStiffness;
    world.particles.add({-0.04, 0, a - overlap}, {0, -0.107, 0}, {}, a, m.density, 0);
    return world;
}

} // namespace

namespace
{

/// Under `mpirun -np R` (R > 1): the run's figures from all ranks, printed by the first. Wall time
/// is the slowest rank's; memory is every rank's peak RSS summed (ghosts and MPI buffers
/// included) over the particles; communication is each rank's time in the exchanges.
void reportRanks(const Options& o, const World& world, const distributed::RankStep& ranks, std::size_t n,
                 double seconds, double cpu, double residentBefore)
{
    const distributed::Collective& comm = ranks.comm();
    const distributed::RankStep::Times& t = ranks.times();
    std::vector<double> largest = {seconds, t.refresh, t.decision, t.health, t.exchange};
    comm.max(largest);
    std::vector<std::uint64_t> sums = {static_cast<std::uint64_t>(peakResidentBytes()),
                                       static_cast<std::uint64_t>(residentBefore),
                                       static_cast<std::uint64_t>(cpu * 1e6),
                                       ranks.halo().ghosts(),
                                       ranks.refreshBytes(),
                                       ranks.exchangeBytes()};
    comm.sum(sums);
    std::vector<double> ownedMaxD = {double(ranks.owned()), double(ranks.halo().ghosts())};
    comm.max(ownedMaxD);
    const std::optional<World> whole = distributed::gatherWorld(world, ranks);
    if (comm.rank() != 0)
        return;
    const int r = comm.size();
    const double steps = static_cast<double>(o.steps);
    const double wall = largest[0];
    std::printf("scene %s  model %s  particles %zu  MPI ranks %d  threads %d  steps %ld  dt %g s\n",
                o.scene.c_str(), o.model.c_str(), n, r, o.threads, o.steps, 1e-5);
    std::printf("  wall time %.3f s  %.4g particle-steps/s  %.4g steps/s\n", wall,
                static_cast<double>(n) * steps / wall, steps / wall);
    std::printf("  cpu time %.3f s = %.2f cores busy\n", double(sums[2]) / 1e6, double(sums[2]) / 1e6 / wall);
    std::printf("  peak RSS summed over the ranks %.1f MB = %.0f B/particle (%.0f B/particle above the empty "
                "processes)\n",
                double(sums[0]) / 1e6, double(sums[0]) / double(n), double(sums[0] - sums[1]) / double(n));
    std::printf(
        "  owned per rank: mean %.0f, largest %.0f (%.3f of the mean); ghosts %.0f a rank (%.3f per owned "
        "particle), largest %.0f\n",
        double(n) / r, ownedMaxD[0], ownedMaxD[0] * r / double(n), double(sums[3]) / r,
        double(sums[3]) / double(n), ownedMaxD[1]);
    std::printf("  regions cut %llu times in %llu exchanges of particles\n",
                static_cast<unsigned long long>(ranks.cuts()),
                static_cast<unsigned long long>(ranks.exchanges()));
    std::printf(
        "  bytes sent per rank per step: ghost motion %.0f, exchanges of particles and history %.0f (mean "
        "over the ranks, warm-up included)\n",
        double(sums[4]) / r / double(o.steps + o.warmup), double(sums[5]) / r / double(o.steps + o.warmup));
    std::printf(
        "  time in communication (largest rank, warm-up included): ghost refresh %.3f s, rebuild decision "
        "%.3f s, health %.3f s, exchanges %.3f s; of the wall time %.1f %%\n",
        largest[1], largest[2], largest[3], largest[4],
        100 * (largest[1] + largest[2] + largest[3] + largest[4]) / wall);
    if (whole)
        std::printf("  kinetic energy after %ld steps %.9e J\n", o.warmup + o.steps, kineticEnergy(*whole));
    std::fflush(stdout);
}

int run(int argc, char** argv)
{
    app::MpiLaunch launch(argc, argv);
    const Options o = parse(argc, argv);
    if (o.probeOnly)
    {
        const bench::CoreProbe probe = bench::probeCore();
        std::printf("core probe: %.2f GHz, %.2f adds/cycle (%s)\n", probe.clockGHz, probe.addsPerCycle,
                    bench::kWholeCoreAdds);
        return 0;
    }
    exec::setThreads(o.threads);
    exec::setSpinNanoseconds(o.spinNs);
    const double residentBefore = currentResidentBytes();
    const bool single = o.scene == "turntable";
    const Real dt = 1e-5;

    for (int r = 0; r < o.repeat; ++r)
    {
        World world = single ? turntableWorld() : o.scene == "drum" ? drumWorld(o) : bedWorld(o);
        const std::size_t n = world.particles.size();
        const auto setupStart = std::chrono::steady_clock::now();
        if (o.sort)
            sortParticlesSpatially(world);
        std::optional<distributed::RankStep> ranks;
        if (launch.size() > 1) // each rank prepares its part
        {
            ranks.emplace(*launch.collective());
            ranks->distribute(world);
        }
        else
            prepare(world);
        const double setupSeconds =
            std::chrono::duration<double>(std::chrono::steady_clock::now() - setupStart).count();
        world.exec.profile.enabled = o.profile;
        world.exec.fusedSteps = o.fusion;
        if (o.warmup > 0)
            advance(world, dt, static_cast<std::uint64_t>(o.warmup)); // (not timed)

        const bench::CoreProbe probeBefore = bench::probeCore();
        const double cpuStart = cpuSeconds();
        const auto start = std::chrono::steady_clock::now();
        // The fastest window of kWindow steps as well: on a shared machine the whole-run rate
        // moves by +-15 % with other load, the best window much less (for A/B comparisons of
        // builds; comparisons with other codes use whole runs, which is all they report).
        constexpr long kWindow = 100;
        std::vector<double> windows; // seconds per window
        windows.reserve(static_cast<std::size_t>(o.steps / kWindow));
        auto windowStart = start;
        const bool progressTty = isatty(STDERR_FILENO) != 0 && launch.rank() == 0; // (not into logs)
        auto nextProgress = start + std::chrono::seconds(5);
        bool progressShown = false;
        for (long done = 0; done < o.steps;) // windows of kWindow steps, then the remainder
        {
            const long count = std::min(kWindow, o.steps - done);
            advance(world, dt, static_cast<std::uint64_t>(count)); // (as `count` step() calls, fused)
            done += count;
            if (count == kWindow)
            {
                const auto now = std::chrono::steady_clock::now();
                windows.push_back(std::chrono::duration<double>(now - windowStart).count());
                windowStart = now;
                // Progress on stderr for long runs (a 1e6-sphere bed takes minutes), every ~5 s;
                // the clock is read here anyway, so the loop pays one comparison.
                if (progressTty && now >= nextProgress)
                {
                    const double elapsed = std::chrono::duration<double>(now - start).count();
                    const double fraction = static_cast<double>(done) / static_cast<double>(o.steps);
                    std::fprintf(stderr, "\r  step %ld of %ld (%.0f %%), ETA %.0f s   ", done, o.steps,
                                 100 * fraction, elapsed / fraction - elapsed);
                    std::fflush(stderr);
                    nextProgress = now + std::chrono::seconds(5);
                    progressShown = true;
                }
            }
        }
        if (progressShown)
            std::fprintf(stderr, "\r%*s\r", 60, "");
        const double seconds =
            std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
        const double cpu = cpuSeconds() - cpuStart;
        const bench::CoreProbe probeAfter = bench::probeCore();
        const double rate = static_cast<double>(n) * static_cast<double>(o.steps) / seconds;
        if (ranks)
        {
            reportRanks(o, world, *ranks, n, seconds, cpu, residentBefore);
            continue;
        }

        const double peak = peakResidentBytes();
        std::printf("scene %s  model %s  particles %zu  threads %d  steps %ld  dt %g s\n", o.scene.c_str(),
                    single ? "turntable ball" : o.model.c_str(), n, o.threads, o.steps, dt);
        std::printf("  wall time %.3f s (prepare %.3f s)  %.4g particle-steps/s  %.4g steps/s\n", seconds,
                    setupSeconds, rate, static_cast<double>(o.steps) / seconds);
        if (!windows.empty())
        {
            // VERIDEM_BENCH_WINDOWS=file: every window's rate in run order, one per line, to see
            // whether slow windows come in stretches (other load) or singly (rebuilds).
            if (const char* path = std::getenv("VERIDEM_BENCH_WINDOWS"))
                if (std::FILE* f = std::fopen(path, "w"))
                {
                    for (const double w : windows)
                        std::fprintf(f, "%.6g\n", static_cast<double>(n) * kWindow / w);
                    std::fclose(f);
                }
            // Best and median: the median window shows whether a slow whole run was slow
            // throughout (other load) or in a few windows (list rebuilds, a preempted thread).
            std::sort(windows.begin(), windows.end());
            const double perWindow = static_cast<double>(n) * static_cast<double>(kWindow);
            std::printf("  best window of %ld steps %.4g particle-steps/s (median window %.4g)\n", kWindow,
                        perWindow / windows.front(), perWindow / windows[windows.size() / 2]);
        }
        // CPU time of the process over the loop: on a shared machine, the rate per busy core is a
        // steadier measure than wall time (with T threads, compare cpu / T with the wall time).
        std::printf("  cpu time %.3f s = %.2f cores busy  %.4g particle-steps per cpu-second\n", cpu,
                    cpu / seconds, static_cast<double>(n) * static_cast<double>(o.steps) / cpu);
        // Whether the run had a whole core (bench/core_probe.h): on a shared machine another
        // tenant's hardware thread on the same core slows a run by up to ~1.5x at the same clock.
        if (probeBefore.addsPerCycle > 0)
            std::printf("  core probe (main thread): before %.2f GHz, %.2f adds/cycle; after %.2f GHz, %.2f "
                        "adds/cycle (%s)\n",
                        probeBefore.clockGHz, probeBefore.addsPerCycle, probeAfter.clockGHz,
                        probeAfter.addsPerCycle, bench::kWholeCoreAdds);
        std::printf("  peak RSS %.1f MB = %.0f B/particle (%.0f B/particle above the empty process)\n",
                    peak / 1e6, peak / static_cast<double>(n),
                    (peak - residentBefore) / static_cast<double>(n));
        {
            // The heap at the end (glibc mallinfo2): bytes in use by live allocations and bytes
            // freed but still held, against the resident set now; peak RSS above what is in use is
            // transient (list rebuilds) or freed memory the allocator kept.
            const struct mallinfo2 heap = mallinfo2();
            std::printf("  at the end: RSS %.1f MB, heap in use %.1f MB, heap free but held %.1f MB\n",
                        currentResidentBytes() / 1e6, static_cast<double>(heap.uordblks) / 1e6,
                        static_cast<double>(heap.fordblks) / 1e6);
        }
        if (const double mesh = meshBytes(world); mesh > 0)
            std::printf(
                "  mesh %.3f MB; peak RSS without it %.0f B/particle (%.0f B/particle above the empty "
                "process)\n",
                mesh / 1e6, (peak - mesh) / static_cast<double>(n),
                (peak - residentBefore - mesh) / static_cast<double>(n));
        const ParticleStore& store = world.particles;
        const double particleBytes =
            static_cast<double>(n * (3 * sizeof(store.position[0]) + 3 * sizeof(store.force[0]) +
                                     4 * sizeof(Real) + sizeof(std::uint32_t)));
        std::printf("  arrays: particles %.0f B/particle, pair list and history %.0f B/particle, wall list "
                    "and history "
                    "%.0f B/particle\n",
                    particleBytes / static_cast<double>(n),
                    static_cast<double>(world.neighbors.memoryBytes() + world.pairHistory.memoryBytes()) /
                        static_cast<double>(n),
                    static_cast<double>(world.wallContacts.memoryBytes() + world.wallHistory.memoryBytes()) /
                        static_cast<double>(n));
        std::printf("  contact kernel %s (VERIDEM_KERNEL=avx2|portable to choose)\n", exec::isaName());
        std::printf("  pair slots %zu (%.2f per particle), rebuilds %zu, max overlap/r %.3g\n",
                    world.neighbors.size(),
                    static_cast<double>(world.neighbors.size()) / static_cast<double>(n),
                    world.neighbors.rebuildCount(), world.health.maxOverlapRatio);
        std::printf("  cross-block slots %zu (%.1f %% of slots; blocks of %u particles)\n",
                    world.neighbors.deferred.size(),
                    100.0 * static_cast<double>(world.neighbors.deferred.size()) /
                        static_cast<double>(std::max<std::size_t>(world.neighbors.size(), 1)),
                    NeighborList::kBlockParticles);
        if (world.exec.pairSchedule.chunks > 1)
            std::printf(
                "  pair stage on %d threads: the busiest has %.1f %% of the weighted candidates; the split "
                "moved %llu times after the threads' measured speeds\n",
                world.exec.pairSchedule.chunks, 100.0 * world.exec.pairSchedule.heaviestShare,
                static_cast<unsigned long long>(world.exec.pairSchedule.moves));
        std::printf("  touching candidates %zu (%.2f per particle, inner skin %.3g m), rebuilt %zu times\n",
                    world.neighbors.activeSlots.size(),
                    static_cast<double>(world.neighbors.activeSlots.size()) / static_cast<double>(n),
                    world.neighbors.innerSkin, world.neighbors.activeRebuildCount());
        const auto touching = static_cast<std::ptrdiff_t>(world.health.touchingPairs);
        const auto wallTouching = static_cast<std::ptrdiff_t>(world.health.touchingWalls);
        std::printf("  touching pairs %td (%.2f per particle), wall slots %zu, touching walls %td\n",
                    touching, static_cast<double>(touching) / static_cast<double>(n),
                    world.wallContacts.size(), wallTouching);
        if (world.domain.any())
        {
            std::size_t formed = 0;
            for (const std::uint8_t f : world.periodicPairs.history.formed)
                formed += f;
            std::printf("  pairs through a periodic face %zu (%zu in contact)\n", world.periodicPairs.size(),
                        formed);
        }
        std::printf("  kinetic energy after %ld steps %.9e J\n", o.warmup + o.steps, kineticEnergy(world));
        if (o.scene == "drum")
        {
            Vec3 centre;
            for (std::size_t i = 0; i < n; ++i)
                centre += world.particles.position[i];
            centre = (1.0 / static_cast<Real>(n)) * centre;
            std::printf("  centre of mass after %ld steps %.6e %.6e %.6e m\n", o.warmup + o.steps, centre.x,
                        centre.y, centre.z);
        }
        if (!o.writeXyz.empty())
        {
            std::FILE* f = std::fopen(o.writeXyz.c_str(), "w");
            if (f == nullptr)
                throw std::runtime_error("cannot write " + o.writeXyz);
            for (std::size_t i = 0; i < n; ++i)
                std::fprintf(f, "%.17g %.17g %.17g\n", world.particles.position[i].x,
                             world.particles.position[i].y, world.particles.position[i].z);
            std::fclose(f);
        }
        if (o.profile)
        {
            const StepProfile& p = world.exec.profile;
            const double total = p.integration + p.neighbours + p.pairForces + p.particlePass;
            auto share = [&](const char* name, double t)
            {
                std::printf("    %-25s %8.3f s %5.1f %%  %6.1f ns/particle-step\n", name, t, 100 * t / total,
                            1e9 * t / (static_cast<double>(n) * static_cast<double>(o.steps)));
            };
            // The run advances in advance() calls: every step but each window's last closes with the
            // next step's kick-drift, inside the particle pass (world.h).
            std::printf("  time by stage (timers on; the kick-drift runs inside the particle pass):\n");
            share("neighbour rebuild", p.neighbours);
            share("pair forces", p.pairForces);
            share("cross-block, walls, kicks", p.particlePass);
            share("walls moved, 1st drift", p.integration);
            if (o.threads > 1)
            {
                // Each thread's busy time in the two parallel stages (StepProfile): the balance,
                // and the stage's wall time beyond its busiest thread (the serial work before the
                // region, such as refreshing the candidate sub-list, and entering and leaving it).
                auto perThread =
                    [&](const char* name, const std::array<double, StepProfile::kThreads>& busy, double wall)
                {
                    const double perStep = 1e9 / (static_cast<double>(n) * static_cast<double>(o.steps));
                    std::printf("    %-25s", name);
                    double busiest = 0;
                    for (int t = 0; t < std::min(o.threads, StepProfile::kThreads); ++t)
                    {
                        std::printf(" %6.1f", perStep * busy[static_cast<std::size_t>(t)]);
                        busiest = std::max(busiest, busy[static_cast<std::size_t>(t)]);
                    }
                    std::printf("  ns/particle-step by thread (stage wall time %.1f)\n", perStep * wall);
                };
                std::printf(
                    "  busy time by thread (their sum is the work; the stage waits for the busiest):\n");
                perThread("pair forces", p.pairBusy, p.pairForces);
                perThread("cross-block, walls, kicks", p.particlePassBusy, p.particlePass);
            }
        }
        std::fflush(stdout);
    }
    return 0;
}
} // namespace

int main(int argc, char** argv)
{
    // A missing or malformed input file is a message and exit status 1, not an abort.
    try
    {
        return run(argc, argv);
    }
    catch (const std::exception& e)
    {
        std::fprintf(stderr, "veridem_bench: %s\n", e.what());
        return 1;
    }
}
