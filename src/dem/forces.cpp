// Contact lever arms ("contact radius convention", docs/models.md):
//  * sphere-wall: the lever arm is the undeformed radius r. The contact-point velocity
//    v + w x (-r n) and the torque (-r n) x Ft use the same arm, so the discrete dynamics are
//    exactly those of a rigid ball of radius r rolling on the wall (v = r w when rolling), which
//    is what the analytical solutions assume (2/7 Omega orbit, 5/7 v0 bowling ball).
//  * sphere-sphere: the contact point divides the centre distance d in the ratio of the radii,
//    l_i = r_i d / (r_i + r_j), so l_i + l_j = d and the tangential force conserves the total
//    angular momentum exactly (with r_i alone it would be violated by delta n x Ft).
//
// Parallel layout (STYLE 3.4): stage 3 loops over contact slots and writes only the slot's own
// outputs and history; stage 4 loops over particles and reads the slots in a fixed order. The
// health record (largest overlap) is reduced per chunk and combined in chunk order, so it too is
// independent of the thread count.
#include "dem/forces.h"

#include "dem/contact_law.h"
#include "dem/parallel.h"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <immintrin.h>

namespace veridem::dem
{

namespace
{

constexpr int kMaxChunks = 64;

struct WorstOverlap // trivial on purpose: per-chunk arrays of it are not cleared every step
{
    Real ratio;
    std::uint32_t particle;
    bool found;
};

/// Folds per-chunk records into health in chunk order (strictly greater wins: the first slot
/// with the largest ratio, as a serial loop would find).
void combine(StepHealth& health, const WorstOverlap* worst, int chunks)
{
    for (int c = 0; c < chunks; ++c)
        if (worst[c].found && worst[c].ratio > health.maxOverlapRatio)
        {
            health.maxOverlapRatio = worst[c].ratio;
            health.worstParticle = worst[c].particle;
        }
}

/// What the contact law reads beyond the linear normal and tangential model.
struct ExtraInputs
{
    bool effectiveRadius, spinInertia, rollingInertia;
};

ExtraInputs extraInputsFor(const PairParams& params)
{
    return {params.normalModel == NormalModel::Hertz || params.rollingModel != RollingModel::None,
            params.rollingModel == RollingModel::ConstantTorque, params.rollingModel == RollingModel::Epsd};
}

// ---------------------------------------------------------------------------------------------
// Four contacts at a time (linear spring-dashpot, no rolling resistance: the reference bed's law).
//
// One contact is a chain of ~12 dependent divisions and square roots (normal, lever arms, m*, the
// end-of-step normal speed, the spring rotation, the Coulomb cap), so a scalar loop waits on
// latency. Here the same operations run on four independent contacts in the lanes of GCC vector
// types (two SSE2 registers each, or one AVX register with VERIDEM_NATIVE): every lane performs
// exactly the IEEE operations of evaluateContact() in the same order, branches become selects, so
// the bits are those of the scalar path (tests/dem/contact_batch_test.cpp checks it). Contacts
// with another law go through the scalar path.
// ---------------------------------------------------------------------------------------------
#if defined(__AVX__)
using Lanes = double __attribute__((vector_size(32))); // same type as __m256d
using LaneMask = long long __attribute__((vector_size(32)));
constexpr std::size_t kLanes = 4;
inline Lanes laneSqrt(Lanes x)
{
    return _mm256_sqrt_pd(x);
}
#else
using Lanes = double __attribute__((vector_size(16))); // same type as __m128d
using LaneMask = long long __attribute__((vector_size(16)));
constexpr std::size_t kLanes = 2;
inline Lanes laneSqrt(Lanes x)
{
    return _mm_sqrt_pd(x);
} // correctly rounded, as std::sqrt
#endif

/// True if pairs of these parameters may take the four-lane path (all pairs must, or none does).
bool batchable(const PairParams& params)
{
    return params.normalModel == NormalModel::Linear && params.rollingModel == RollingModel::None;
}

constexpr std::size_t kBatch = 64; // contacts per batch (a multiple of 4); ~25 KB of lanes, in L1

/// Per-batch lanes: inputs are gathered here with scalar stores, read back as vectors long after
/// (a vector load right after scalar stores to the same bytes misses store forwarding).
struct PairBatch
{
    alignas(32) double sx[kBatch], sy[kBatch], sz[kBatch], ri[kBatch], rj[kBatch];
    alignas(32) double dvx[kBatch], dvy[kBatch], dvz[kBatch];
    alignas(32) double wix[kBatch], wiy[kBatch], wiz[kBatch], wjx[kBatch], wjy[kBatch], wjz[kBatch];
    alignas(32) double effectiveMass[kBatch], hx[kBatch], hy[kBatch], hz[kBatch];
    alignas(32) double kn[kBatch], ktRatio[kBatch], rate[kBatch], fromRatio[kBatch], etaRatio[kBatch],
        mu[kBatch];
    // outputs
    alignas(32) double fx[kBatch], fy[kBatch], fz[kBatch], ttx[kBatch], tty[kBatch], ttz[kBatch];
    alignas(32) double leverI[kBatch], leverJ[kBatch], springX[kBatch], springY[kBatch], springZ[kBatch];
    alignas(32) double ratio[kBatch];
    std::uint32_t slot[kBatch], i[kBatch], j[kBatch];
};

inline bool anyLane(const LaneMask& mask)
{
    bool any = false;
    for (std::size_t l = 0; l < kLanes; ++l)
        any = any || mask[l] != 0;
    return any;
}

inline bool allLanes(const LaneMask& mask)
{
    bool all = true;
    for (std::size_t l = 0; l < kLanes; ++l)
        all = all && mask[l] != 0;
    return all;
}

inline Lanes load(const double* a)
{
    Lanes v;
    std::memcpy(&v, a, sizeof v);
    return v;
}
inline void store(double* a, const Lanes& v)
{
    std::memcpy(a, &v, sizeof v);
}

/// Evaluates the touching contacts in lanes [0, count) of `b` (count <= kBatch; slot, i, j and the
/// separation and radii already collected by the caller; the law batchable) and writes their
/// outputs exactly as the scalar path does. `uniform`: the pair parameters if there is a single
/// material pair (skips the table look-up), else null.
[[gnu::noinline]] void pairContactsBatch(const World& world, NeighborList& list, Real dt, std::size_t count,
                                         WorstOverlap& worst, PairBatch& b, const PairParams* uniform)
{
    const ParticleStore& p = world.particles;
    const std::size_t padded = (count + kLanes - 1) / kLanes * kLanes;
    for (std::size_t m = count; m < padded; ++m)
    {
        // Padding lanes repeat the last contact; their results are not written.
        b.slot[m] = b.slot[count - 1];
        b.i[m] = b.i[count - 1];
        b.j[m] = b.j[count - 1];
        b.sx[m] = b.sx[count - 1];
        b.sy[m] = b.sy[count - 1];
        b.sz[m] = b.sz[count - 1];
        b.ri[m] = b.ri[count - 1];
        b.rj[m] = b.rj[count - 1];
    }
    for (std::size_t m = 0; m < padded; ++m)
    {
        const std::uint32_t k = b.slot[m], i = b.i[m], j = b.j[m];
        const PairParams& pp = uniform ? *uniform : world.pairs(p.material[i], p.material[j]);
        const Vec3 &vi = p.velocity[i], &vj = p.velocity[j];
        const Vec3 &wi = p.angularVelocity[i], &wj = p.angularVelocity[j], &h = list.tangentialSpring[k];
        b.dvx[m] = vi.x - vj.x;
        b.dvy[m] = vi.y - vj.y;
        b.dvz[m] = vi.z - vj.z;
        b.wix[m] = wi.x;
        b.wiy[m] = wi.y;
        b.wiz[m] = wi.z;
        b.wjx[m] = wj.x;
        b.wjy[m] = wj.y;
        b.wjz[m] = wj.z;
        b.effectiveMass[m] = list.effectiveMass[k]; // m_i m_j / (m_i + m_j), per slot
        b.hx[m] = h.x;
        b.hy[m] = h.y;
        b.hz[m] = h.z;
        b.kn[m] = pp.kn;
        b.ktRatio[m] = pp.ktRatio;
        b.rate[m] = pp.dampingRate;
        b.fromRatio[m] = 2.0 * pp.dampingRatio;
        b.etaRatio[m] = pp.tangentialDampingRatio;
        b.mu[m] = pp.mu;
    }

    const Lanes zero = {}, one = zero + 1.0;
    for (std::size_t m = 0; m < padded; m += kLanes)
    {
        // Geometry (the scalar path in computePairForces).
        const Lanes sx = load(b.sx + m), sy = load(b.sy + m), sz = load(b.sz + m);
        const Lanes ri = load(b.ri + m), rj = load(b.rj + m);
        const Lanes touching = ri + rj;
        const Lanes distance2 = sx * sx + sy * sy + sz * sz;
        const Lanes distance = laneSqrt(distance2);
        const LaneMask positive = distance > zero;
        const Lanes nx = positive ? sx / distance : zero;
        const Lanes ny = positive ? sy / distance : zero;
        const Lanes nz = positive ? sz / distance : one;
        const Lanes overlap = touching - distance;
        const Lanes leverI = ri * distance / touching, leverJ = rj * distance / touching;
        const Lanes ax = load(b.wix + m) * leverI + load(b.wjx + m) * leverJ;
        const Lanes ay = load(b.wiy + m) * leverI + load(b.wjy + m) * leverJ;
        const Lanes az = load(b.wiz + m) * leverI + load(b.wjz + m) * leverJ;
        const Lanes rvx = load(b.dvx + m) - (ay * nz - az * ny);
        const Lanes rvy = load(b.dvy + m) - (az * nx - ax * nz);
        const Lanes rvz = load(b.dvz + m) - (ax * ny - ay * nx);
        const Lanes effectiveMass = load(b.effectiveMass + m);

        // contactCoefficients(), linear branch.
        const Lanes kn = load(b.kn + m);
        const Lanes kt = load(b.ktRatio + m) * kn;
        const Lanes rate = load(b.rate + m);
        const LaneMask fromRate = rate >= zero;
        Lanes etaN = rate * effectiveMass;
        if (!allLanes(fromRate)) // damping from restitution: 2 zeta sqrt(m* kn)
            etaN = fromRate ? etaN : load(b.fromRatio + m) * laneSqrt(effectiveMass * kn);
        const Lanes etaT = load(b.etaRatio + m) * etaN;

        // evaluateContact(): 1. normal force.
        const Lanes normalSpeed = rvx * nx + rvy * ny + rvz * nz;
        const Lanes elastic = kn * overlap;
        const Lanes travel =
            reinterpret_cast<Lanes>(reinterpret_cast<LaneMask>(normalSpeed) & 0x7fffffffffffffffLL) * dt;
        // Divisions and roots are the bottleneck: those of rare branches run only if a lane takes them.
        const LaneMask transition = overlap < travel;
        Lanes dashpotWeight = one;
        if (anyLane(transition))
            dashpotWeight = transition ? 0.5 + overlap / travel : one;
        const Lanes dampingWeight = dashpotWeight * etaN;
        const Lanes halfStepOverMass = 0.5 * dt / effectiveMass;
        const Lanes normalSpeedEnd =
            (normalSpeed + halfStepOverMass * elastic) / (1.0 + halfStepOverMass * dampingWeight);
        const Lanes normalForce = elastic - dampingWeight * normalSpeedEnd;

        // 2. coulombSpringForce().
        const Lanes vtx = rvx - normalSpeed * nx, vty = rvy - normalSpeed * ny, vtz = rvz - normalSpeed * nz;
        const Lanes hx = load(b.hx + m), hy = load(b.hy + m), hz = load(b.hz + m);
        const Lanes oldLength2 = hx * hx + hy * hy + hz * hz;
        const Lanes along = hx * nx + hy * ny + hz * nz;
        const Lanes qx = hx - along * nx, qy = hy - along * ny, qz = hz - along * nz;
        const Lanes newLength2 = qx * qx + qy * qy + qz * qz;
        const Lanes lengthRatio = oldLength2 / newLength2;
        const Lanes rescale = laneSqrt(lengthRatio);
        const LaneMask keep = oldLength2 == zero, vanish = newLength2 == zero;
        const Lanes px = keep ? hx : (vanish ? zero : qx * rescale);
        const Lanes py = keep ? hy : (vanish ? zero : qy * rescale);
        const Lanes pz = keep ? hz : (vanish ? zero : qz * rescale);
        const Lanes springX = px + vtx * dt, springY = py + vty * dt, springZ = pz + vtz * dt;
        const Lanes trialX = -kt * springX - etaT * vtx, trialY = -kt * springY - etaT * vty,
                    trialZ = -kt * springZ - etaT * vtz;
        const Lanes cap = load(b.mu + m) * (normalForce > zero ? normalForce : zero);
        const Lanes trialLength2 = trialX * trialX + trialY * trialY + trialZ * trialZ;
        const LaneMask sticks = trialLength2 <= cap * cap;
        Lanes ftx = trialX, fty = trialY, ftz = trialZ, newSpringX = springX, newSpringY = springY,
              newSpringZ = springZ;
        if (!allLanes(sticks))
        {
            const Lanes slideScale = cap / laneSqrt(trialLength2);
            const Lanes slideX = trialX * slideScale, slideY = trialY * slideScale,
                        slideZ = trialZ * slideScale;
            const LaneMask stiff = kt > zero;
            ftx = sticks ? trialX : slideX;
            fty = sticks ? trialY : slideY;
            ftz = sticks ? trialZ : slideZ;
            newSpringX = sticks ? springX : (stiff ? -(slideX + etaT * vtx) / kt : zero);
            newSpringY = sticks ? springY : (stiff ? -(slideY + etaT * vty) / kt : zero);
            newSpringZ = sticks ? springZ : (stiff ? -(slideZ + etaT * vtz) / kt : zero);
        }
        store(b.springX + m, newSpringX);
        store(b.springY + m, newSpringY);
        store(b.springZ + m, newSpringZ);
        store(b.fx + m, normalForce * nx + ftx);
        store(b.fy + m, normalForce * ny + fty);
        store(b.fz + m, normalForce * nz + ftz);

        // n x Ft and the lever arms; the gather forms the torques (no rolling resistance here).
        store(b.ttx + m, ny * ftz - nz * fty);
        store(b.tty + m, nz * ftx - nx * ftz);
        store(b.ttz + m, nx * fty - ny * ftx);
        store(b.leverI + m, leverI);
        store(b.leverJ + m, leverJ);
        store(b.ratio + m, overlap / (rj < ri ? rj : ri));
    }

    std::uint8_t* const mayBeActive = list.mayBeActive.data(); // (a byte store aliases anything:
    Vec3* const spring = list.tangentialSpring.data();         //  array bases are kept in locals)
    Vec3* const force = list.force.data();
    Vec3* const tangentialTorque = list.tangentialTorque.data();
    Real* const leverFirst = list.leverFirst.data();
    Real* const leverSecond = list.leverSecond.data();
    for (std::size_t m = 0; m < count; ++m)
    {
        const std::uint32_t k = b.slot[m];
        mayBeActive[k] = 1;
        spring[k] = {b.springX[m], b.springY[m], b.springZ[m]};
        force[k] = {b.fx[m], b.fy[m], b.fz[m]};
        tangentialTorque[k] = {b.ttx[m], b.tty[m], b.ttz[m]};
        leverFirst[k] = b.leverI[m];
        leverSecond[k] = b.leverJ[m];
        if (b.ratio[m] > worst.ratio)
            worst = {b.ratio[m], b.i[m], true};
    }
}

} // namespace

void computePairForces(World& world, Real dt)
{
    const ParticleStore& p = world.particles;
    NeighborList& list = world.neighbors;
    world.health.maxOverlapRatio = 0;
    const std::size_t pairCount = list.size();
    if (pairCount == 0)
        return;
    bool allBatchable = world.batchedContactKernel;
    for (std::uint32_t a = 0; a < world.pairs.count(); ++a)
        for (std::uint32_t b = 0; b < world.pairs.count(); ++b)
            allBatchable = allBatchable && batchable(world.pairs(a, b));
    const PairParams* uniform = world.pairs.count() == 1 ? &world.pairs(0, 0) : nullptr;
    if (!allBatchable)
        list.touchingScratch.resize(pairCount); // the scalar path's per-chunk lists of touching slots
    const int chunks = std::min(loopThreads(pairCount), kMaxChunks);
    WorstOverlap worst[kMaxChunks];
    parallelChunks(
        pairCount, chunks,
        [&](int chunk, std::size_t begin, std::size_t end)
        {
            WorstOverlap local{0, 0, false};
            if (allBatchable)
            {
                // One pass: each touching slot is appended (branch-free) to a batch of lanes with
                // its separation and radii, and the batch runs when full.
                PairBatch batch;
                std::size_t m = 0;
                // Array bases in locals: the byte-sized mayBeActive store below could otherwise
                // alias the vectors' own pointers, which the compiler would reload every slot.
                const std::uint32_t* const first = list.first.data();
                const std::uint32_t* const second = list.second.data();
                const Vec3* const position = p.position.data();
                const Real* const radius = p.radius.data();
                std::uint8_t* const mayBeActive = list.mayBeActive.data();
                for (std::size_t k = begin; k < end; ++k)
                {
                    const std::uint32_t i = first[k], j = second[k];
                    const Vec3 &xi = position[i], &xj = position[j];
                    const Real ri = radius[i], rj = radius[j];
                    const Real sx = xi.x - xj.x, sy = xi.y - xj.y, sz = xi.z - xj.z;
                    const Real touching = ri + rj;
                    const bool isTouching = sx * sx + sy * sy + sz * sz < touching * touching;
                    batch.slot[m] = static_cast<std::uint32_t>(k);
                    batch.i[m] = i;
                    batch.j[m] = j;
                    batch.sx[m] = sx;
                    batch.sy[m] = sy;
                    batch.sz[m] = sz;
                    batch.ri[m] = ri;
                    batch.rj[m] = rj;
                    m += isTouching;
                    if (!isTouching && mayBeActive[k])
                    {
                        // The contact opened (or never closed): forget it, contribute nothing.
                        list.setHistory(k, ContactHistory{});
                        list.force[k] = Vec3{};
                        list.tangentialTorque[k] = Vec3{};
                        if (list.keepRollingTorque)
                            list.rollingTorque[k] = Vec3{};
                        mayBeActive[k] = 0;
                    }
                    if (m == kBatch)
                    {
                        pairContactsBatch(world, list, dt, m, local, batch, uniform);
                        m = 0;
                    }
                }
                if (m > 0)
                    pairContactsBatch(world, list, dt, m, local, batch, uniform);
                worst[chunk] = local;
                return;
            }
            // Pass 1: which slots touch (branch-free), and clear the slots that just opened.
            std::uint32_t* touchingSlots = list.touchingScratch.data() + begin;
            std::size_t touchingCount = 0;
            for (std::size_t k = begin; k < end; ++k)
            {
                const std::uint32_t i = list.first[k], j = list.second[k];
                const Real touching = p.radius[i] + p.radius[j];
                const bool isTouching = lengthSquared(p.position[i] - p.position[j]) < touching * touching;
                touchingSlots[touchingCount] = static_cast<std::uint32_t>(k);
                touchingCount += isTouching;
                if (!isTouching && list.mayBeActive[k])
                {
                    // The contact opened (or never closed): forget it, contribute nothing.
                    list.setHistory(k, ContactHistory{});
                    list.force[k] = Vec3{};
                    list.tangentialTorque[k] = Vec3{};
                    if (list.keepRollingTorque)
                        list.rollingTorque[k] = Vec3{};
                    list.mayBeActive[k] = 0;
                }
            }
            // Pass 2: the contact law on the touching slots, in ascending slot order.
            auto scalarContact = [&](std::size_t k)
            {
                const std::uint32_t i = list.first[k], j = list.second[k];
                list.mayBeActive[k] = 1;
                const Vec3 separation = p.position[i] - p.position[j];
                const Real ri = p.radius[i], rj = p.radius[j];
                const Real touching = ri + rj;
                const Real distance2 = lengthSquared(separation);
                const PairParams& params = world.pairs(p.material[i], p.material[j]);
                const ExtraInputs extra = extraInputsFor(params);
                const Real distance = std::sqrt(distance2);
                ContactInput in;
                in.normal = distance > 0 ? separation / distance : Vec3{0, 0, 1};
                in.overlap = touching - distance;
                const Real leverI = ri * distance / touching, leverJ = rj * distance / touching;
                in.relativeVelocity =
                    p.velocity[i] - p.velocity[j] -
                    cross(leverI * p.angularVelocity[i] + leverJ * p.angularVelocity[j], in.normal);
                in.relativeAngularVelocity = p.angularVelocity[i] - p.angularVelocity[j];
                in.effectiveMass = p.mass[i] * p.mass[j] / (p.mass[i] + p.mass[j]);
                if (extra.effectiveRadius)
                    in.effectiveRadius = ri * rj / touching;
                if (extra.spinInertia)
                    in.spinInertia = 1.0 / (p.invInertia[i] + p.invInertia[j]);
                if (extra.rollingInertia)
                    in.rollingInertia = 1.0 / (1.0 / (1.0 / p.invInertia[i] + p.mass[i] * ri * ri) +
                                               1.0 / (1.0 / p.invInertia[j] + p.mass[j] * rj * rj));

                ContactHistory history = list.history(k);
                const ContactOutput out = evaluateContact(params, in, history, dt);
                list.setHistory(k, history);

                const Vec3 tangentialTorque = cross(in.normal, out.tangentialForce); // n x Ft
                list.force[k] = out.force;
                list.tangentialTorque[k] = tangentialTorque;
                list.leverFirst[k] = leverI;
                list.leverSecond[k] = leverJ;
                if (list.keepRollingTorque)
                    list.rollingTorque[k] = out.rollingTorque;

                const Real ratio = in.overlap / std::min(ri, rj);
                if (ratio > local.ratio)
                    local = {ratio, i, true};
            };
            for (std::size_t t = 0; t < touchingCount; ++t)
                scalarContact(touchingSlots[t]);
            worst[chunk] = local;
        });
    combine(world.health, worst, chunks);
}

namespace
{

/// Wall slots [begin, end): the scalar contact law, outputs into the slots.
WorstOverlap wallContactRange(const World& world, WallContactList& list, Real dt, std::size_t begin,
                              std::size_t end)
{
    const ParticleStore& p = world.particles;
    WorstOverlap worst{0, 0, false};
    for (std::size_t k = begin; k < end; ++k)
    {
        const std::uint32_t i = list.particle[k];
        const Wall& wall = world.walls[list.wall[k]];
        const Real r = p.radius[i];
        const Vec3 position = p.position[i], velocity = p.velocity[i], angularVelocity = p.angularVelocity[i];
        const WallGap gap = wallGap(wall, position, r);
        if (!gap.touching)
        {
            list.setHistory(k, ContactHistory{});
            list.force[k] = Vec3{};
            list.torque[k] = Vec3{};
            continue;
        }
        const PairParams& params = world.pairs(p.material[i], wall.material);
        ContactInput in;
        in.normal = gap.normal;
        in.overlap = gap.overlap;
        const Vec3 arm = -r * gap.normal; // centre to contact point
        // The particle's velocities are those of the half step t+dt/2, so the wall's surface
        // velocity is taken at the contact point of the half step too (x - v dt/2). Using x(t+dt)
        // would add a spurious slip Omega |v| dt/2 on a rotating wall, and a ball orbiting on a
        // turntable would lose speed at a rate of order Omega v dt.
        const Vec3 midStepContactPoint = position - (0.5 * dt) * velocity + arm;
        in.relativeVelocity = velocity + cross(angularVelocity, arm) -
                              wallSurfaceVelocity(wall, midStepContactPoint, -0.5 * dt);
        in.relativeAngularVelocity = angularVelocity - wall.motion.angularVelocity;
        in.effectiveMass = p.mass[i];
        in.effectiveRadius = gap.effectiveRadius;
        in.spinInertia = 1.0 / p.invInertia[i];
        if (params.rollingModel == RollingModel::Epsd)
            in.rollingInertia = in.spinInertia + p.mass[i] * r * r;

        ContactHistory history = list.history(k);
        const ContactOutput out = evaluateContact(params, in, history, dt);
        list.setHistory(k, history);
        list.force[k] = out.force;
        list.torque[k] = out.rollingTorque + cross(arm, out.tangentialForce);

        const Real ratio = in.overlap / r;
        if (ratio > worst.ratio)
            worst = {ratio, i, true};
    }
    return worst;
}

} // namespace

void computeWallForces(World& world, Real dt)
{
    WallContactList& list = world.wallContacts;
    const std::size_t count = list.size();
    if (count == 0)
        return;
    const int chunks = std::min(loopThreads(count), kMaxChunks);
    if (chunks == 1)
    {
        const WorstOverlap worst = wallContactRange(world, list, dt, 0, count);
        combine(world.health, &worst, 1);
        return;
    }
    WorstOverlap worst[kMaxChunks];
    parallelChunks(count, chunks,
                   [&](int chunk, std::size_t begin, std::size_t end)
                   { worst[chunk] = wallContactRange(world, list, dt, begin, end); });
    combine(world.health, worst, chunks);
}

void gatherContactForces(World& world)
{
    ParticleStore& p = world.particles;
    const NeighborList& pairs = world.neighbors;
    const WallContactList& walls = world.wallContacts;
    const bool hasWalls = walls.start.size() == p.size() + 1;
    parallelFor(p.size(),
                [&](std::size_t i)
                {
                    Vec3 force{}, torque{};
                    // Slots where i is the second particle come first in slot order (their first
                    // particle is < i), then i's own slots.
                    for (std::uint32_t s = pairs.secondStart[i]; s < pairs.secondStart[i + 1]; ++s)
                    {
                        const std::uint32_t k = pairs.secondSlots[s];
                        force -= pairs.force[k];
                        const Vec3 rolling = pairs.keepRollingTorque ? pairs.rollingTorque[k] : Vec3{};
                        torque += -rolling - pairs.leverSecond[k] * pairs.tangentialTorque[k];
                    }
                    for (std::uint32_t k = pairs.firstStart[i]; k < pairs.firstStart[i + 1]; ++k)
                    {
                        force += pairs.force[k];
                        const Vec3 rolling = pairs.keepRollingTorque ? pairs.rollingTorque[k] : Vec3{};
                        torque += rolling - pairs.leverFirst[k] * pairs.tangentialTorque[k];
                    }
                    if (hasWalls)
                        for (std::uint32_t k = walls.start[i]; k < walls.start[i + 1]; ++k)
                        {
                            force += walls.force[k];
                            torque += walls.torque[k];
                        }
                    p.force[i] = force;
                    p.torque[i] = torque;
                });
}

void computeForces(World& world, Real dt)
{
    computePairForces(world, dt);
    computeWallForces(world, dt);
    gatherContactForces(world);
}

} // namespace veridem::dem
