// A triangle-mesh wall: a TriangleMesh kept in its body frame, placed in the world by the wall's
// translation and an accumulated rotation about the rotation centre,
//   x_world = pivot + displacement + R (x_body - pivot),
// so a particle is mapped into the body frame for every query and the mesh's grid never changes.
//
// Contacts of a sphere with the surface (meshContacts). Each triangle gives its closest point to
// the centre, on its face, an edge or a vertex (closestPointOnTriangle). On a connected surface the
// same touch is then seen by several triangles, and a sphere straddling the shared edge of two
// coplanar triangles would feel two contacts. The contact-elimination rules of Kremmer & Favier
// (2001) as refined by Su, Gu, Zhou & Shen (2011) and Hu, Hu, Jin & Wang (2013) remove them: a face
// contact suppresses the contacts with its triangle's edges and vertices, an edge contact those
// with its end vertices, and the duplicate edge and vertex contacts reported by adjacent triangles
// are merged. They are applied here in their local, equivalent form, which also covers features
// that are not of the same triangle (a fan of slivers): a contact with an edge or vertex is kept
// only if its closest point is a local minimum of the distance over the whole surface, i.e. the
// centre lies in the feature's Voronoi region: for an edge, not over the inside of any triangle
// using it (dot(c - q, inward) <= 0 for each); for a vertex, not beyond it along any of its edges.
// A face contact always is one. Contacts of one feature (an edge seen by both its triangles) and
// contacts whose normals agree to 1e-12 (an edge hit exactly on the line between two coplanar
// faces, within round-off of the face contact) are merged, faces first, then the deeper. Several
// distinct contacts remain possible: a sphere in a concave corner of one mesh touches both faces.
// The normal is the closest-point normal (centre minus closest point, normalised; the face normal
// on a face), the overlap r - distance, and R* = r (the wall is taken as flat at the contact).
#pragma once

#include "core/hot.h"
#include "core/vec3.h"
#include "dem/walls/triangle_mesh.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <memory>
#include <vector>

namespace veridem::dem
{

struct WallGap;

/// Contact slots per (particle, mesh wall) candidate: the distinct contacts one sphere may have
/// with one mesh at a time (three in a cube's corner, one spare). Beyond it the shallowest
/// contacts are dropped (meshContacts keeps the deepest kMeshSlots).
inline constexpr int kMeshSlots = 4;

struct MeshShape
{
    std::shared_ptr<const TriangleMesh> mesh;                                  // body frame [m]
    Vec3 pivot;                                                                // rotation centre at t = 0 [m]
    std::array<Vec3, 3> rotation{Vec3{1, 0, 0}, Vec3{0, 1, 0}, Vec3{0, 0, 1}}; // rows of R
    Real turned = 0;         // accumulated rotation angle since t = 0 [rad]
    Real farthestVertex = 0; // largest vertex distance from the pivot [m]
};

/// Rotates the mesh by the rotation vector `angle` [rad] (omega dt) about its pivot.
void rotateMesh(MeshShape& shape, const Vec3& angle);

/// A world point x [m] in the mesh's body frame (offset: the wall's displacement [m]).
inline Vec3 bodyPoint(const MeshShape& s, const Vec3& offset, const Vec3& x)
{
    const Vec3 d = x - s.pivot - offset;
    return s.pivot + (d.x * s.rotation[0] + d.y * s.rotation[1] + d.z * s.rotation[2]);
}

/// A body-frame direction in the world.
inline Vec3 worldDirection(const MeshShape& s, const Vec3& v)
{
    return {dot(s.rotation[0], v), dot(s.rotation[1], v), dot(s.rotation[2], v)};
}

struct MeshContact
{
    Real overlap;    // [m]
    Vec3 normal;     // unit, world frame, from the surface towards the centre
    Vec3 bodyNormal; // the same in the body frame
};

/// The contact of a sphere of radius r [m] whose centre is at signed distance s [m] along the
/// unit normal n from a plane, from either side: the overlap r - |s| [m] and the normal sign(s) n
/// (n if s = 0). False if |s| >= r.
VERIDEM_HOT_INLINE bool signedPlaneContact(Real s, const Vec3& n, Real r, Real& overlap, Vec3& normal)
{
    const Real d = std::fabs(s);
    if (!(d < r))
        return false;
    overlap = r - d;
    normal = s < 0 ? -n : n;
    return true;
}

/// The contact of the body-frame point p (a sphere's centre, radius r [m]) with the plane of
/// triangle t: signedPlaneContact at s = (p - a).n, with a its first corner and n its normal
/// (the body-frame normal). A face contact of meshContacts (which takes s from
/// triangleFartherThan: the same operations on the same values), and the whole contact of a
/// flat candidate (meshPatchFlat).
VERIDEM_HOT_INLINE bool trianglePlaneContact(const TriangleMesh& m, std::uint32_t t, const Vec3& p, Real r,
                                             Real& overlap, Vec3& bodyNormal)
{
    return signedPlaneContact(dot(p - m.vertices[m.triangles[t][0]], m.normals[t]), m.normals[t], r, overlap,
                              bodyNormal);
}

/// True if triangle t is certainly farther than r [m] from the body-frame point p [m]: a lower
/// bound of the distance, sqrt(s^2 + o^2) with s the distance from the triangle's plane and o the
/// largest distance of p outside the three half-planes bounded by its edges (inward normals, in
/// the plane), exceeds r by more than the bound's rounding (a relative 1e-10 of the lengths
/// involved), so no contact meshContacts would keep is skipped. A few dot products on the
/// triangle's Bound record instead of closestPointOnTriangle for most listed triangles (those
/// near but not touching); the plane distance alone decides first when it suffices. With
/// pa = p - v[0], edge e's outside distance is -(p - v[e]).inward[e]: -pa.inward[e] for edges 0
/// and 2 (through v[0]), and -pa.inward[1] - apexHeight for edge 1. Sets planeDistance to the
/// signed s = pa.n [m].
VERIDEM_HOT_INLINE bool triangleFartherThan(const TriangleMesh& m, std::uint32_t t, const Vec3& p, Real r,
                                            Real& planeDistance)
{
    const TriangleMesh::Bound& tb = m.bounds[t];
    const Vec3 pa = p - tb.corner;
    const Real margin = 1e-10 * (r + std::fabs(pa.x) + std::fabs(pa.y) + std::fabs(pa.z) + tb.apexHeight);
    const Real reach = (r + margin) * (r + margin);
    const Real s = dot(pa, tb.normal);
    planeDistance = s;
    if (s * s > reach)
        return true;
    const Real o = std::max(
        {Real(0), -dot(pa, tb.inward[0]), -dot(pa, tb.inward[1]) - tb.apexHeight, -dot(pa, tb.inward[2])});
    return s * s + o * o > reach;
}

/// The contacts of a sphere (centre x, radius r [m]) with the mesh after contact elimination
/// (header comment), deepest first, at most kMeshSlots; returns their number. Looks the
/// triangles near the sphere up in the mesh's grid.
int meshContacts(const MeshShape& shape, const Vec3& offset, const Vec3& x, Real r, MeshContact* out);
/// The same among the triangles near[0, nearCount) (ascending ids), which must include every
/// triangle the sphere touches (a candidate's list from meshTrianglesNear, kept while the relative
/// motion stays within the reach it was made with): the same contacts, without the grid lookup.
int meshContacts(const MeshShape& shape, const Vec3& offset, const Vec3& x, Real r, const std::uint32_t* near,
                 std::size_t nearCount, MeshContact* out);

/// A contact of meshContacts in the body frame: what the slot matching reads (its world normal is
/// worldDirection of bodyNormal), and the feature it is with (for the elimination: rank 0 a face,
/// 1 an edge, 2 a vertex; feature its triangle, edge or vertex id).
struct MeshBodyContact
{
    Vec3 bodyNormal; // unit, body frame, from the surface towards the centre
    Real overlap;    // [m]
    int rank;
    std::uint32_t feature;
};
/// Room for the candidate contacts of one query, left uninitialised (an array of MeshBodyContact
/// would zero its 1.3 KB on every query; only the entries written are read).
inline constexpr int kMaxMeshFound = 32;
union MeshContactBuffer
{
    MeshContactBuffer() {}
    MeshBodyContact item[kMaxMeshFound];
};
/// meshContacts in the body frame (the same contacts, in the same order, at most kMeshSlots) in
/// found.item, without and with a candidate's triangle list. (The slot matching reads them where
/// the query wrote them: a copy read back at once costs store-forwarding stalls.)
int meshBodyContacts(const MeshShape& shape, const Vec3& offset, const Vec3& x, Real r,
                     MeshContactBuffer& found);
int meshBodyContacts(const MeshShape& shape, const Vec3& offset, const Vec3& x, Real r,
                     const std::uint32_t* near, std::size_t nearCount, MeshContactBuffer& found);

/// The deepest contact of a sphere with the mesh (for single-gap uses: diagnostics, initial
/// overlap checks). The force stage takes all of them (WallContactList::meshGaps).
WallGap wallGap(const MeshShape& shape, const Vec3& offset, const Vec3& x, Real r);

/// Appends to `out` the triangles (ascending ids) within r + reach [m] of the centre x [m]: the
/// only ones the sphere can touch while its motion relative to the mesh stays below `reach`.
/// Returns how many were appended.
std::size_t meshTrianglesNear(const MeshShape& shape, const Vec3& offset, const Vec3& x, Real r, Real reach,
                              std::vector<std::uint32_t>& out);

/// True if the triangles near[0, nearCount) (a candidate's list: those within r + reach [m] of the
/// centre x [m], meshTrianglesNear) form a flat patch that covers the disc (plane of the patch) x
/// ball(x, r + reach): every vertex of them lies within kFlatSlack times the mesh's size of the
/// plane of near[0] (coplanar to round-off; their normals then agree up to sign), and every edge
/// of them that comes within r + reach of x has exactly two users, both listed, on opposite sides
/// of it (an interior edge). Why that covers the disc, and why the sphere's only contact until the
/// next rebuild is then the plane contact of near[0] (trianglePlaneContact): wall_contacts.h.
bool meshPatchFlat(const MeshShape& shape, const Vec3& offset, const Vec3& x, Real r, Real reach,
                   const std::uint32_t* near, std::size_t nearCount);

/// Coplanarity slack of meshPatchFlat, relative to the mesh's bounding-box diagonal: a vertex
/// farther than this from the patch's plane makes the patch not flat. Vertices written as exact
/// coplanar coordinates land on the plane to a few ulps of the mesh's extent (~1e-16 relative);
/// 1e-12 leaves room for meshes transformed by a rotation or read from text, and moves a contact
/// by at most 1e-12 of the mesh size (1e-13 m for a 0.1 m mesh: below 1e-7 of a typical overlap).
inline constexpr Real kFlatSlack = 1e-12;

/// True if the sphere is within `reach` [m] of the mesh surface (the candidate-list test).
bool wallNear(const MeshShape& shape, const Vec3& offset, const Vec3& x, Real r, Real reach);

} // namespace veridem::dem
