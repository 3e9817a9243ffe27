// The readers under fuzzing, as one function each: the libFuzzer targets (fuzz/*_fuzzer.cpp) and
// the regression test that replays every input that ever crashed them (tests/io/fuzz_cases/) call
// these. Refused input (InputError) is the expected outcome for most inputs; anything else that
// escapes (another exception, a sanitizer report, a crash, a hang) is a finding.
#pragma once

#include "core/error.h"
#include "fdem/gmsh_reader.h"
#include "fdem/scene.h"
#include "io/dem_scene.h"
#include "io/scene_limits.h"
#include "io/toml_reader.h"

#include <sstream>
#include <string>
#include <string_view>

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

} // namespace veridem::fuzz
