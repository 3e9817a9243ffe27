// Flat mesh candidates (wall_contacts.h): which candidates are flat (meshPatchFlat), the one slot
// they take, and the contact history carried across a change between flat and general.
#include "core/constants.h"
#include "dem/integrate.h"
#include "dem/walls/wall.h"
#include "dem/world.h"

#include <gtest/gtest.h>

#include <cmath>
#include <memory>

using namespace veridem;
using namespace veridem::dem;

namespace
{

constexpr Real kRadius = 0.01, kSkin = 1e-3; // [m]

/// The floor z = 0 over [-0.3, 0.5] x [-0.2, 0.2] m as two triangles, and a vertical fin (one
/// triangle in the plane y = 0.0104 m, x in [0, 0.05] m, up to z = 20 mm) beside the line y = 0: a
/// ball on that line within r + skin of the fin (0.0104 < 0.011 m) but never touching it.
MeshShape floorWithFin()
{
    const std::vector<Vec3> corners{{-0.3, -0.2, 0},    {0.5, -0.2, 0},      {0.5, 0.2, 0},
                                    {-0.3, -0.2, 0},    {0.5, 0.2, 0},       {-0.3, 0.2, 0},
                                    {0.0, 0.0104, 0.0}, {0.05, 0.0104, 0.0}, {0.025, 0.0104, 0.02}};
    MeshReport report; // (an open boundary: expected)
    MeshShape s;
    s.mesh = std::make_shared<const TriangleMesh>(buildTriangleMesh(corners, "floor with fin", report));
    s.farthestVertex = s.mesh->farthestVertex(s.pivot);
    return s;
}

bool flatAt(const MeshShape& shape, const Vec3& x)
{
    std::vector<std::uint32_t> near;
    const std::size_t count = meshTrianglesNear(shape, {}, x, kRadius, kSkin, near);
    return meshPatchFlat(shape, {}, x, kRadius, kSkin, near.data(), count);
}

World finWorld(const Vec3& x, const Vec3& v, Real friction, Real kn = 1e5, bool plane = false)
{
    World world;
    Material m;
    m.restitution = 1; // (no dashpot: a sliding contact's spring holds the whole Coulomb force)
    m.density = 7800;
    m.normalStiffness = kn;
    m.friction = friction;
    world.addMaterial(m);
    world.gravity = {0, 0, -kStandardGravity};
    world.neighbors.skin = kSkin;
    Wall floor;
    if (plane)
        floor.shape = PlaneShape{};
    else
        floor.shape = floorWithFin();
    world.walls.push_back(std::move(floor));
    world.particles.add(x, v, {}, kRadius, m.density, 0);
    prepare(world);
    return world;
}

std::size_t slotsOf(const World& world, std::uint32_t i)
{
    return world.wallContacts.start[i + 1] - world.wallContacts.start[i];
}

} // namespace

TEST(MeshFlat, InteriorOfAFlatPatchIsFlatAndEdgesBordersCornersAreNot)
{
    const MeshShape fin = floorWithFin();
    EXPECT_TRUE(flatAt(fin, {-0.1, 0, 0.0099}));   // on the face, far from any border or the fin
    EXPECT_TRUE(flatAt(fin, {0.1, 0.05, 0.0099})); // on the shared diagonal: an interior edge
    EXPECT_FALSE(flatAt(fin, {0.02, 0, 0.0099}));  // the fin within r + skin (not touching)
    // The disc plane x ball(x, r + skin) has the radius sqrt(0.011^2 - 0.0099^2) = 4.8 mm here.
    EXPECT_FALSE(flatAt(fin, {0.497, 0, 0.0099})); // the floor's border 3 mm away: inside the disc
    EXPECT_TRUE(flatAt(fin, {0.494, 0, 0.0099}));  // 6 mm away: beyond it

    // Six triangles about a shared vertex: the fan closes, flat; a ridge (two planes meeting at
    // 1e-3 rad) is not.
    std::vector<Vec3> hexagon, ridge;
    for (int q = 0; q < 6; ++q)
    {
        const Real a0 = kPi / 3 * q, a1 = kPi / 3 * ((q + 1) % 6);
        hexagon.insert(hexagon.end(),
                       {Vec3{}, Vec3{std::cos(a0), std::sin(a0), 0}, Vec3{std::cos(a1), std::sin(a1), 0}});
    }
    const Real h = 1e-3;
    ridge = {{-1, -1, h}, {0, -1, 0}, {0, 1, 0}, {-1, -1, h}, {0, 1, 0}, {-1, 1, h},
             {0, -1, 0},  {1, -1, h}, {1, 1, h}, {0, -1, 0},  {1, 1, h}, {0, 1, 0}};
    MeshReport report;
    MeshShape hex, roof;
    hex.mesh = std::make_shared<const TriangleMesh>(buildTriangleMesh(hexagon, "hexagon", report));
    roof.mesh = std::make_shared<const TriangleMesh>(buildTriangleMesh(ridge, "ridge", report));
    EXPECT_TRUE(flatAt(hex, {0, 0, 0.0099}));
    EXPECT_FALSE(flatAt(roof, {0, 0, 0.0099}));
    EXPECT_TRUE(flatAt(roof, {-0.5, 0, 0.0099 + 0.5 * h})); // one plane only within r + skin
}

TEST(MeshFlat, AFlatCandidateTakesOneSlotAndTheForceOfThePlane)
{
    // A ball resting on the face: one slot, and the force stage gives the analytic plane's force
    // to round-off (the same overlap and normal: the flat slot is the face contact itself).
    World mesh = finWorld({-0.1, 0, 0.0099}, {}, 0.3);
    World plane = finWorld({-0.1, 0, 0.0099}, {}, 0.3, 1e5, true);
    EXPECT_EQ(slotsOf(mesh, 0), 1u);
    step(mesh, 1e-6);
    step(plane, 1e-6);
    EXPECT_EQ(mesh.health.touchingWalls, 1u);
    EXPECT_EQ(mesh.wallContacts.meshNormal[0].z, 1.0);
    EXPECT_NEAR(mesh.particles.force[0].z, plane.particles.force[0].z, 1e-12 * plane.particles.force[0].z);
    // By the fin: kMeshSlots slots, still one contact.
    World byFin = finWorld({0.02, 0, 0.0099}, {}, 0.3);
    EXPECT_EQ(slotsOf(byFin, 0), std::size_t(kMeshSlots));
    step(byFin, 1e-6);
    EXPECT_EQ(byFin.health.touchingWalls, 1u);
}

TEST(MeshFlat, ARebuildCarriesTheHistoryOfTheMatchingSlotBothWays)
{
    World world = finWorld({0.02, 0, 0.0099}, {}, 0.3);
    WallContactList& list = world.wallContacts;
    ASSERT_EQ(list.size(), std::size_t(kMeshSlots));
    // General -> flat: the old slot whose normal is the plane's towards the centre (slot 1 here,
    // not slot 0, whose stale contact pointed along x) gives the flat slot its history.
    list.meshNormal[0] = {1, 0, 0};
    list.meshNormal[1] = {0, 0, 1};
    world.wallHistory.spring[0] = {1e-6, 0, 0};
    world.wallHistory.spring[1] = {0, 2e-6, 0};
    world.particles.position[0] = {-0.1, 0, 0.0099};
    list.rebuild(world.particles, world.walls, kSkin, world.wallHistory);
    ASSERT_EQ(list.size(), 1u);
    EXPECT_NE(list.meshFlat[0], WallContactList::kNotFlat);
    EXPECT_EQ(world.wallHistory.spring[0], (Vec3{0, 2e-6, 0}));
    EXPECT_EQ(list.meshNormal[0], (Vec3{0, 0, 1}));
    // Flat -> general: the new group's first slot.
    world.particles.position[0] = {0.02, 0, 0.0099};
    list.rebuild(world.particles, world.walls, kSkin, world.wallHistory);
    ASSERT_EQ(list.size(), std::size_t(kMeshSlots));
    EXPECT_EQ(world.wallHistory.spring[0], (Vec3{0, 2e-6, 0}));
    EXPECT_EQ(list.meshNormal[0], (Vec3{0, 0, 1}));
    for (std::size_t q = 1; q < std::size_t(kMeshSlots); ++q)
        EXPECT_EQ(world.wallHistory.spring[q], Vec3{});
    // General -> flat with no slot within 60 degrees of the plane's normal: a fresh history.
    list.meshNormal[0] = {1, 0, 0};
    world.particles.position[0] = {-0.1, 0, 0.0099};
    list.rebuild(world.particles, world.walls, kSkin, world.wallHistory);
    ASSERT_EQ(list.size(), 1u);
    EXPECT_EQ(world.wallHistory.spring[0], Vec3{});
}

TEST(MeshFlat, SlidingPastTheFinKeepsTheTangentialSpringAcrossBothSwitches)
{
    // A ball sliding along y = 0 (v0 = 2 m/s, no spin, mu = 1, kn = 1e4 N/m, kt = 2/7 kn) passes
    // the fin: its candidate is flat, then general by the fin, then flat again. While it slides
    // the tangential spring (no dashpot: restitution 1) sits at the Coulomb cap mu Fn / kt =
    // 1.1e-4 m, Fn = m g to round-off (the start is at the resting overlap): a history lost at a
    // switch would restart it from one step's slip (vt dt = 2e-5 m), a relative drop of 0.8.
    // 1e-3 per step separates the two by far.
    const Real dt = 1e-5, friction = 1, kn = 1e4;
    const Real mass = 7800 * 4.0 / 3.0 * kPi * kRadius * kRadius * kRadius;
    World world = finWorld({-0.02, 0, kRadius - mass * kStandardGravity / kn}, {2, 0, 0}, friction, kn);
    const Real tStar = 2 * 2.0 / (7 * friction * kStandardGravity); // the end of sliding (0.058 s)
    std::size_t mostSlots = 0, leastSlots = 99, flatAfterGeneral = 0;
    Real previous = 0, largestJump = 0;
    while (world.time < tStar - 0.002)
    {
        step(world, dt);
        const std::size_t slots = slotsOf(world, 0);
        if (slots == 1 && mostSlots > 1)
            ++flatAfterGeneral;
        mostSlots = std::max(mostSlots, slots);
        leastSlots = std::min(leastSlots, slots);
        const std::size_t first = world.wallContacts.start[0];
        Real spring = 0;
        for (std::size_t k = first; k < first + slots; ++k)
            spring = std::max(spring, length(world.wallHistory.spring[k]));
        if (world.time > 0.002) // past the spring's rise to the cap and the normal transient
            largestJump = std::max(largestJump, std::fabs(spring - previous) / previous);
        previous = spring;
    }
    EXPECT_EQ(leastSlots, 1u);
    EXPECT_EQ(mostSlots, std::size_t(kMeshSlots));
    EXPECT_GT(flatAfterGeneral, 0u);
    EXPECT_GT(world.particles.position[0].x, 0.065); // past the fin (x up to 0.05 m) and its reach
    EXPECT_GT(previous, 0.5 * friction * mass * kStandardGravity / (2.0 / 7.0 * kn));
    EXPECT_LT(largestJump, 1e-3);
}
