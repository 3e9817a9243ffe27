// The Gmsh .msh reader (ASCII formats 2.2 and 4.1; https://gmsh.info/doc/texinfo/gmsh.html,
// section "MSH file format"), shared by the 3D mesh walls (io/surface_mesh_reader.h) and the 2D
// FEM/DEM bodies (fdem/gmsh_reader.h). It keeps the 3-node triangles (element type 2) and the
// nodes they use; points, lines, quadrangles, volumes and higher-order elements are skipped.
// Every declared count is bounded by the size of the stream, so a short file declaring 1e8 nodes
// is refused before anything is allocated. Errors are InputError "source:line: what is wrong".
#pragma once

#include "core/vec3.h"

#include <array>
#include <cstdint>
#include <istream>
#include <string>
#include <vector>

namespace veridem::io
{

/// The triangles of a .msh file and the nodes they use, in the order of first use.
struct GmshTriangles
{
    std::vector<Vec3> nodes;                             // coordinates as written in the file
    std::vector<long long> nodeTags;                     // each node's Gmsh tag (for messages)
    std::vector<std::array<std::uint32_t, 3>> triangles; // indices into nodes, in file order
};

/// Reads the .msh text of `in`; `source` names it in messages.
GmshTriangles readGmshTriangles(std::istream& in, const std::string& source);

/// Reads the .msh file at `path`.
GmshTriangles readGmshTriangles(const std::string& path);

} // namespace veridem::io
