// The pair contacts of the force stage (dem/forces.cpp): each touching candidate's contact frame
// (pairContactFrame, dem/contact_frame.h: unit normal, overlap, lever arms, relative velocity at the
// contact point) and inputs, the contact law (dem/contact_law.h), and the forces and torques added
// into the particles' sums (or a cross-block share into the slot's deferred entry,
// dem/neighbor_list.h). In lanes for a batch of contacts (dem/exec/law_batch.h), and one at a time
// through the general law (pairContactScalar): the same templates, so the same bits.
#pragma once

#include "dem/contact_frame.h"
#include "dem/contact_input.h"
#include "dem/exec/pair_selection.h"
#include "dem/world.h"
#include "exec/isa.h"

#include <cstdint>

namespace veridem::dem
{

struct WorstOverlap // the running largest overlap of a chunk's contacts
{
    Real ratio;
    std::uint32_t particle;
    bool found;

    /// overlap / radius > ratio, without the division (radius > 0 [m]; overlap [m]); the division
    /// is paid only when the worst contact changes, which is rare.
    bool exceededBy(Real overlap, Real radius) const { return overlap > ratio * radius; }
};

/// Where the pair loop writes. Array bases are held in locals: a byte store (mayBeActive) may alias
/// anything, so GCC would otherwise reload every vector's pointer after it.
struct PairSink
{
    PaddedVec3* force;                     // per-particle sums [N] (ParticleStore::force)
    PaddedVec3* torque;                    // [N m]
    const std::uint32_t* deferredIndex;    // per candidate, or NeighborList::kInBlock
    NeighborList::DeferredShare* deferred; // on the second particle of a cross-block slot
    // The contact history per candidate (World::pairHistory, dem/contact_history.h):
    Vec3* spring;              // tangential spring [m]
    Vec3* rolling;             // rolling spring [N m], or null if none is kept
    std::uint8_t* mayBeActive; // whether the contact may be formed (ContactHistoryStore::formed)
    Real* scalars;             // the history scalars (ContactHistoryStore::scalars), or null if none
    unsigned scalarCount;      // per candidate

    explicit PairSink(World& world)
        : force(world.particles.force.data()), torque(world.particles.torque.data()),
          deferredIndex(world.neighbors.activeDeferred.data()), deferred(world.neighbors.deferred.data()),
          spring(world.pairHistory.spring.data()),
          rolling(world.pairHistory.keepRolling ? world.pairHistory.rolling.data() : nullptr),
          mayBeActive(world.pairHistory.formed.data()),
          scalars(world.pairHistory.scalarCount ? world.pairHistory.scalars.data() : nullptr),
          scalarCount(world.pairHistory.scalarCount)
    {
    }

    /// Candidate k's history as the contact law takes it, and stores it back (ContactHistoryStore::at
    /// and set, through the sink's bases).
    ContactHistory history(std::size_t k) const
    {
        ContactHistory h{spring[k], rolling ? rolling[k] : Vec3{}, Real(mayBeActive[k])};
        for (unsigned s = 0; s < scalarCount; ++s)
            h.scalars[s] = scalars[k * scalarCount + s];
        return h;
    }
    void setHistory(std::size_t k, const ContactHistory& h) const
    {
        spring[k] = h.tangentialSpring;
        if (rolling)
            rolling[k] = h.rollingSpring;
        mayBeActive[k] = h.formed != 0;
        for (unsigned s = 0; s < scalarCount; ++s)
            scalars[k * scalarCount + s] = h.scalars[s];
    }

    static void add(PaddedVec3& sum, const Vec3& v)
    {
        sum.x += v.x;
        sum.y += v.y;
        sum.z += v.z;
    }
    static void subtract(PaddedVec3& sum, const Vec3& v)
    {
        sum.x -= v.x;
        sum.y -= v.y;
        sum.z -= v.z;
    }

    /// Adds the contact of candidate k: force f [N] on i and -f on j, torques ti on i and tj on j
    /// [N m].
    void add(std::uint32_t k, std::uint32_t i, std::uint32_t j, const Vec3& f, const Vec3& ti,
             const Vec3& tj) const
    {
        add(force[i], f);
        add(torque[i], ti);
        const std::uint32_t d = deferredIndex[k];
        if (d == NeighborList::kInBlock)
        {
            subtract(force[j], f);
            add(torque[j], tj);
        }
        else
        {
            deferred[d].force = -f;
            deferred[d].torque = tj;
        }
    }
};

/// A pair kernel: evaluates the touching contacts [0, count) of a batch (selected by the selection
/// pass) into the sink in lane order, folding their overlaps into `worst`. `uniform`: the law of a
/// world with a single material pair, else null (the pair table is read per contact).
using PairKernel = void (*)(const World&, const PairSink&, Real dt, std::size_t count, WorstOverlap& worst,
                            batch::PairBatch&, const batch::UniformLaw* uniform);

/// The pair kernel compiled for `isa` (four lanes with AVX2, two portable).
PairKernel pairKernelFor(exec::Isa isa);

/// A pair contact's results: force on i [N] (-force on j), torques on i and j [N m], overlap [m].
struct PairContactResult
{
    Vec3 force, torqueI, torqueJ;
    Real overlap;
};

/// Spheres i and j at separation x_i - x_j (or x_i minus j's periodic image) [m] through the
/// contact frame and the general contact law (any model), with m* [kg]; `history` is read and
/// updated. The one scalar evaluation of a pair (pairContactScalar, the periodic pairs).
PairContactResult pairContactAt(const World& world, std::uint32_t i, std::uint32_t j, const Vec3& separation,
                                Real effectiveMass, ContactHistory& history, Real dt);

/// Touching candidate k through the general contact law (any model), added into the sink.
void pairContactScalar(const World& world, const PairSink& sink, Real dt, std::size_t k, WorstOverlap& worst);

} // namespace veridem::dem
