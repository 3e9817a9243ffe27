// Refusal of 2D bodies that overlap at the start. Overlapping bodies would be thrown apart by the
// penalty contact in the first steps (at tens of m/s), so a scene in which they overlap is an
// input error. Bodies that only touch (a shared boundary, a corner on an edge) are accepted.
#pragma once

#include "fdem/mesh.h"

#include <string>
#include <vector>

namespace veridem::fdem
{

/// Throws InputError naming `file`, the two bodies and a point of the overlap if any two of the
/// meshes overlap by more than a rounding tolerance (1e-9 of the pair's size).
void checkBodiesApart(const std::vector<const TriangleMesh*>& meshes, const std::vector<std::string>& names,
                      const std::string& file);

} // namespace veridem::fdem
