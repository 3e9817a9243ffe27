#include "fdem/gmsh_reader.h"

#include "core/error.h"
#include "io/gmsh_file.h"

#include <cmath>
#include <fstream>

namespace veridem::fdem
{

namespace
{

/// The 2D mesh of the .msh triangles: every node they use must lie in the x-y plane.
TriangleMesh planarMesh(io::GmshTriangles read, const std::string& source)
{
    TriangleMesh mesh;
    mesh.points.reserve(read.nodes.size());
    for (std::size_t i = 0; i < read.nodes.size(); ++i)
    {
        const Vec3& p = read.nodes[i];
        if (std::abs(p.z) > 1e-12 * (1 + std::abs(p.x) + std::abs(p.y)))
            throw InputError(source + ": node " + std::to_string(read.nodeTags[i]) +
                             " has z = " + std::to_string(p.z) + "; a 2D mesh must lie in the x-y plane");
        mesh.points.push_back({p.x, p.y});
    }
    mesh.triangles = std::move(read.triangles);
    return validatedMesh(std::move(mesh), source);
}

} // namespace

TriangleMesh readGmsh(std::istream& in, const std::string& source)
{
    return planarMesh(io::readGmshTriangles(in, source), source);
}

TriangleMesh readGmsh(const std::string& path)
{
    return planarMesh(io::readGmshTriangles(path), path);
}

} // namespace veridem::fdem
