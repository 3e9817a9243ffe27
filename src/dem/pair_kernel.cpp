#include "dem/pair_kernel.h"

#include "dem/contact_assembly.h"
#include "dem/contact_frame.h"
#include "dem/contact_input.h"
#include "dem/contact_law.h"
#include "dem/exec/lane_memory.h"

#include <algorithm>
#include <cstring>

namespace veridem::dem
{

namespace
{

using namespace batch; // LawBatch, PairBatch, kBatch, lawLanes (dem/exec/law_batch.h)

/// The inputs beyond the linear law's of the pair contacts [0, padded) of `b` (R*, the inertias,
/// the relative angular velocity, the stored rolling spring), as pairContactScalar computes them.
[[gnu::noinline]] void pairExtraInputs(const World& world, const PairBatch& b, LawBatch& law,
                                       std::size_t padded)
{
    const ParticleStore& p = world.particles;
    const ContactHistoryStore& history = world.pairHistory;
    if (!law.rolling) // (Hertz without rolling resistance: the law reads R* alone, lawLanes)
    {
        for (std::size_t m = 0; m < padded; ++m)
            law.radius[m] = pairEffectiveRadius(b.ri[m], b.rj[m]);
        return;
    }
    for (std::size_t m = 0; m < padded; ++m)
    {
        ContactInput in;
        setPairRollingInput(in, p, b.i[m], b.j[m]);
        law.setRollingInputs(m, in, history.keepRolling ? history.rolling[b.candidate[m]] : Vec3{});
    }
}

/// lawLanes on four (AVX2) or two lanes, the springs already in the tangent plane (the pair kernel).
[[gnu::noinline]] VERIDEM_AVX2_TARGET void projectedLawAvx2(LawBatch& b, std::size_t count, Real dt,
                                                            const LawParams* uniform)
{
    lawLanes<Lanes4, true>(b, count, dt, uniform);
}
[[gnu::noinline]] void projectedLawPortable(LawBatch& b, std::size_t count, Real dt, const LawParams* uniform)
{
    lawLanes<Lanes2, true>(b, count, dt, uniform);
}

/// Adds contact q of batch `b` to the sink: force f [N] on i and -f on j, torques ti on i and tj
/// on j [N m] (vectors (x, y, z, 0)), or j's share to the slot's deferred entry; stores the new
/// tangential spring [m] and marks the candidate mayBeActive.
VERIDEM_HOT_INLINE void scatterContact(const PairSink& sink, const PairBatch& b, std::size_t q,
                                       const Lanes4& f, const Lanes4& ti, const Lanes4& tj,
                                       const Lanes4& spring)
{
    const std::uint32_t k = b.candidate[q], i = b.i[q], j = b.j[q];
    sink.mayBeActive[k] = 1;
    std::memcpy(&sink.spring[k].x, &spring, 3 * sizeof(double)); // x, y, z of (x, y, z, 0)
    addInto(&sink.force[i].x, f);
    addInto(&sink.torque[i].x, ti);
    const std::uint32_t d = sink.deferredIndex[k];
    if (d == NeighborList::kInBlock)
    {
        subtractFrom(&sink.force[j].x, f);
        addInto(&sink.torque[j].x, tj);
    }
    else
    {
        // -f in x, y, z (a sign flip, as the scalar path's); the padding stays +0.
        const Index4 flipXyz = {INT64_MIN, INT64_MIN, INT64_MIN, 0};
        store(&sink.deferred[d].force.x, reinterpret_cast<Lanes4>(reinterpret_cast<Index4>(f) ^ flipXyz));
        store(&sink.deferred[d].torque.x, tj);
    }
}

/// Evaluates the touching contacts [0, count) of `b` (count <= kBatch; slot, i and j collected by
/// the caller; the law batchable) and adds them into
/// the sink in lane order, exactly as the scalar path does. `uniform`: the pair parameters if
/// there is a single material pair (no table look-up), else null.
template <class Lanes>
VERIDEM_HOT_INLINE void pairContactsLanes(const World& world, const PairSink& sink, Real dt,
                                          std::size_t count, WorstOverlap& worst, PairBatch& b,
                                          const UniformLaw* uniform)
{
    constexpr std::size_t kLanes = kWidth<Lanes>;
    const ParticleStore& p = world.particles;
    const NeighborList& list = world.neighbors;
    const std::size_t padded = (count + kLanes - 1) / kLanes * kLanes;
    for (std::size_t m = count; m < padded; ++m)
    {
        // Padding lanes repeat the last contact; their results are not written.
        b.candidate[m] = b.candidate[count - 1];
        b.i[m] = b.i[count - 1];
        b.j[m] = b.j[count - 1];
        for (double* a : {b.sx, b.sy, b.sz, b.ri, b.rj})
            a[m] = a[count - 1];
    }
    const Vec3* const velocity = p.velocity.data();
    const Vec3* const angularVelocity = p.angularVelocity.data();
    const Real* const candidateMass = list.activeMass.data();
    // In three passes over the batch, group by group: the contact inputs, the law, the scatter.
    // Each pass's body is short enough for the out-of-order core to overlap one group's chain of
    // divisions and square roots with the next group's (one pass of ~600 instructions a group,
    // more than the reorder buffer, left them in sequence); the inputs and outputs stay in L1.
    LawBatch law;
    alignas(32) double leverIs[kBatch], leverJs[kBatch], minRadii[kBatch];
    setBatchLaws(law, padded, uniform,
                 [&](std::size_t m) VERIDEM_INLINE_LAMBDA -> const PairParams&
                 { return world.pairs(p.material[b.i[m]], p.material[b.j[m]]); });
    if (law.models != 1u) // another model than linear without rolling: R*, inertias, w_rel
        pairExtraInputs(world, b, law, padded);

    const Lanes zero = {};
    // No prefetch of the partners' velocity rows: issued directly (two per contact, eight contacts
    // ahead) they measure no faster on the 20k bed, since the out-of-order core hides those loads;
    // the selection pass's prefetch of the positions stays. (Never issue a prefetch from a lambda
    // here: GCC 12 deletes calls of a lambda whose only effect is a prefetch once it is inlined
    // into an always_inline function.)
    // 1. Inputs (as pairContactScalar).
    for (std::size_t m = 0; m < padded; m += kLanes)
    {
        const std::uint32_t *const laneI = b.i + m, *const laneJ = b.j + m, *const laneK = b.candidate + m;
        // x_i - x_j and the radii as the selection pass computed them.
        const Lanes sx = load<Lanes>(b.sx + m), sy = load<Lanes>(b.sy + m), sz = load<Lanes>(b.sz + m);
        const Lanes ri = load<Lanes>(b.ri + m), rj = load<Lanes>(b.rj + m);
        // Particle and slot data straight into lanes (gatherVec3: paired 16-byte loads).
        const Lanes3<Lanes> wi = gatherVec3<Lanes>(angularVelocity, laneI),
                            wj = gatherVec3<Lanes>(angularVelocity, laneJ);
        const Lanes3<Lanes> vi = gatherVec3<Lanes>(velocity, laneI), vj = gatherVec3<Lanes>(velocity, laneJ);
        const Lanes3<Lanes> h = gatherVec3<Lanes>(sink.spring, laneK);
        const ContactFrameOf<Lanes> f =
            pairContactFrame<Lanes>({sx, sy, sz}, ri, rj, {vi.x - vj.x, vi.y - vj.y, vi.z - vj.z},
                                    {wi.x, wi.y, wi.z}, {wj.x, wj.y, wj.z});
        const Lanes nx = f.normal.x, ny = f.normal.y, nz = f.normal.z;
        store(law.nx + m, nx);
        store(law.ny + m, ny);
        store(law.nz + m, nz);
        store(law.overlap + m, f.overlap);
        store(law.rvx + m, f.relativeVelocity.x);
        store(law.rvy + m, f.relativeVelocity.y);
        store(law.rvz + m, f.relativeVelocity.z);
        store(law.mass + m, gather<Lanes>(candidateMass, laneK)); // m_i m_j / (m_i + m_j)
        // The spring rotated into the tangent plane here rather than in the law pass (its
        // division and square root): the divider work of the two passes is then about even
        // (two square roots and two divisions here, one division there, per group).
        const V3<Lanes> projected = projectSpring<Lanes>({h.x, h.y, h.z}, {nx, ny, nz});
        store(law.hx + m, projected.x);
        store(law.hy + m, projected.y);
        store(law.hz + m, projected.z);
        store(leverIs + m, f.leverI);
        store(leverJs + m, f.leverJ);
        store(minRadii + m, rj < ri ? rj : ri);
    }

    // The JKR touch criterion's state: formed or not at the previous step.
    law.formedKnown = law.jkr;
    if (law.jkr)
        for (std::size_t m = 0; m < padded; ++m)
            law.formed[m] = sink.mayBeActive[b.candidate[m]];

    // 2. The law (lawLanes, as the wall contacts').
    // (In its own function, as the walls': inlined, its register pressure spills the other passes.)
    if constexpr (kWidth<Lanes> == 4)
        projectedLawAvx2(law, padded, dt, uniform ? &uniform->params : nullptr);
    else
        projectedLawPortable(law, padded, dt, uniform ? &uniform->params : nullptr);

    // 3. Forces and torques, scattered in lane (= slot) order; the health record. Compiled with and
    // without rolling torques (kRolling), so that the common case carries none of their work.
    const auto scatter = [&]<bool kRolling>() VERIDEM_INLINE_LAMBDA
    {
        for (std::size_t m = 0; m < padded; m += kLanes)
        {
            const Lanes nx = load<Lanes>(law.nx + m), ny = load<Lanes>(law.ny + m),
                        nz = load<Lanes>(law.nz + m);
            const Lanes normalForce = load<Lanes>(law.normalForce + m), ftx = load<Lanes>(law.ftx + m),
                        fty = load<Lanes>(law.fty + m), ftz = load<Lanes>(law.ftz + m);
            const Lanes leverI = load<Lanes>(leverIs + m), leverJ = load<Lanes>(leverJs + m);
            // F = Fn n + Ft; torques M_r - l_i (n x Ft) on i, -M_r - l_j (n x Ft) on j
            // (contact_assembly.h; M_r = +0 without a rolling model, so -M_r = -0, as the scalar path's).
            const V3<Lanes> n{nx, ny, nz}, ft{ftx, fty, ftz};
            V3<Lanes> rolling{zero, zero, zero};
            if constexpr (kRolling)
                rolling = {load<Lanes>(law.torqueX + m), load<Lanes>(law.torqueY + m),
                           load<Lanes>(law.torqueZ + m)};
            const V3<Lanes> f = contactForceOf<Lanes>(n, normalForce, ft);
            const PairTorquesOf<Lanes> t = pairContactTorques<Lanes>(n, ft, rolling, leverI, leverJ);

            // Scatter: one (x, y, z, 0) vector per contact and sum.
            Lanes4 force[kLanes], torqueI[kLanes], torqueJ[kLanes], spring[kLanes];
            transpose(f.x, f.y, f.z, force);
            transpose(t.onI.x, t.onI.y, t.onI.z, torqueI);
            transpose(t.onJ.x, t.onJ.y, t.onJ.z, torqueJ);
            transpose(load<Lanes>(law.springX + m), load<Lanes>(law.springY + m),
                      load<Lanes>(law.springZ + m), spring);
            const std::size_t lanes = std::min(kLanes, count - m);
            if (kRolling && sink.rolling)
                for (std::size_t l = 0; l < lanes; ++l)
                    sink.rolling[b.candidate[m + l]] = {law.rollingX[m + l], law.rollingY[m + l],
                                                        law.rollingZ[m + l]};
            if (lanes == kLanes) // (a constant trip count: unrolled, every lane index a constant)
            {
#pragma GCC unroll 4
                for (std::size_t l = 0; l < kLanes; ++l)
                    scatterContact(sink, b, m + l, force[l], torqueI[l], torqueJ[l], spring[l]);
            }
            else
                for (std::size_t l = 0; l < lanes; ++l)
                    scatterContact(sink, b, m + l, force[l], torqueI[l], torqueJ[l], spring[l]);

            // The health record, in lane order. One comparison first: the running ratio only grows,
            // so a lane that does not exceed it now cannot exceed it after an earlier lane's update.
            const Lanes overlap = load<Lanes>(law.overlap + m), minRadius = load<Lanes>(minRadii + m);
            if (anyLane(overlap > worst.ratio * minRadius))
                for (std::size_t l = 0; l < lanes; ++l)
                    if (worst.exceededBy(overlap[l], minRadius[l]))
                        worst = {overlap[l] / minRadius[l], b.i[m + l], true};
        }
    };
    if (law.rolling)
        scatter.template operator()<true>();
    else
        scatter.template operator()<false>();
    if (law.jkr) // (scatterContact marked every contact formed)
        for (std::size_t q = 0; q < count; ++q)
            sink.mayBeActive[b.candidate[q]] = law.formed[q] != 0;
}

VERIDEM_AVX2_TARGET void pairContactsAvx2(const World& world, const PairSink& sink, Real dt,
                                          std::size_t count, WorstOverlap& worst, PairBatch& b,
                                          const UniformLaw* uniform)
{
    pairContactsLanes<Lanes4>(world, sink, dt, count, worst, b, uniform);
}

void pairContactsPortable(const World& world, const PairSink& sink, Real dt, std::size_t count,
                          WorstOverlap& worst, PairBatch& b, const UniformLaw* uniform)
{
    pairContactsLanes<Lanes2>(world, sink, dt, count, worst, b, uniform);
}

} // namespace

PairKernel pairKernelFor(exec::Isa isa)
{
    return isa == exec::Isa::Avx2 ? pairContactsAvx2 : pairContactsPortable;
}

PairContactResult pairContactAt(const World& world, std::uint32_t i, std::uint32_t j, const Vec3& separation,
                                Real effectiveMass, ContactHistory& history, Real dt)
{
    const ParticleStore& p = world.particles;
    const Real ri = p.radius[i], rj = p.radius[j];
    const PairParams& params = world.pairs(p.material[i], p.material[j]);
    const ContactFrameOf<Real> f = pairContactFrame<Real>(separation, ri, rj, p.velocity[i] - p.velocity[j],
                                                          p.angularVelocity[i], p.angularVelocity[j]);
    const ContactInput in = pairContactInput(p, i, j, f, effectiveMass);
    const ContactOutput out = evaluateContact(params, in, history, dt);
    const PairTorquesOf<Real> t =
        pairContactTorques<Real>(in.normal, out.tangentialForce, out.rollingTorque, f.leverI, f.leverJ);
    return {out.force, t.onI, t.onJ, in.overlap};
}

/// Touching candidate k through the general contact law (any model), added into the sink.
void pairContactScalar(const World& world, const PairSink& sink, Real dt, std::size_t k, WorstOverlap& worst)
{
    const ParticleStore& p = world.particles;
    const NeighborList& list = world.neighbors;
    const std::uint32_t i = list.activeFirst[k], j = list.activeSecond[k];
    ContactHistory history = sink.history(k);
    const PairContactResult c =
        pairContactAt(world, i, j, p.position[i] - p.position[j], list.activeMass[k], history, dt);
    sink.setHistory(k, history);
    sink.add(static_cast<std::uint32_t>(k), i, j, c.force, c.torqueI, c.torqueJ);

    const Real minRadius = std::min(p.radius[i], p.radius[j]);
    if (worst.exceededBy(c.overlap, minRadius))
        worst = {c.overlap / minRadius, i, true};
}

} // namespace veridem::dem
