// The [[wall]] keys shared by every wall type (docs/scene-format.md): prescribed motion tables
// (velocity_table, omega_table), the active window (active_from, active_until) and the load
// reference point (load_point); the cylinder type with its end caps, and the mesh type.
#pragma once

#include "dem/walls/wall.h"
#include "dem/world.h"
#include "io/toml_reader.h"

#include <vector>

namespace veridem::io
{

/// One [[wall]] table: its type's shape and motion, then the keys shared by every type
/// (readCommonWallKeys); materials are looked up in `world`. A capped cylinder's caps are not
/// added here (cylinderCaps).
dem::Wall readWall(TableReader& t, const dem::World& world);

/// The axis a wall may rotate about: its shape's symmetry axis (plane normal, cylinder axis, the
/// dish's vertical).
Vec3 symmetryAxis(const dem::Wall& wall);

/// Reads velocity_table, omega_table, active_from, active_until and load_point into `wall`, whose
/// shape, constant velocity and angular velocity are already read. `axis`: the shape's symmetry
/// axis (unit), the only direction an angular velocity may have.
void readCommonWallKeys(TableReader& t, dem::Wall& wall, const Vec3& axis);

/// A triangle-mesh wall: the surface from `file` (STL or Gmsh, relative to the scene's directory)
/// times `scale`, translating at `velocity` [m/s] and turning at `omega` [rad/s, a vector] about
/// `rotation_centre` [m]. The mesh's warnings (open boundary, non-manifold edges) go to stderr.
void readMeshWall(TableReader& t, dem::Wall& wall);

/// Reads a `type = "cylinder"` wall's shape and rotation (point, axis, radius, length, side,
/// omega) into `wall`; returns true if it asks for closed ends (caps = true).
bool readCylinder(TableReader& t, dem::Wall& wall);

/// The two end disks of a capped cylinder wall, walls of their own named NAME/cap0 (at `point`)
/// and NAME/cap1 (at point + length axis), facing the particles' side, with the cylinder's
/// material, motion, active window and load point.
std::vector<dem::Wall> cylinderCaps(const dem::Wall& cylinder);

} // namespace veridem::io
