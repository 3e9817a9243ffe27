// Readers of triangle surfaces for mesh walls, each giving a triangle soup (three corners per
// triangle, in file order, multiplied by `scale`) for dem::buildTriangleMesh:
//   STL   ASCII or binary, told apart by content (a binary file's size is 84 + 50 n for the
//         count n in its header; otherwise a file starting with "solid" and holding no zero
//         byte is ASCII, anything else a truncated binary one);
//   Gmsh  .msh format 2.2 or 4.1, ASCII (io/gmsh_file.h); only 3-node triangles are kept;
//   text  .txt, nine columns: a header line (words, not numbers), then one triangle a line, the
//         x y z of its three corners [m] separated by spaces or tabs (the DEM8 benchmark's walls).
// Errors are InputError "file:line: what is wrong" (a binary STL: the triangle index).
#pragma once

#include "core/vec3.h"

#include <string>
#include <vector>

namespace veridem::io
{

std::vector<Vec3> readStl(const std::string& path, Real scale = 1);
std::vector<Vec3> readGmshSurface(const std::string& path, Real scale = 1);
/// The nine-column triangle text; with `lines`, the file line of each triangle is appended to it
/// (for buildTriangleMesh's message naming a degenerate triangle's line).
std::vector<Vec3> readTriangleText(const std::string& path, Real scale = 1,
                                   std::vector<std::size_t>* lines = nullptr);

/// readStl, readGmshSurface or readTriangleText by the file's extension (.stl, .msh or .txt, any
/// case); `lines` as readTriangleText's (left empty for the other formats).
std::vector<Vec3> readSurfaceMesh(const std::string& path, Real scale = 1,
                                  std::vector<std::size_t>* lines = nullptr);

} // namespace veridem::io
