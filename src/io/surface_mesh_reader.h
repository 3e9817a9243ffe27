// Readers of triangle surfaces for mesh walls, each giving a triangle soup (three corners per
// triangle, in file order, multiplied by `scale`) for dem::buildTriangleMesh:
//   STL   ASCII or binary, told apart by content (a binary file's size is 84 + 50 n for the
//         count n in its header; otherwise a file starting with "solid" and holding no zero
//         byte is ASCII, anything else a truncated binary one);
//   Gmsh  .msh format 2.2 or 4.1, ASCII; only 3-node triangles (element type 2) are kept.
// Errors are InputError "file:line: what is wrong" (a binary STL: the triangle index).
#pragma once

#include "core/vec3.h"

#include <string>
#include <vector>

namespace veridem::io
{

std::vector<Vec3> readStl(const std::string& path, Real scale = 1);
std::vector<Vec3> readGmshSurface(const std::string& path, Real scale = 1);

/// readStl or readGmshSurface by the file's extension (.stl or .msh, any case).
std::vector<Vec3> readSurfaceMesh(const std::string& path, Real scale = 1);

} // namespace veridem::io
