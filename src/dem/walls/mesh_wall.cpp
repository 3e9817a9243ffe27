#include "dem/walls/mesh_wall.h"

#include "dem/walls/wall.h"

#include <algorithm>
#include <cmath>
#include <vector>

namespace veridem::dem
{

void rotateMesh(MeshShape& shape, const Vec3& angle)
{
    const Real theta = length(angle);
    if (!(theta > 0))
        return;
    // Rodrigues: Q v = v cos + (k x v) sin + k (k.v)(1 - cos); R <- Q R, applied to R's columns.
    const Vec3 k = angle / theta;
    const Real c = std::cos(theta), s = std::sin(theta);
    const auto q = [&](const Vec3& v) { return c * v + s * cross(k, v) + ((1 - c) * dot(k, v)) * k; };
    std::array<Vec3, 3>& R = shape.rotation;
    const Vec3 c0 = q({R[0].x, R[1].x, R[2].x}), c1 = q({R[0].y, R[1].y, R[2].y}),
               c2 = q({R[0].z, R[1].z, R[2].z});
    R[0] = {c0.x, c1.x, c2.x};
    R[1] = {c0.y, c1.y, c2.y};
    R[2] = {c0.z, c1.z, c2.z};
    // Re-orthonormalise (Gram-Schmidt on the rows) so round-off does not accumulate.
    R[0] = R[0] / length(R[0]);
    R[1] = R[1] - dot(R[1], R[0]) * R[0];
    R[1] = R[1] / length(R[1]);
    R[2] = cross(R[0], R[1]);
    shape.turned += theta;
}

namespace
{

enum Rank : int
{
    FaceRank = 0,
    EdgeRank = 1,
    VertexRank = 2
};

using Found = MeshBodyContact;

constexpr Real kVoronoiSlack = 1e-10; // relative: a centre on the boundary of two regions is in both
constexpr Real kSameNormal = 1e-12;   // 1 - cos of the angle below which two contacts are one

/// True if the centre p, at distance d from edge g's point q (p - q = diff), is not over the
/// inside of any triangle using the edge.
bool edgeRegion(const TriangleMesh& m, std::uint32_t g, const Vec3& diff, Real d)
{
    for (std::uint32_t u = m.edgeStart[g]; u < m.edgeStart[g + 1]; ++u)
        if (dot(diff, m.inward[m.edgeUsers[u] / 3][m.edgeUsers[u] % 3]) > kVoronoiSlack * d)
            return false;
    return true;
}

/// True if the centre (p - vertex v = diff, |diff| = d) is not beyond v along any of its edges.
bool vertexRegion(const TriangleMesh& m, std::uint32_t v, const Vec3& diff, Real d)
{
    for (std::uint32_t u = m.vertexStart[v]; u < m.vertexStart[v + 1]; ++u)
    {
        const Vec3 edge = m.vertices[m.vertexNeighbours[u]] - m.vertices[v];
        if (dot(diff, edge) > kVoronoiSlack * d * length(edge))
            return false;
    }
    return true;
}

/// Sorts found[0, count) by `before` (a strict weak order), stable: insertion sort, as count is a
/// handful (no allocation, unlike std::stable_sort).
template <class Before> void sortFound(Found* found, int count, Before before)
{
    for (int i = 1; i < count; ++i)
    {
        const Found f = found[i];
        int j = i;
        for (; j > 0 && before(f, found[j - 1]); --j)
            found[j] = found[j - 1];
        found[j] = f;
    }
}

/// Contacts of body-frame point p (radius r [m]) with the triangles `near` (ascending; every
/// triangle that touches the sphere among them) after elimination, deepest first, into
/// found[0, kMaxMeshFound): candidates are gathered there, then sorted and merged in place (no copy
/// when one contact is found, the common case).
int findContacts(const TriangleMesh& m, const Vec3& p, Real r, const std::uint32_t* near,
                 std::size_t nearCount, Found* found)
{
    int count = 0;
    for (std::size_t n = 0; n < nearCount; ++n)
    {
        const std::uint32_t t = near[n];
        Real planeDistance;
        if (triangleFartherThan(m, t, p, r, planeDistance))
            continue;
        const auto& tri = m.triangles[t];
        const TrianglePoint cp =
            closestPointOnTriangle(p, m.vertices[tri[0]], m.vertices[tri[1]], m.vertices[tri[2]]);
        Found f;
        if (cp.feature == MeshFeature::Face)
        {
            Real overlap;
            Vec3 normal;
            if (!signedPlaneContact(planeDistance, m.bounds[t].normal, r, overlap, normal))
                continue;
            f = {normal, overlap, FaceRank, t};
        }
        else
        {
            const Vec3 diff = p - cp.point;
            const Real d = length(diff);
            if (!(d < r))
                continue;
            const Vec3 normal = d > 0 ? diff / d : m.normals[t];
            if (cp.feature == MeshFeature::Edge)
            {
                const std::uint32_t g = m.triangleEdges[t][cp.index];
                if (!edgeRegion(m, g, diff, d))
                    continue;
                f = {normal, r - d, EdgeRank, g};
            }
            else
            {
                const std::uint32_t v = tri[cp.index];
                if (!vertexRegion(m, v, diff, d))
                    continue;
                f = {normal, r - d, VertexRank, v};
            }
        }
        bool duplicate = false;
        for (int q = 0; q < count && !duplicate; ++q)
            duplicate = found[q].rank == f.rank && found[q].feature == f.feature;
        if (!duplicate && count < kMaxMeshFound)
            found[count++] = f;
    }
    if (count <= 1)
        return count;
    // Faces first, then deeper, then by id (a deterministic order), and merge equal normals.
    sortFound(found, count,
              [](const Found& x, const Found& y)
              {
                  if (x.rank != y.rank)
                      return x.rank < y.rank;
                  if (x.overlap != y.overlap)
                      return x.overlap > y.overlap;
                  return x.feature < y.feature;
              });
    int kept = 0;
    for (int q = 0; q < count; ++q)
    {
        bool merged = false;
        for (int k = 0; k < kept && !merged; ++k)
            merged = 1 - dot(found[k].bodyNormal, found[q].bodyNormal) < kSameNormal;
        if (!merged)
        {
            if (kept != q)
                found[kept] = found[q];
            ++kept;
        }
    }
    sortFound(found, kept, [](const Found& x, const Found& y) { return x.overlap > y.overlap; });
    return kept;
}

} // namespace

int meshBodyContacts(const MeshShape& shape, const Vec3& offset, const Vec3& x, Real r,
                     const std::uint32_t* near, std::size_t nearCount, MeshContactBuffer& found)
{
    const int count = findContacts(*shape.mesh, bodyPoint(shape, offset, x), r, near, nearCount, found.item);
    return std::min(count, kMeshSlots);
}

int meshContacts(const MeshShape& shape, const Vec3& offset, const Vec3& x, Real r, const std::uint32_t* near,
                 std::size_t nearCount, MeshContact* out)
{
    MeshContactBuffer found;
    const int kept = meshBodyContacts(shape, offset, x, r, near, nearCount, found);
    for (int q = 0; q < kept; ++q)
        out[q] = {found.item[q].overlap, worldDirection(shape, found.item[q].bodyNormal),
                  found.item[q].bodyNormal};
    return kept;
}

namespace
{

/// The triangles whose grid cells meet the sphere's box (all that can touch it).
const std::vector<std::uint32_t>& gridTriangles(const MeshShape& shape, const Vec3& offset, const Vec3& x,
                                                Real r)
{
    thread_local std::vector<std::uint32_t> near;
    const Vec3 p = bodyPoint(shape, offset, x), span{r, r, r};
    shape.mesh->trianglesNear(p - span, p + span, near);
    return near;
}

} // namespace

int meshBodyContacts(const MeshShape& shape, const Vec3& offset, const Vec3& x, Real r,
                     MeshContactBuffer& found)
{
    const std::vector<std::uint32_t>& near = gridTriangles(shape, offset, x, r);
    return meshBodyContacts(shape, offset, x, r, near.data(), near.size(), found);
}

int meshContacts(const MeshShape& shape, const Vec3& offset, const Vec3& x, Real r, MeshContact* out)
{
    const std::vector<std::uint32_t>& near = gridTriangles(shape, offset, x, r);
    return meshContacts(shape, offset, x, r, near.data(), near.size(), out);
}

WallGap wallGap(const MeshShape& shape, const Vec3& offset, const Vec3& x, Real r)
{
    MeshContact c[kMeshSlots];
    WallGap g;
    if (meshContacts(shape, offset, x, r, c) == 0)
        return g;
    g.touching = true;
    g.overlap = c[0].overlap;
    g.normal = c[0].normal;
    g.effectiveRadius = r;
    return g;
}

std::size_t meshTrianglesNear(const MeshShape& shape, const Vec3& offset, const Vec3& x, Real r, Real reach,
                              std::vector<std::uint32_t>& out)
{
    const TriangleMesh& m = *shape.mesh;
    const Vec3 p = bodyPoint(shape, offset, x);
    const Real limit = r + reach;
    thread_local std::vector<std::uint32_t> near;
    m.trianglesNear(p - Vec3{limit, limit, limit}, p + Vec3{limit, limit, limit}, near);
    std::size_t added = 0;
    for (const std::uint32_t t : near)
    {
        const auto& tri = m.triangles[t];
        const TrianglePoint cp =
            closestPointOnTriangle(p, m.vertices[tri[0]], m.vertices[tri[1]], m.vertices[tri[2]]);
        if (lengthSquared(p - cp.point) < limit * limit)
        {
            out.push_back(t);
            ++added;
        }
    }
    return added;
}

bool meshPatchFlat(const MeshShape& shape, const Vec3& offset, const Vec3& x, Real r, Real reach,
                   const std::uint32_t* near, std::size_t nearCount)
{
    if (nearCount == 0)
        return false;
    const TriangleMesh& m = *shape.mesh;
    const Vec3 p = bodyPoint(shape, offset, x);
    const Vec3& normal = m.normals[near[0]];
    const Vec3& origin = m.vertices[m.triangles[near[0]][0]];
    const Real slack = kFlatSlack * m.size, limit = r + reach;
    const auto listed = [&](std::uint32_t t) { return std::binary_search(near, near + nearCount, t); };
    for (std::size_t n = 0; n < nearCount; ++n)
    {
        const std::uint32_t t = near[n];
        for (int e = 0; e < 3; ++e)
            if (!(std::fabs(dot(m.vertices[m.triangles[t][e]] - origin, normal)) <= slack))
                return false;
        for (int e = 0; e < 3; ++e)
        {
            const Vec3& a = m.vertices[m.triangles[t][e]];
            const Vec3& b = m.vertices[m.triangles[t][(e + 1) % 3]];
            const Vec3 ab = b - a;
            const Real along = std::clamp(dot(p - a, ab) / dot(ab, ab), Real(0), Real(1));
            if (!(lengthSquared(p - (a + along * ab)) < limit * limit))
                continue; // (an edge beyond r + reach: the disc does not reach it)
            const std::uint32_t g = m.triangleEdges[t][e];
            if (m.edgeStart[g + 1] - m.edgeStart[g] != 2)
                return false;
            const std::uint32_t u0 = m.edgeUsers[m.edgeStart[g]], u1 = m.edgeUsers[m.edgeStart[g] + 1];
            if (!listed(u0 / 3) || !listed(u1 / 3) ||
                !(dot(m.inward[u0 / 3][u0 % 3], m.inward[u1 / 3][u1 % 3]) < 0))
                return false;
        }
    }
    return true;
}

bool wallNear(const MeshShape& shape, const Vec3& offset, const Vec3& x, Real r, Real reach)
{
    thread_local std::vector<std::uint32_t> near;
    near.clear();
    return meshTrianglesNear(shape, offset, x, r, reach, near) > 0;
}

} // namespace veridem::dem
