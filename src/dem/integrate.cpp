// The integration loops in four AVX2 lanes (integrate.h: kickDriftRange, kickRange).
//
// The particle arrays hold Vec3 rows (x, y, z, 24 bytes), so four particles are twelve doubles:
// three 32-byte vectors per array, "rows" r = 0, 1, 2 below. Force and torque are padded rows
// (PaddedVec3, 32 bytes), brought to the same pattern by three shuffles (loadPaddedRows). The
// updates are component-wise, so they run on the rows as they are, with the per-particle factors
// (1/m, dt/2 / I) spread to the row pattern (m0 m0 m0 m1 | m1 m1 m2 m2 | m2 m3 m3 m3) and gravity
// to (gx gy gz gx | ...). Only the motion check, a sum over a particle's three components,
// transposes its squares to one lane per particle. Each lane performs the scalar loop's IEEE
// operations in the same order (no fused multiply-add, -ffp-contract=off), so the bits are the
// scalar loop's (tests/dem/determinism_test.cpp). The scalar loops, one op per component, issue
// about three times the instructions: the two passes over the particles were ~18 % of a bed step's.
#include "dem/integrate.h"

#include "dem/lanes.h"

#include <cstring>

namespace veridem::dem
{

namespace
{

using lanes::Lanes4;

/// Rows 0, 1, 2 of four PaddedVec3 from a[i] (x, y, z, pad each) in the pattern of four Vec3:
/// (x0 y0 z0 x1 | y1 z1 x2 y2 | z2 x3 y3 z3).
struct PaddedRows
{
    Lanes4 row[3];
};
VERIDEM_HOT_INLINE PaddedRows loadPaddedRows(const PaddedVec3* a, std::size_t i)
{
    const Lanes4 v0 = lanes::load<Lanes4>(&a[i].x), v1 = lanes::load<Lanes4>(&a[i + 1].x),
                 v2 = lanes::load<Lanes4>(&a[i + 2].x), v3 = lanes::load<Lanes4>(&a[i + 3].x);
    return {{__builtin_shufflevector(v0, v1, 0, 1, 2, 4), __builtin_shufflevector(v1, v2, 1, 2, 4, 5),
             __builtin_shufflevector(v2, v3, 2, 4, 5, 6)}};
}

/// Row r (0, 1, 2) of the four Vec3 starting at a[i], unaligned.
VERIDEM_HOT_INLINE Lanes4 loadRow(const Vec3* a, std::size_t i, int r)
{
    Lanes4 v;
    std::memcpy(&v, reinterpret_cast<const char*>(a + i) + r * sizeof(Lanes4), sizeof v);
    return v;
}
VERIDEM_HOT_INLINE void storeRow(Vec3* a, std::size_t i, int r, const Lanes4& v)
{
    std::memcpy(reinterpret_cast<char*>(a + i) + r * sizeof(Lanes4), &v, sizeof v);
}

/// A per-particle factor s = (s0 s1 s2 s3) in the row pattern of four Vec3.
struct Spread
{
    Lanes4 row[3];
    VERIDEM_HOT_INLINE explicit Spread(const Lanes4& s)
        : row{__builtin_shufflevector(s, s, 0, 0, 0, 1), __builtin_shufflevector(s, s, 1, 1, 2, 2),
              __builtin_shufflevector(s, s, 2, 3, 3, 3)}
    {
    }
};

/// Gravity [m/s^2] in the row pattern of four Vec3.
struct GravityRows
{
    Lanes4 row[3];
    explicit GravityRows(const Vec3& g)
        : row{Lanes4{g.x, g.y, g.z, g.x}, Lanes4{g.y, g.z, g.x, g.y}, Lanes4{g.z, g.x, g.y, g.z}}
    {
    }
};

/// Per lane, the larger of `far` and the squared distance of each of four particles (rows x)
/// from `reference` rows: lengthSquared(x - reference), (dx dx + dy dy) + dz dz, as the scalar
/// loop computes it, and its std::max (a NaN distance is never taken).
VERIDEM_HOT_INLINE Lanes4 fartherOf(const Lanes4& far, const Lanes4 (&x)[3], const Vec3* reference,
                                    std::size_t i)
{
    Lanes4 q[3];
    for (int r = 0; r < 3; ++r)
    {
        const Lanes4 d = x[r] - loadRow(reference, i, r);
        q[r] = d * d;
    }
    // Rows (x0 y0 z0 x1 | y1 z1 x2 y2 | z2 x3 y3 z3) to one lane per particle.
    const Lanes4 u = __builtin_shufflevector(q[0], q[1], 0, 1, 6, 7); // x0 y0 x2 y2
    const Lanes4 v = __builtin_shufflevector(q[0], q[2], 2, 3, 4, 5); // z0 x1 z2 x3
    const Lanes4 w = __builtin_shufflevector(q[1], q[2], 0, 1, 6, 7); // y1 z1 y3 z3
    const Lanes4 dx2 = __builtin_shufflevector(u, v, 0, 5, 2, 7);
    const Lanes4 dy2 = __builtin_shufflevector(u, w, 1, 4, 3, 6);
    const Lanes4 dz2 = __builtin_shufflevector(v, w, 0, 5, 2, 7);
    const Lanes4 length2 = dx2 + dy2 + dz2;
    return far < length2 ? length2 : far;
}

/// Row r of four particles' half kick from i: v + half (F/m + g) and w + (half / I) T, as the
/// scalar loops compute them (F and T: the four particles' rows, loadPaddedRows).
struct KickedRows
{
    Lanes4 velocity, angularVelocity;
};
VERIDEM_HOT_INLINE KickedRows halfKickRow(const IntegrationArrays& a, std::size_t i, int r, Real half,
                                          const Spread& inverseMass, const Spread& halfInverseInertia,
                                          const GravityRows& g, const PaddedRows& force,
                                          const PaddedRows& torque)
{
    return {loadRow(a.velocity, i, r) + half * (force.row[r] * inverseMass.row[r] + g.row[r]),
            loadRow(a.angularVelocity, i, r) + halfInverseInertia.row[r] * torque.row[r]};
}

/// Four particles' position rows x (the pattern of four Vec3) and radii r as four (x, y, z, r)
/// rows from a.positionRadius[i] (if the array is sized).
VERIDEM_HOT_INLINE void storePositionRadius(const IntegrationArrays& a, std::size_t i, const Lanes4 (&x)[3])
{
    if (!a.positionRadius)
        return;
    const Lanes4 r = lanes::load<Lanes4>(a.radius + i);
    const Lanes4 xyz1 = __builtin_shufflevector(x[0], x[1], 3, 4, 5, 5); // x1 y1 z1 -
    const Lanes4 xyz2 = __builtin_shufflevector(x[1], x[2], 2, 3, 4, 4); // x2 y2 z2 -
    lanes::store(&a.positionRadius[i].x, __builtin_shufflevector(x[0], r, 0, 1, 2, 4));
    lanes::store(&a.positionRadius[i + 1].x, __builtin_shufflevector(xyz1, r, 0, 1, 2, 5));
    lanes::store(&a.positionRadius[i + 2].x, __builtin_shufflevector(xyz2, r, 0, 1, 2, 6));
    lanes::store(&a.positionRadius[i + 3].x, __builtin_shufflevector(x[2], r, 1, 2, 3, 7));
}

/// std::max over the lanes, from `m` (lane order does not matter: no NaN is ever taken).
Real foldMax(Real m, const Lanes4& lanes)
{
    for (int l = 0; l < 4; ++l)
        m = std::max(m, lanes[l]);
    return m;
}

} // namespace

VERIDEM_AVX2_TARGET Motion kickDriftLanes(ParticleStore& p, const Vec3& gravity, Real dt,
                                          NeighborList::MotionReference reference, std::size_t begin,
                                          std::size_t end)
{
    const Real half = 0.5 * dt;
    const GravityRows g(gravity);
    const IntegrationArrays a(p);
    Lanes4 farBuilt = {}, farActive = {};
    std::size_t i = begin;
    for (; i + 4 <= end; i += 4)
    {
        const Spread inverseMass(lanes::load<Lanes4>(a.invMass + i));
        const Spread halfInverseInertia(half * lanes::load<Lanes4>(a.invInertia + i));
        const PaddedRows force = loadPaddedRows(a.force, i), torque = loadPaddedRows(a.torque, i);
        Lanes4 x[3];
        for (int r = 0; r < 3; ++r)
        {
            // v += half (F/m + g); w += (half / I) T; x += dt v, as kickDriftRange.
            const KickedRows kicked =
                halfKickRow(a, i, r, half, inverseMass, halfInverseInertia, g, force, torque);
            storeRow(a.velocity, i, r, kicked.velocity);
            storeRow(a.angularVelocity, i, r, kicked.angularVelocity);
            x[r] = loadRow(a.position, i, r) + dt * kicked.velocity;
            storeRow(a.position, i, r, x[r]);
        }
        storePositionRadius(a, i, x);
        if (reference.built)
        {
            farBuilt = fartherOf(farBuilt, x, reference.built, i);
            farActive = fartherOf(farActive, x, reference.activeBuilt, i);
        }
    }
    const Motion m{foldMax(0.0, farBuilt), foldMax(0.0, farActive)};
    return kickDriftRange(p, gravity, dt, reference, i, end, m); // the last 0-3 particles
}

VERIDEM_AVX2_TARGET bool kickLanes(ParticleStore& p, const Vec3& gravity, Real dt, std::size_t begin,
                                   std::size_t end)
{
    const Real half = 0.5 * dt;
    const GravityRows g(gravity);
    const IntegrationArrays a(p);
    // The finiteness probe of kickRange: a sum of 0 * a over every component is 0 exactly when
    // all are finite (0 * inf and 0 * NaN are NaN), whatever the order of the sum.
    Lanes4 probe = {};
    std::size_t i = begin;
    for (; i + 4 <= end; i += 4)
    {
        const Spread inverseMass(lanes::load<Lanes4>(a.invMass + i));
        const Spread halfInverseInertia(half * lanes::load<Lanes4>(a.invInertia + i));
        const PaddedRows force = loadPaddedRows(a.force, i), torque = loadPaddedRows(a.torque, i);
        for (int r = 0; r < 3; ++r)
        {
            const KickedRows kicked =
                halfKickRow(a, i, r, half, inverseMass, halfInverseInertia, g, force, torque);
            storeRow(a.velocity, i, r, kicked.velocity);
            storeRow(a.angularVelocity, i, r, kicked.angularVelocity);
            probe = probe +
                    (0.0 * loadRow(a.position, i, r) + 0.0 * kicked.velocity + 0.0 * kicked.angularVelocity);
        }
    }
    const bool finite = probe[0] == 0.0 && probe[1] == 0.0 && probe[2] == 0.0 && probe[3] == 0.0;
    return kickRange(p, gravity, dt, i, end) && finite; // the last 0-3 particles
}

VERIDEM_AVX2_TARGET bool kickThenKickDriftLanes(ParticleStore& p, const Vec3& gravity, Real dt,
                                                NeighborList::MotionReference reference, std::size_t begin,
                                                std::size_t end, Motion& m)
{
    const Real half = 0.5 * dt;
    const GravityRows g(gravity);
    const IntegrationArrays a(p);
    Lanes4 probe = {}, farBuilt = {}, farActive = {};
    std::size_t i = begin;
    for (; i + 4 <= end; i += 4)
    {
        const Spread inverseMass(lanes::load<Lanes4>(a.invMass + i));
        const Spread halfInverseInertia(half * lanes::load<Lanes4>(a.invInertia + i));
        const PaddedRows force = loadPaddedRows(a.force, i), torque = loadPaddedRows(a.torque, i);
        // Read for the last time this step: zeroed for the next step's sums (sumsAreZero).
        for (std::size_t k = i; k < i + 4; ++k)
        {
            lanes::store(&p.force[k].x, Lanes4{});
            lanes::store(&p.torque[k].x, Lanes4{});
        }
        Lanes4 x[3];
        for (int r = 0; r < 3; ++r)
        {
            // kickLanes: v(t) = v(t-dt/2) + half (F/m + g); w likewise; the finiteness probe.
            const KickedRows kicked =
                halfKickRow(a, i, r, half, inverseMass, halfInverseInertia, g, force, torque);
            const Lanes4 position = loadRow(a.position, i, r);
            probe = probe + (0.0 * position + 0.0 * kicked.velocity + 0.0 * kicked.angularVelocity);
            // kickDriftLanes: the same half kick again (the same force), then x += dt v.
            const Lanes4 velocity = kicked.velocity + half * (force.row[r] * inverseMass.row[r] + g.row[r]);
            const Lanes4 angularVelocity = kicked.angularVelocity + halfInverseInertia.row[r] * torque.row[r];
            storeRow(a.velocity, i, r, velocity);
            storeRow(a.angularVelocity, i, r, angularVelocity);
            x[r] = position + dt * velocity;
            storeRow(a.position, i, r, x[r]);
        }
        storePositionRadius(a, i, x);
        if (reference.built)
        {
            farBuilt = fartherOf(farBuilt, x, reference.built, i);
            farActive = fartherOf(farActive, x, reference.activeBuilt, i);
        }
    }
    m = {foldMax(m.sinceBuild2, farBuilt), foldMax(m.sinceActiveBuild2, farActive)};
    const bool finite = probe[0] == 0.0 && probe[1] == 0.0 && probe[2] == 0.0 && probe[3] == 0.0;
    return kickThenKickDriftRange(p, gravity, dt, reference, i, end, m) && finite; // the last 0-3
}

} // namespace veridem::dem
