// Time to write and to read a checkpoint of a 1e6-sphere bed (docs/performance.md, "Checkpoint").
// A 100 x 100 x 100 lattice of near-touching spheres with friction and a floor, stepped a few
// times so the neighbour list and its contact history are those of a dense bed; then
// writeDemCheckpoint (fsync and rename included) and readDemCheckpoint, three times each.
//   checkpoint_bench [DIR] [STEPS]   (DIR default /tmp, STEPS default 20)
#include "bench_args.h"
#include "dem/world.h"
#include "io/dem_checkpoint.h"
#include "io/dem_scene.h"
#include "io/toml_reader.h"

#include <chrono>
#include <cstdio>
#include <filesystem>
#include <string>

namespace
{

const char* kScene = R"(
[simulation]
dt = 1e-5
duration = 1
vtk = false
gravity = [0, 0, -9.81]

[[material]]
name = "grain"
density = 2500
kn = 1e5
friction = 0.5

[[wall]]
name = "floor"
material = "grain"
normal = [0, 0, 1]

[[lattice]]
material = "grain"
radius = 0.001
min = [0, 0, 0]
max = [0.2001, 0.2001, 0.2001]
spacing = 0.002001
velocity = [0.01, 0.005, -0.01]
)";

} // namespace

int main(int argc, char** argv)
{
    using namespace veridem;
    using bench::seconds;
    const std::filesystem::path dir = argc > 1 ? argv[1] : "/tmp";
    const int steps = argc > 2 ? std::stoi(argv[2]) : 20;
    const toml::table table = io::parseText(kScene, "checkpoint_bench.toml");
    io::DemScene scene = io::readDemScene(table, "checkpoint_bench.toml");
    dem::World& world = scene.world;
    dem::prepare(world);
    dem::advance(world, scene.dt, static_cast<std::uint64_t>(steps));
    std::printf("%zu spheres, %zu slots, %zu candidates, %zu wall contacts after %d steps\n",
                world.particles.size(), world.neighbors.size(), world.neighbors.activeSlots.size(),
                world.wallContacts.size(), steps);
    const std::filesystem::path path = dir / "checkpoint_bench.bin";
    const io::CheckpointOutputs outputs{{0.0}, {0, 0}, 0};
    for (int round = 0; round < 3; ++round)
    {
        const auto start = std::chrono::steady_clock::now();
        io::writeDemCheckpoint(path, world, 42, outputs);
        const double write = seconds(start);
        const double bytes = double(std::filesystem::file_size(path));
        io::DemScene copy = io::readDemScene(table, "checkpoint_bench.toml");
        const auto readStart = std::chrono::steady_clock::now();
        io::readDemCheckpoint(path, copy.world, 42);
        const double read = seconds(readStart);
        std::printf("checkpoint %.1f MB: write %.3f s (%.0f MB/s, fsync included), read %.3f s\n",
                    bytes / 1e6, write, bytes / 1e6 / write, read);
    }
    std::filesystem::remove(path);
    return 0;
}
