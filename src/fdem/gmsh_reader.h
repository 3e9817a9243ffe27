// The 2D FEM/DEM body of a Gmsh .msh file, read by the shared reader (io/gmsh_file.h: ASCII
// formats 2.2 and 4.1, 3-node triangles kept, other elements skipped). Every node the triangles
// use must lie in the x-y plane (z = 0).
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
