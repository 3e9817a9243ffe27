// The readers under fuzzing, as one function each: the libFuzzer targets (fuzz/*_fuzzer.cpp) and
// the regression test that replays every input that ever crashed them (tests/io/fuzz_cases/) call
// these. Refused input (InputError) is the expected outcome for most inputs; anything else that
// escapes (another exception, a sanitizer report, a crash, a hang) is a finding.
#pragma once

#include "core/constants.h"
#include "core/error.h"
#include "dem/sphere_box_volume.h"
#include "fdem/gmsh_reader.h"
#include "fdem/scene.h"
#include "io/dem_checkpoint.h"
#include "io/dem_scene.h"
#include "io/scene_limits.h"
#include "io/toml_reader.h"

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <string_view>
#include <unistd.h>

namespace veridem::fuzz
{

/// Scenes of at most this many spheres: larger ones are refused like a scene above the machine's
/// memory, so a fuzz input cannot spend seconds building a big lattice.
inline constexpr double kFuzzSphereLimit = 2000;

/// 3D scene: TOML text -> checked scene and world (initial overlap check included; no stepping).
inline void readScene3d(std::string_view text)
{
    io::limitSpheres(kFuzzSphereLimit);
    try
    {
        const toml::table table = io::parseText(text, "fuzz.toml");
        io::readDemScene(table, "fuzz.toml");
    }
    catch (const InputError&)
    {
    }
}

/// 2D scene: TOML text -> checked scene -> world (meshes built, bodies added; no stepping).
inline void readScene2d(std::string_view text)
{
    try
    {
        const toml::table table = io::parseText(text, "fuzz.toml");
        const fdem::Scene scene = fdem::readScene(table, "fuzz.toml");
        std::size_t triangles = 0;
        for (const auto& body : scene.bodies)
            triangles += body.mesh.triangles.size();
        if (triangles <= 20000) // bounded work per input (the reader itself allows 1e7)
            fdem::buildWorld(scene, false);
    }
    catch (const InputError&)
    {
    }
}

/// The scene whose checkpoints readCheckpoint3d reads: 8 spheres with friction and EPSD rolling
/// on an oscillating floor (every kind of record non-empty once stepped).
inline constexpr const char* kCheckpointScene = R"(
[simulation]
dt = 2e-5
duration = 1
gravity = [0, 0, -30]
vtk = false
[[material]]
name = "grain"
density = 2500
kn = 1e4
restitution = 0.1
rolling_model = "epsd"
rolling_friction = 0.0005
[[wall]]
name = "floor"
material = "grain"
normal = [0, 0, 1]
oscillation_amplitude = [0, 0, 0.0002]
oscillation_omega = 300
[[lattice]]
material = "grain"
radius = 0.005
min = [0.0001, 0.0001, 0.0001]
max = [0.0203, 0.0203, 0.0203]
spacing = 0.0101
velocity = [0.1, 0.05, -0.1]
)";
inline constexpr std::uint64_t kCheckpointSceneHash = 1; // (the fuzz inputs' header carries it)

inline io::DemScene checkpointScene()
{
    return io::readDemScene(io::parseText(kCheckpointScene, "checkpoint.toml"), "checkpoint.toml");
}

/// Checkpoint bytes -> a world of kCheckpointScene restored from them (the reader takes a file: the
/// bytes go to a temporary file of this process first).
inline void readCheckpoint3d(std::string_view bytes)
{
    const std::filesystem::path path = std::filesystem::temp_directory_path() /
                                       ("veridem_fuzz_checkpoint_" + std::to_string(::getpid()) + ".bin");
    std::ofstream(path, std::ios::binary).write(bytes.data(), static_cast<std::streamsize>(bytes.size()));
    static const io::DemScene base = checkpointScene(); // (copied per input: no TOML parse each time)
    io::DemScene scene = base;
    try
    {
        io::readDemCheckpoint(path, scene.world, kCheckpointSceneHash);
    }
    catch (const InputError&)
    {
    }
    std::error_code ignored;
    std::filesystem::remove(path, ignored);
}

/// Gmsh .msh text -> validated triangle mesh.
inline void readMsh(std::string_view text)
{
    try
    {
        std::istringstream in{std::string(text)};
        fdem::readGmsh(in, "fuzz.msh");
    }
    catch (const InputError&)
    {
    }
}

/// Region measures: the bytes as little-endian doubles, 11 per case: the sphere's centre and radius,
/// the box's two corners and a cut x. Cases with a value that is not finite, a coordinate beyond
/// 1e3 m or a radius outside [1e-9, 1e3] m (no granular scene has them) are skipped. The volume of
/// the sphere in the box must be finite, within [0, 4/3 pi r^3], and equal the sum of its parts on
/// either side of the cut to 1e-12 of the sphere's volume (sphere_box_volume.h: rounding only);
/// anything else aborts. A hang (the cost of the closed form is bounded) is libFuzzer's -timeout.
inline void measureRegionVolumes(std::string_view bytes)
{
    constexpr std::size_t kValues = 11;
    for (std::size_t at = 0; at + kValues * sizeof(double) <= bytes.size(); at += kValues * sizeof(double))
    {
        double v[kValues];
        std::memcpy(v, bytes.data() + at, sizeof v);
        if (!std::all_of(v, v + kValues, [](double x) { return std::isfinite(x) && std::abs(x) <= 1e3; }))
            continue;
        const double r = v[3];
        if (!(r >= 1e-9 && r <= 1e3))
            continue;
        const Vec3 c{v[0], v[1], v[2]};
        const Vec3 lo{std::min(v[4], v[7]), std::min(v[5], v[8]), std::min(v[6], v[9])};
        const Vec3 hi{std::max(v[4], v[7]), std::max(v[5], v[8]), std::max(v[6], v[9])};
        const double cut = std::clamp(v[10], lo.x, hi.x);
        const double sphere = 4.0 / 3.0 * kPi * r * r * r;
        const double whole = dem::sphereBoxVolume(c, r, lo, hi);
        const double parts = dem::sphereBoxVolume(c, r, lo, {cut, hi.y, hi.z}) +
                             dem::sphereBoxVolume(c, r, {cut, lo.y, lo.z}, hi);
        if (!(whole >= 0 && whole <= sphere) || !(std::abs(whole - parts) <= 1e-12 * sphere))
            std::abort();
    }
}

} // namespace veridem::fuzz
