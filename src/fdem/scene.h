// 2D FEM/DEM scene files (TOML, [simulation] type = "fdem2d"). Every key is read through the strict
// io::TableReader, so an unknown key is an error naming the line and the nearest valid key. The keys,
// units and defaults are listed in docs/fdem.md.
#pragma once

#include "fdem/world.h"

#include <toml++/toml.h>

#include <string>
#include <vector>

namespace veridem::fdem
{

struct SceneBoundary
{
    std::uint32_t body = 0; ///< index into Scene::bodies
    Vec2 boxMin{};          ///< [m]
    Vec2 boxMax{};          ///< [m]
    Vec2 velocity{};        ///< prescribed velocity of the nodes in the box [m/s]
};

struct Scene
{
    WorldSettings settings;
    Real duration = 0;                 ///< simulated time after settling [s]
    Real outputInterval = 0;           ///< [s]; 0: first and last state only
    Real checkpointInterval = 0;       ///< [s] between checkpoints (after the settling); 0: none
    Real settleTime = 0;               ///< [s] run with zero body velocities before t = 0, then impose them
    Real settleNormalDampingRatio = 0; ///< zeta_n during the settling [1]
    bool vtk = true;                   ///< write .vtu frames and series.pvd
    std::string vtkFormat = "auto";    ///< "auto", "ascii" or "binary" (io::chooseVtkFormat)
    std::vector<std::string> materialNames;
    std::vector<Material> materials;
    std::vector<BodyDefinition> bodies;
    std::vector<SceneBoundary> boundaries;
};

/// Reads and checks a scene. `sceneFile` names the file in messages and anchors relative mesh paths.
Scene readScene(const toml::table& root, const std::string& sceneFile);

/// Builds the world of a scene. With `settle`, the bodies start at rest (Scene::settleTime).
World buildWorld(const Scene& scene, bool settle);

} // namespace veridem::fdem
