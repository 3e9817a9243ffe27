// Stage 4b of the step (declared in dem/forces.h): the wall contacts of each particle, in slot
// order (WallContactList), through the contact law: in lanes a batch at a time (dem/exec/law_batch.h)
// or one at a time through the general law, with the same bits. A wall contact's frame: the gap of
// the wall's shape (wallGap, dem/walls/wall.h) and wallContactFrame (dem/contact_frame.h: the lever
// arm, the contact-point velocity against the wall's surface velocity at the half step). Passes:
// planes and meshes only (frames once per step; a flat mesh slot is its plane, flatSlotGap; a
// general mesh group is matched once at its first slot, matchMeshGroupAt), any walls in lanes
// (frames once per call), and the scalar path; the same bits from each. Every pass assembles a
// contact's force and torque with dem/contact_assembly.h and builds its input with
// dem/contact_input.h; a batch of one (particle, wall) material pair takes its law broadcast.
#include "dem/contact_assembly.h"
#include "dem/contact_frame.h"
#include "dem/contact_input.h"
#include "dem/contact_law.h"
#include "dem/exec/law_batch.h"
#include "dem/forces.h"
#include "exec/isa.h"

#include <cmath>
#include <optional>
#include <vector>

namespace veridem::dem
{

namespace
{

using namespace batch; // LawBatch, kBatch, lawLanes, UniformLaw (dem/exec/law_batch.h)

/// The law of a batch of wall contacts in lanes (a wall is a partner of infinite mass: m* = m).
using WallLaw = void (*)(LawBatch&, std::size_t, Real, const LawParams*);

[[gnu::noinline]] VERIDEM_AVX2_TARGET void wallLawAvx2(LawBatch& b, std::size_t count, Real dt,
                                                       const LawParams* uniform)
{
    lawLanes<Lanes4, false>(b, count, dt, uniform);
}

[[gnu::noinline]] void wallLawPortable(LawBatch& b, std::size_t count, Real dt, const LawParams* uniform)
{
    lawLanes<Lanes2, false>(b, count, dt, uniform);
}

/// The gap of wall slot k for the sphere (x, r [m]): the wall shape's (wallGap), or for a mesh wall
/// the contact matched to the slot (WallContactList::meshSlotGap; a slot taken over by a new contact
/// starts with a fresh history).
VERIDEM_HOT_INLINE WallGap slotGap(WallContactList& list, std::size_t k, const Wall& wall, const Vec3& x,
                                   Real r, std::optional<WallContactList::MeshGroup>& group,
                                   ContactHistoryStore& history)
{
    if (!std::holds_alternative<MeshShape>(wall.shape)) [[likely]]
        return wallGap(wall, x, r);
    if (!group)
        group.emplace();
    const WallGap gap = list.meshSlotGap(k, wall, x, r, *group);
    if (group->isFresh(k - group->first))
        history.forget(k);
    return gap;
}

/// Folds the overlap [m] of a touching wall contact of particle i (radius [m]) into `health`: the
/// first contact of the largest overlap ratio is kept.
VERIDEM_HOT_INLINE void foldWallOverlap(std::uint32_t i, Real overlap, Real radius, ContactHealth& health)
{
    const Real ratio = overlap / radius;
    if (ratio > health.maxOverlapRatio)
        health = {ratio, i, true, health.touching};
}

/// Records slot k's force [N] on particle i (at x [m]) and torque [N m] for the wall loads
/// (WallContactList::recordLoads): the force and its moment about the origin plus the torque.
VERIDEM_HOT_INLINE void recordWallLoad(WallContactList& list, std::size_t k, const Vec3& x, const Vec3& force,
                                       const Vec3& torque)
{
    list.loadForce[k] = force;
    list.loadMoment[k] = cross(x, force) + torque;
}

/// Zeroes the load record of slots [first, last) before a pass (the touching ones are written).
void clearWallLoads(WallContactList& list, std::size_t first, std::size_t last)
{
    for (std::size_t k = first; k < last; ++k)
        list.loadForce[k] = list.loadMoment[k] = Vec3{};
}

/// Adds one wall contact's force and torque to particle i and folds its overlap into `health`.
void addWallContact(ParticleStore& p, std::uint32_t i, const Vec3& force, const Vec3& torque, Real overlap,
                    ContactHealth& health)
{
    p.force[i] += force;
    p.torque[i] += torque;
    foldWallOverlap(i, overlap, p.radius[i], health);
}

/// A wall as the general lane pass reads it, made once per call: its motion at the half step
/// (surfaceMotion at -dt/2, as wallContactInput takes it), and for a plane its geometry
/// (planeGeometry; not `active`: no contact, as wallGap), for a mesh its shape. The same values as
/// made per contact, so the same bits.
struct WallFrame
{
    SurfaceMotion motion;
    const MeshShape* mesh;
    bool isPlane, active;
    PlaneGeometry plane;
};

/// computeWallForces when every contact takes the lane law: the inputs are computed per contact
/// (wallContactInput), the law runs in lanes a batch at a time, and the results are added in
/// slot order, so the sums and bits are those of the scalar path. A flat mesh slot goes straight
/// to its plane (WallContactList::flatSlotGap), without the group matching.
ContactHealth wallForcesInLanes(World& world, Real dt, std::size_t begin, std::size_t end)
{
    ParticleStore& p = world.particles;
    WallContactList& list = world.wallContacts;
    ContactHistoryStore& history = world.wallHistory;
    ContactHealth health{0, 0, false, 0};
    const bool loads = list.recordLoads;
    const std::optional<UniformLaw> single = uniformLaw(world);
    const UniformLaw* const uniform = single ? &*single : nullptr;
    const BatchLaws perBatch = batchLaws(world, uniform);
    std::optional<WallContactList::MeshGroup> group; // (made on the first mesh slot only)
    const WallLaw kernel = exec::isAvx2() ? wallLawAvx2 : wallLawPortable;
    std::vector<WallFrame> frames(world.walls.size());
    for (std::size_t w = 0; w < frames.size(); ++w)
    {
        const Wall& wall = world.walls[w];
        const PlaneShape* plane = std::get_if<PlaneShape>(&wall.shape);
        frames[w] = {surfaceMotion(wall, -0.5 * dt), std::get_if<MeshShape>(&wall.shape), plane != nullptr,
                     wallActive(wall), plane ? planeGeometry(*plane, wall.displacement) : PlaneGeometry{}};
    }
    LawBatch b;
    std::uint32_t particleMaterial[kBatch], wallMaterial[kBatch]; // of each contact (lawOfContacts)
    std::size_t m = 0;
    const auto run = [&]
    {
        const UniformLaw* const law =
            lawOfContacts(world, perBatch, uniform, b, m, particleMaterial, wallMaterial);
        kernel(b, m, dt, law ? &law->params : nullptr);
        for (std::size_t q = 0; q < m; ++q)
        {
            const std::uint32_t i = b.particle[q];
            const Vec3 normal{b.nx[q], b.ny[q], b.nz[q]}, tangential{b.ftx[q], b.fty[q], b.ftz[q]};
            history.set(b.slot[q],
                        ContactHistory{{b.springX[q], b.springY[q], b.springZ[q]}, b.rollingSpringOf(q)});
            const Vec3 f = contactForceOf<Real>(normal, b.normalForce[q], tangential),
                       t = wallContactTorque(b.rollingTorqueOf(q), wallArm(p.radius[i], normal), tangential);
            if (loads)
                recordWallLoad(world.wallContacts, b.slot[q], p.position[i], f, t);
            addWallContact(p, i, f, t, b.overlap[q], health);
        }
        m = 0;
        b.models = 0;
    };
    for (std::size_t k = list.start[begin]; k < list.start[end]; ++k)
    {
        const std::uint32_t i = list.particle[k];
        const std::uint32_t w = list.wall[k];
        const WallFrame& frame = frames[w];
        WallGap gap;
        if (frame.isPlane)
            gap = frame.active ? wallGap(frame.plane, p.position[i], p.radius[i]) : WallGap{};
        else if (frame.mesh && list.meshFlat[k] != WallContactList::kNotFlat)
        {
            bool fresh;
            gap = list.flatSlotGap(k, *frame.mesh, world.walls[w].displacement, p.position[i], p.radius[i],
                                   list.meshNormal[k], fresh);
            if (fresh)
                history.forget(k);
        }
        else
            gap = slotGap(list, k, world.walls[w], p.position[i], p.radius[i], group, history);
        if (!gap.touching)
        {
            history.forget(k);
            continue;
        }
        ++health.touching;
        const Wall& wall = world.walls[w];
        const ContactInput in = wallContactInput(particleState(p, i), frame.motion, gap, dt);
        b.setInputs(m, k, i, in.normal, in.overlap, in.relativeVelocity, in.effectiveMass, history.spring[k]);
        particleMaterial[m] = p.material[i];
        wallMaterial[m] = wall.material;
        if (!uniform || uniform->models != 1u) // (as wallContactScalar)
            b.setRollingInputs(m, in, history.keepRolling ? history.rolling[k] : Vec3{});
        if (++m == kBatch)
            run();
    }
    if (m > 0)
        run();
    return health;
}

/// A wall as the plane-wall pass reads it: a plane's geometry (planeGeometry) or a mesh's shape
/// (`mesh`, else null), and its motion at the half step (surfaceMotion at -dt/2, as
/// wallContactInput), made once per step.
struct PlaneFrame
{
    PlaneGeometry geometry;
    SurfaceMotion motion;
    std::uint32_t material;
    const MeshShape* mesh;
};

constexpr std::size_t kMaxPlaneFrames = 16; // more walls than this take the general pass

/// The frames of `walls` at the half step; false if some wall is neither a plane nor a mesh or
/// there are more than kMaxPlaneFrames. `meshes`: whether some wall is a mesh.
bool planeFrames(const std::vector<Wall>& walls, Real dt, PlaneFrame* frames, bool& meshes)
{
    meshes = false;
    if (walls.size() > kMaxPlaneFrames)
        return false;
    for (std::size_t w = 0; w < walls.size(); ++w)
    {
        const Wall& wall = walls[w];
        const PlaneShape* plane = std::get_if<PlaneShape>(&wall.shape);
        const MeshShape* mesh = std::get_if<MeshShape>(&wall.shape);
        if (!plane && !mesh)
            return false;
        meshes = meshes || mesh;
        frames[w] = {plane ? planeGeometry(*plane, wall.displacement) : PlaneGeometry{},
                     surfaceMotion(wall, -0.5 * dt), wall.material, mesh};
    }
    return true;
}

/// The inputs beyond the linear law's of the plane-wall contacts [0, count) of `b` (as
/// wallContactInput and wallContactScalar: a plane's R* is r), out of the hot loop.
[[gnu::noinline]] void planeExtraInputs(const World& world, const PlaneFrame* frames, LawBatch& b,
                                        std::size_t count)
{
    const ParticleStore& p = world.particles;
    const WallContactList& list = world.wallContacts;
    const ContactHistoryStore& history = world.wallHistory;
    for (std::size_t q = 0; q < count; ++q)
    {
        const std::uint32_t i = b.particle[q];
        const std::size_t k = b.slot[q];
        const Real r = p.radius[i];
        ContactInput in;
        in.effectiveRadius = r;
        setWallRollingInput(in, p.angularVelocity[i], p.mass[i], p.invInertia[i], r,
                            frames[list.wall[k]].motion.angularVelocity);
        b.setRollingInputs(q, in, history.keepRolling ? history.rolling[k] : Vec3{});
    }
}

/// The gap of flat mesh slot k in the plane-wall pass, as wallForcesInLanes takes it: its plane
/// (forgetting a replaced contact's history). (A general group is matched whole in the pass.)
VERIDEM_HOT_INLINE WallGap meshSlotGapInPass(World& world, std::size_t k, const MeshShape& shape,
                                             const Vec3& x, Real r)
{
    WallContactList& list = world.wallContacts;
    bool fresh;
    const WallGap gap =
        list.flatSlotGap(k, shape, world.walls[list.wall[k]].displacement, x, r, list.meshNormal[k], fresh);
    if (fresh)
        world.wallHistory.forget(k);
    return gap;
}

/// wallForcesInLanes for plane walls (frames from planeFrames): the same gap (wallGap of the plane's
/// geometry) and contact frame (wallContactFrame) with the wall's part made once per step, so the
/// same operations on the same values and the same bits. With kMeshes, some walls are meshes: a
/// flat slot's gap is its plane's (WallContactList::flatSlotGap), another mesh slot's the matched
/// contact (slotGap); a mesh contact's frame is a plane's (R* = r, arm -r n). Inlined into an
/// instruction-set variant below (three-operand AVX encodings of the same scalar operations for
/// the AVX2 one).
template <class Lanes, bool kMeshes>
VERIDEM_HOT_INLINE ContactHealth planeWallForcesBody(World& world, Real dt, std::size_t begin,
                                                     std::size_t end, const PlaneFrame* frames)
{
    ParticleStore& p = world.particles;
    const WallContactList& list = world.wallContacts;
    ContactHistoryStore& history = world.wallHistory;
    ContactHealth health{0, 0, false, 0};
    const std::optional<UniformLaw> single = uniformLaw(world);
    const UniformLaw* const uniform = single ? &*single : nullptr;
    const BatchLaws perBatch = batchLaws(world, uniform);
    const bool extraInputs = !uniform || uniform->models != 1u; // some model beyond the linear law's
    const Vec3* const position = p.position.data();
    const Vec3* const velocity = p.velocity.data();
    const Vec3* const angularVelocity = p.angularVelocity.data();
    const Real* const radius = p.radius.data();
    const Real* const mass = p.mass.data();
    PaddedVec3* const force = p.force.data();
    PaddedVec3* const torque = p.torque.data();
    const std::uint32_t* const particle = list.particle.data();
    const std::uint32_t* const wallOf = list.wall.data();
    Vec3* const spring = history.spring.data();
    const bool rolling = history.keepRolling;
    const bool loads = list.recordLoads;
    const Real halfStep = 0.5 * dt;
    std::optional<WallContactList::MeshGroup> group; // (kMeshes only: the general mesh group at hand)
    if constexpr (kMeshes)
        group.emplace();
    LawBatch b;
    std::uint32_t particleMaterial[kBatch], wallMaterial[kBatch]; // of each contact (lawOfContacts)
    std::size_t m = 0;
    // (Inlined: a lambda's own function would not have the caller's instruction set.)
    const auto run = [&]() __attribute__((always_inline))
    {
        const UniformLaw* const law =
            lawOfContacts(world, perBatch, uniform, b, m, particleMaterial, wallMaterial);
        if (extraInputs)
            planeExtraInputs(world, frames, b, m);
        // (The law in its own function: inlined here, its register pressure spilled this loop.)
        if constexpr (kWidth<Lanes> == 4)
            wallLawAvx2(b, m, dt, law ? &law->params : nullptr);
        else
            wallLawPortable(b, m, dt, law ? &law->params : nullptr);
        for (std::size_t q = 0; q < m; ++q)
        {
            const std::uint32_t i = b.particle[q];
            const Vec3 normal{b.nx[q], b.ny[q], b.nz[q]}, tangential{b.ftx[q], b.fty[q], b.ftz[q]};
            if (rolling)
                history.set(b.slot[q],
                            ContactHistory{{b.springX[q], b.springY[q], b.springZ[q]}, b.rollingSpringOf(q)});
            else
                spring[b.slot[q]] = {b.springX[q], b.springY[q], b.springZ[q]};
            const Vec3 f = contactForceOf<Real>(normal, b.normalForce[q], tangential),
                       t = wallContactTorque(b.rollingTorqueOf(q), wallArm(radius[i], normal), tangential);
            force[i].x += f.x;
            force[i].y += f.y;
            force[i].z += f.z;
            torque[i].x += t.x;
            torque[i].y += t.y;
            torque[i].z += t.z;
            if (loads)
                recordWallLoad(world.wallContacts, b.slot[q], position[i], f, t);
            foldWallOverlap(i, b.overlap[q], radius[i], health);
        }
        m = 0;
        b.models = 0;
    };
    // Slot k of particle i (at x, radius r) against the wall of `frame` with gap `gap`: into the
    // batch if touching, else its history cleared.
    const auto add = [&](std::size_t k, std::uint32_t i, const Vec3& x, Real r, const PlaneFrame& frame,
                         const WallGap& gap) VERIDEM_INLINE_LAMBDA
    {
        if (!gap.touching)
        {
            spring[k] = Vec3{};
            if (rolling)
                history.forget(k);
            return;
        }
        ++health.touching;
        const ContactFrameOf<Real> contact = wallContactFrame(gap.normal, gap.overlap, x, velocity[i],
                                                              angularVelocity[i], r, frame.motion, halfStep);
        b.setInputs(m, k, i, gap.normal, gap.overlap, contact.relativeVelocity, mass[i], spring[k]);
        particleMaterial[m] = p.material[i];
        wallMaterial[m] = frame.material;
        if (++m == kBatch)
            run();
    };
    for (std::size_t k = list.start[begin]; k < list.start[end]; ++k)
    {
        const std::uint32_t i = particle[k];
        const PlaneFrame& frame = frames[wallOf[k]];
        const Vec3 x = position[i];
        const Real r = radius[i];
        if constexpr (kMeshes)
            if (frame.mesh && list.meshFlat[k] == WallContactList::kNotFlat)
            {
                // A general mesh group, entered at its first slot (the loop starts at a particle's
                // first slot and steps over whole groups, which do not straddle particles): its
                // contacts matched once, then its slots in order, as slotGap hands them out.
                world.wallContacts.matchMeshGroupAt(k, world.walls[wallOf[k]], x, r, *group);
                const std::size_t groupEnd = group->first + group->size;
                for (; k < groupEnd; ++k)
                {
                    const std::size_t q = k - group->first;
                    if (group->isFresh(q))
                        history.forget(k);
                    if (group->touching >> q & 1u)
                        add(k, i, x, r, frame, group->gap[q]);
                    else
                        add(k, i, x, r, frame, WallGap{});
                }
                --k; // (the loop's ++k moves on to the next candidate)
                continue;
            }
        WallGap gap;
        if constexpr (kMeshes)
            gap = frame.mesh ? meshSlotGapInPass(world, k, *frame.mesh, x, r) : wallGap(frame.geometry, x, r);
        else
            gap = wallGap(frame.geometry, x, r);
        add(k, i, x, r, frame, gap);
    }
    if (m > 0)
        run();
    return health;
}

VERIDEM_AVX2_TARGET ContactHealth planeWallForcesAvx2(World& world, Real dt, std::size_t begin,
                                                      std::size_t end, const PlaneFrame* frames)
{
    return planeWallForcesBody<Lanes4, false>(world, dt, begin, end, frames);
}

ContactHealth planeWallForcesPortable(World& world, Real dt, std::size_t begin, std::size_t end,
                                      const PlaneFrame* frames)
{
    return planeWallForcesBody<Lanes2, false>(world, dt, begin, end, frames);
}

VERIDEM_AVX2_TARGET ContactHealth planeMeshWallForcesAvx2(World& world, Real dt, std::size_t begin,
                                                          std::size_t end, const PlaneFrame* frames)
{
    return planeWallForcesBody<Lanes4, true>(world, dt, begin, end, frames);
}

ContactHealth planeMeshWallForcesPortable(World& world, Real dt, std::size_t begin, std::size_t end,
                                          const PlaneFrame* frames)
{
    return planeWallForcesBody<Lanes2, true>(world, dt, begin, end, frames);
}

/// Wall contact k of the particle whose state is `s`, through the general contact law (any
/// model; `group`: the mesh contacts being matched to their slots, WallContactList::meshSlotGap): updates the
/// contact's history (cleared if it is not touching); if it touches, adds its force [N] and torque [N m] to
/// `force` and `torque` and folds it into `health`.
VERIDEM_HOT_INLINE void wallContactScalar(World& world, Real dt, std::size_t k, std::uint32_t i,
                                          const ParticleState& s, Vec3& force, Vec3& torque,
                                          ContactHealth& health,
                                          std::optional<WallContactList::MeshGroup>& group)
{
    const Wall& wall = world.walls[world.wallContacts.wall[k]];
    ContactHistoryStore& store = world.wallHistory;
    const WallGap gap = slotGap(world.wallContacts, k, wall, s.position, s.radius, group, store);
    if (!gap.touching)
    {
        store.forget(k);
        return;
    }
    ++health.touching;
    const PairParams& params = world.pairs(s.material, wall.material);
    const ContactInput in = wallContactInput(s, surfaceMotion(wall, -0.5 * dt), gap, dt);
    ContactHistory history = store.at(k);
    const ContactOutput out = evaluateContact(params, in, history, dt);
    store.set(k, history);
    const Vec3 contactTorque =
        wallContactTorque(out.rollingTorque, wallArm(s.radius, gap.normal), out.tangentialForce);
    if (world.wallContacts.recordLoads)
        recordWallLoad(world.wallContacts, k, s.position, out.force, contactTorque);
    force += out.force;
    torque += contactTorque;
    foldWallOverlap(i, in.overlap, s.radius, health);
}

} // namespace

ContactHealth computeWallForces(World& world, Real dt, std::size_t begin, std::size_t end)
{
    ParticleStore& p = world.particles;
    WallContactList& list = world.wallContacts;
    ContactHealth health{0, 0, false, 0};
    if (list.size() == 0 || list.start.size() != p.size() + 1)
        return health;
    if (list.recordLoads)
        clearWallLoads(list, list.start[begin], list.start[end]);
    if (world.exec.batchedContactKernel && world.wallHistory.scalarCount == 0) // (as the pairs')
    {
        PlaneFrame frames[kMaxPlaneFrames];
        bool meshes;
        if (!planeFrames(world.walls, dt, frames, meshes))
            return wallForcesInLanes(world, dt, begin, end);
        if (meshes)
            return exec::isAvx2() ? planeMeshWallForcesAvx2(world, dt, begin, end, frames)
                                  : planeMeshWallForcesPortable(world, dt, begin, end, frames);
        return exec::isAvx2() ? planeWallForcesAvx2(world, dt, begin, end, frames)
                              : planeWallForcesPortable(world, dt, begin, end, frames);
    }
    std::optional<WallContactList::MeshGroup> group; // (made on the first mesh slot only)
    for (std::size_t k = list.start[begin]; k < list.start[end]; ++k)
    {
        const std::uint32_t i = list.particle[k];
        wallContactScalar(world, dt, k, i, particleState(p, i), p.force[i], p.torque[i], health, group);
    }
    return health;
}

ContactHealth wallContactsOf(World& world, Real dt, std::uint32_t i, const ParticleState& s, Vec3& force,
                             Vec3& torque)
{
    WallContactList& list = world.wallContacts;
    ContactHealth health{0, 0, false, 0};
    if (list.size() == 0 || list.start.size() != world.particles.size() + 1)
        return health;
    if (list.recordLoads)
        clearWallLoads(list, list.start[i], list.start[i + 1]);
    std::optional<WallContactList::MeshGroup> group; // (made on the first mesh slot only)
    for (std::size_t k = list.start[i]; k < list.start[i + 1]; ++k)
        wallContactScalar(world, dt, k, i, s, force, torque, health, group);
    return health;
}

} // namespace veridem::dem
