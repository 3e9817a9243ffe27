// Reader for Gmsh .msh files, ASCII format 2.2 and 4.1 (https://gmsh.info/doc/texinfo/gmsh.html,
// section "MSH file format"). Only 3-node triangles (element type 2) are kept; points, lines and
// other elements are skipped. The z coordinate must be 0 (2D meshes in the x-y plane).
#pragma once

#include "fdem/mesh.h"

#include <istream>
#include <string>

namespace veridem::fdem
{

/// Reads and validates (validatedMesh) a .msh file. Throws InputError "file:line: what is wrong".
TriangleMesh readGmsh(const std::string& path);

/// Same, from a stream; `source` names it in messages.
TriangleMesh readGmsh(std::istream& in, const std::string& source);

} // namespace veridem::fdem
