// Particle-wall contact list, whose slots key the wall contacts' history (sparse: only particles
// near a wall have a slot).
//
// Candidates (particle, wall) are the pairs whose gap is below the neighbour skin (wallNear), kept
// sorted by (particle, wall) and rebuilt together with the pair list: when some particle has moved
// more than skin/2, or some wall has translated more than skin/2, since the last build. Relative
// motion is then below the skin, so no wall contact is missed. The history is a store of its own
// (ContactHistoryStore, World::wallHistory), entry k for slot k: a rebuild re-keys it by
// (particle, wall), and the force stage zeroes an entry when its contact opens.
//
// A mesh wall (walls/mesh_wall.h) may touch a sphere at several places at once (a concave
// corner), so its candidate takes kMeshSlots consecutive slots with the same (particle, wall): one
// per distinct contact. Each slot keeps the body-frame normal of its contact (meshNormal), and each
// step the contacts found are matched to the slots by that normal (meshSlotGap): the deepest first
// takes the slot whose stored normal is closest (within 60 degrees), so a contact keeps its
// tangential and rolling history while its feature changes from face to edge to the next face as
// the ball rolls on. A rebuild carries the slots of a continuing (particle, wall) in order.
//
// Flat candidates. A (particle, mesh wall) candidate whose triangles within r + skin of the centre
// x at the build (meshTrianglesNear) form a flat patch (meshPatchFlat: coplanar to round-off, and
// every edge that comes within r + skin of x interior, with two listed users on opposite sides)
// takes ONE slot, evaluated as the two-sided plane of one of its triangles (meshFlat). Why that is
// the same contact: let D be the disc plane x ball(x, r + skin) and U the union of the listed
// triangles. U holds the closest point q of some listed triangle, inside D. For any y in D the
// segment q-y lies in D (convex); were it to leave U, it would cross U's boundary at a point of D,
// on an edge (or at a vertex, whose edges all are in D) of a listed triangle; but such an edge has
// triangles on both sides (and around a vertex the fan closes), so that point is inside U: hence
// D lies in U. Until the next rebuild the sphere moves by d, |d| < skin, relative to the mesh
// (needsRebuild, and the pair list's skin/2 per particle), and only listed triangles can touch it.
// If it touches (centre height h' < r above the plane), its centre's projection is at squared
// distance |d_t|^2 + (h' + |d_n|)^2 <= (r + |d|)^2 < (r + skin)^2 from x (d_t, d_n: d's parts
// along and across the plane), so it lies in D, inside U: the closest point of the surface is that
// projection, a face contact, and meshContacts would find this one contact (the face's, to
// round-off of which coplanar triangle computes it; the edge and vertex contacts fail their
// Voronoi test). A candidate that is not flat (an edge, a corner, a border, a curved surface)
// keeps kMeshSlots slots and the general matching. Mesh groups therefore hold 1 or kMeshSlots
// slots. History follows the contact across a change at a rebuild: a general group becoming flat
// gives its flat slot the history and normal of the old slot whose normal is within 60 degrees of
// the plane's normal towards the centre (the closest), and a flat slot becoming general gives its
// history and normal to the new group's first slot (the matching then keeps it).
//
// A dense (particle x wall) history would cost 24-48 bytes per particle per wall and test every
// wall for every particle each step; a bed in a box has 5 walls and 1 in 5 particles near one.
#pragma once

#include "core/vec3.h"
#include "dem/contact_history.h"
#include "dem/particles.h"
#include "dem/walls/wall.h"

#include <cstdint>
#include <vector>

namespace veridem::dem
{

class WallContactList
{
  public:
    std::vector<std::uint32_t> particle; // sorted by (particle, wall)
    std::vector<std::uint32_t> wall;
    std::vector<std::uint32_t> start; // slots [start[p], start[p+1]) belong to particle p
    // Per slot, the body-frame unit normal of its mesh contact (zero if none); empty unless some
    // wall is a mesh.
    std::vector<Vec3> meshNormal;
    // The triangles a (particle, mesh wall) candidate can touch until the next rebuild (those
    // within r + skin at the build: meshTrianglesNear), as ranges over slots: the group's first
    // slot k holds meshTriangles[meshTriangleStart[k], meshTriangleStart[k+1]), its other slots
    // and non-mesh slots none. Empty unless some wall is a mesh, and after a restore or a
    // renaming until the next rebuild (the query then falls back to the mesh's grid: the same
    // contacts).
    std::vector<std::uint32_t> meshTriangleStart, meshTriangles;
    // Per slot, the triangle whose plane is a flat candidate's contact surface (its only slot), or
    // kNotFlat (every other slot). Empty unless some wall is a mesh; saved in checkpoints.
    static constexpr std::uint32_t kNotFlat = 0xffffffffu;
    std::vector<std::uint32_t> meshFlat;
    /// The flat slot k's contact with the sphere (x, r [m]): trianglePlaneContact of meshFlat[k];
    /// `next` is set to its signed body normal (zero if not touching: the slot's new meshNormal,
    /// which `next` may be) and `fresh` if the stored normal was not within 60 degrees of it (a
    /// new contact, as in the matching: its history must be forgotten).
    VERIDEM_HOT_INLINE WallGap flatSlotGap(std::size_t k, const MeshShape& shape, const Vec3& offset,
                                           const Vec3& x, Real r, Vec3& next, bool& fresh) const
    {
        WallGap gap;
        Vec3 bodyNormal;
        const Vec3 stored = meshNormal[k];
        fresh = false;
        if (!trianglePlaneContact(*shape.mesh, meshFlat[k], bodyPoint(shape, offset, x), r, gap.overlap,
                                  bodyNormal))
        {
            next = Vec3{};
            return gap;
        }
        fresh = lengthSquared(stored) > 0 && !(dot(stored, bodyNormal) > 0.5);
        next = bodyNormal;
        gap.touching = true;
        gap.normal = worldDirection(shape, bodyNormal);
        gap.effectiveRadius = r;
        return gap;
    }

    /// The contacts of one (particle, mesh wall) candidate matched to its slots, for a loop over
    /// slots: `first` is the group's first slot; bit q of `touching` marks slot first + q as
    /// touching with gap[q] (the other gaps are not set), bit q of `fresh` a slot taken over by a
    /// new contact (its history must be forgotten before use). (Masks, not per-slot flags and gaps
    /// zeroed for every group: the force pass reads back at once what the matching wrote, and
    /// fewer, same-width stores keep that read from stalling store-to-load forwarding.)
    struct MeshGroup
    {
        std::size_t first = ~std::size_t(0), size = 0; // size: 1 (flat) or kMeshSlots
        WallGap gap[kMeshSlots];
        std::uint32_t touching = 0, fresh = 0;
        bool isFresh(std::size_t q) const { return (fresh >> q) & 1u; }
        WallGap gapOf(std::size_t q) const { return (touching >> q) & 1u ? gap[q] : WallGap{}; }
    };
    /// The gap of slot k of a mesh wall for the sphere (x, r [m]); matches the group's contacts to
    /// its slots (and updates meshNormal) when k is in a group other than `group`'s.
    WallGap meshSlotGap(std::size_t k, const Wall& meshWall, const Vec3& x, Real r, MeshGroup& group);
    /// meshSlotGap for a loop that takes a general group whole: matches the contacts of the group
    /// whose first slot is `first` to its slots and updates meshNormal (group.gap, group.touching,
    /// group.fresh then give each slot's).
    void matchMeshGroupAt(std::size_t first, const Wall& meshWall, const Vec3& x, Real r, MeshGroup& group)
    {
        matchMeshGroup(first, meshWall, x, r, group, meshNormal.data() + first);
    }
    /// The same without updating meshNormal (after the force stage: the same assignment), for
    /// passes that only read the contacts (contact_diagnostics.cpp).
    WallGap meshSlotGapAsStored(std::size_t k, const Wall& meshWall, const Vec3& x, Real r) const;

    /// True if some wall translated more than skin/2, or switched on or off (wallActive), since
    /// the last build (or never built); a mesh wall counts its rotation as the angle turned times
    /// its farthest vertex from the pivot.
    bool needsRebuild(const std::vector<Wall>& walls, Real skin) const;
    /// Rebuilds the candidate list and re-keys `history` (its entries are the slots') by
    /// (particle, wall).
    void rebuild(const ParticleStore& particles, const std::vector<Wall>& walls, Real skin,
                 ContactHistoryStore& history);

    /// Renames the particles after some were removed between steps (dem/particle_changes.h):
    /// particle p is now newIndex[p], or gone if NeighborList::kGone. The slots keep their history
    /// under the new (particle, wall), sorted again; the rebuild() that must follow carries it.
    void renameParticles(const std::vector<std::uint32_t>& newIndex, ContactHistoryStore& history);
    /// Replaces the slots by (`particles`[k], `walls`[k]), sorted by that key (a mesh group's
    /// slots together, in order), with their mesh normals and flat triangles (both empty unless
    /// some wall is a mesh) and their history `adopted`, for particles renumbered between steps
    /// (renameParticles; an MPI rank's particles after an exchange). The rebuild() that must
    /// follow carries the history.
    void adoptSlots(std::vector<std::uint32_t> particles, std::vector<std::uint32_t> walls,
                    std::vector<Vec3> normals, std::vector<std::uint32_t> flat, ContactHistoryStore& history,
                    ContactHistoryStore&& adopted);

    /// Takes in the particles [from, particles.size()) appended between steps without a rebuild
    /// (dem/particle_changes.h, addInsertedParticles): their candidates, with fresh history, go
    /// at the end (the new particles have the highest indices, so the order is kept). They are
    /// searched within `reach` [m] of the walls' current places: 1.5 skin, since until the next
    /// rebuild a particle moves at most skin/2 from here and a wall up to skin from where it is
    /// now (skin/2 either side of where it was at the last build). The candidates are those a rebuild
    /// would make within that reach (flat mesh candidates included). O(particles appended x walls).
    void appendParticles(const ParticleStore& particles, std::size_t from, const std::vector<Wall>& walls,
                         Real reach, ContactHistoryStore& history);

    /// The slot of the contact (particle, wall) (its entry in the wall history), e.g. to start a
    /// case in a loaded contact state after prepare(). Throws InputError if the particle is not
    /// near that wall.
    std::size_t slotOf(std::uint32_t particleIndex, std::uint32_t wallIndex) const;

    /// After a restore: records the walls' current activity as that of the last build (a wall
    /// that switches on or off forces a rebuild in the step it does, so they agree).
    void markActivity(const std::vector<Wall>& walls);

    // Wall loads (recordLoads, off by default): slot k's force on its particle [N] and that
    // force's moment about the origin plus the contact's torque on the particle [N m], from the
    // last force evaluation (zero if not touching); wallLoad() sums them per wall.
    bool recordLoads = false;
    std::vector<Vec3> loadForce, loadMoment;
    /// Switches the load record on (zeroed, sized to the slots) or off.
    void setRecordLoads(bool on);

    std::size_t size() const { return particle.size(); }
    std::size_t memoryBytes() const;

  private:
    friend struct CheckpointAccess; // io/dem_checkpoint.cpp saves and restores the private state
    std::vector<Vec3> wallDisplacementAtBuild_;
    std::vector<std::uint8_t> wallActiveAtBuild_;
    std::vector<Real> wallTurnAtBuild_; // mesh walls' accumulated rotation [rad]; empty without meshes
    /// The first slot of the (particle, mesh wall) group holding slot k.
    std::size_t meshGroupFirst(std::size_t k) const;
    /// Matches the contacts of the (particle, mesh wall) group whose first slot is `first` to its
    /// slots against the stored normals: fills `group` and the slots' new normals next[0,
    /// group.size), which may be the stored normals (meshNormal + first) themselves, updated in
    /// place. A flat group's one contact is its plane's (flatSlotGap).
    void matchMeshGroup(std::size_t first, const Wall& meshWall, const Vec3& x, Real r, MeshGroup& group,
                        Vec3* next) const;
};

/// The load of wall w on the particles' side: the total force ON the wall [N] (minus the sum of
/// its contacts' forces on the particles) and its torque [N m] about `reference` [m], summed over
/// the slots in slot order (the same bits on any thread count). Needs recordLoads.
struct WallLoad
{
    Vec3 force, torque;
};
WallLoad wallLoad(const WallContactList& list, std::uint32_t w, const Vec3& reference);

} // namespace veridem::dem
