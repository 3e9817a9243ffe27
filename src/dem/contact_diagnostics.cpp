#include "dem/contact_diagnostics.h"

#include "dem/contact_frame.h"
#include "dem/contact_input.h"
#include "dem/contact_law.h"
#include "dem/pair_kernel.h"

#include <cmath>

namespace veridem::dem
{

Real normalElasticEnergy(const PairParams& p, Real overlap, Real effectiveRadius,
                         const ContactHistory& history)
{
    if (p.normalModel == NormalModel::Jkr) // a formed contact: also at delta_c < delta <= 0
        return jkrStoredEnergy(p.effectiveModulus, effectiveRadius, p.workOfAdhesion, overlap);
    if (overlap <= 0)
        return 0;
    switch (p.normalModel)
    {
    case NormalModel::Linear:
        return 0.5 * p.kn * overlap * overlap;
    case NormalModel::Hertz:
        return 0.4 * hertzElasticForce<Real>(p.effectiveModulus, effectiveRadius, overlap) * overlap;
    case NormalModel::Dmt:
        return 0.4 * hertzElasticForce<Real>(p.effectiveModulus, effectiveRadius, overlap) * overlap -
               dmtPullOffForce<Real>(effectiveRadius, p.workOfAdhesion) * overlap;
    case NormalModel::Jkr: // above
        break;
    case NormalModel::Thornton: // the work its unloading branch gives back (history: delta_max)
        return thorntonStoredEnergy(p.effectiveModulus, effectiveRadius, p.yieldPressure, overlap,
                                    history.scalars[0]);
    }
    return 0;
}

namespace
{

/// The record of one contact from the law's output and terms; `start` is the history before the
/// law ran, `history` after. The springs' energies and the slip work: docs/measurements.md.
ContactRecord recordOf(const PairParams& params, const ContactInput& in, const ContactOutput& out,
                       const LawTerms& terms, const ContactHistory& history)
{
    ContactRecord r;
    r.normal = in.normal;
    r.overlap = in.overlap;
    r.normalForce = out.normalForce * in.normal;
    r.tangentialForce = out.tangentialForce;
    r.rollingTorque = out.rollingTorque;
    r.normalDamping = terms.dampingNormalForce * in.normal;
    r.tangentialDamping = terms.tangentialDamping;
    const Real kt = terms.coefficients.kt, kr = terms.rollingStiffness;
    r.rollingDissipative =
        params.rollingModel == RollingModel::Epsd ? terms.rollingDamping : out.rollingTorque;
    r.normalEnergy = normalElasticEnergy(params, in.overlap, in.effectiveRadius, history);
    r.tangentialEnergy = 0.5 * kt * lengthSquared(history.tangentialSpring);
    r.tangentialEnergyBefore = 0.5 * kt * lengthSquared(terms.tangentialStart);
    // Slip work, midpoint in the spring: kt (xi0 + xi1)/2 . (xi_trial - xi1).
    r.frictionWork = 0.5 * kt *
                     dot(terms.tangentialStart + history.tangentialSpring,
                         terms.tangentialTrial - history.tangentialSpring);
    if (params.rollingModel == RollingModel::Epsd && kr > 0)
    {
        r.rollingEnergy = 0.5 * lengthSquared(history.rollingSpring) / kr;
        r.rollingEnergyBefore = 0.5 * lengthSquared(terms.rollingStart) / kr;
        r.rollingSlipWork =
            0.5 *
            dot(terms.rollingStart + history.rollingSpring, terms.rollingTrial - history.rollingSpring) / kr;
    }
    return r;
}

} // namespace

std::vector<ContactRecord> evaluateContacts(const World& world, Real dt, Real* brokenEnergy)
{
    std::vector<ContactRecord> records;
    const ParticleStore& p = world.particles;
    const NeighborList& list = world.neighbors;
    // On an MPI rank (world.ranks) only the contacts it books, so that each is booked once over the
    // ranks: a pair whose particle of lower id is its own, a wall contact of its own particle.
    const std::size_t own = world.ranks ? world.ranks->ownedParticles() : p.size();
    const auto books = [&](std::uint32_t i, std::uint32_t j) { return (p.id[i] < p.id[j] ? i : j) < own; };
    // Pairs: the contact frame of the force stage (pairContactFrame, contact_frame.h), within the
    // touch criterion's reach as the force stage passes them to the law; recorded while formed
    // (JKR: the law's formed flag; every other model: delta > 0). `separation`: x_i - x_j, or x_i
    // minus j's periodic image [m].
    // `historyOf()`: a copy of its history (the world keeps its own), read only for a touching pair.
    const auto pairContact = [&](std::uint32_t i, std::uint32_t j, const Vec3& separation, Real effectiveMass,
                                 const auto& historyOf)
    {
        if (!books(i, j))
            return;
        const Real ri = p.radius[i], rj = p.radius[j];
        const PairParams& params = world.pairs(p.material[i], p.material[j]);
        const bool jkr = params.normalModel == NormalModel::Jkr;
        const Real touching = ri + rj + (jkr ? list.reach : 0);
        if (lengthSquared(separation) >= touching * touching)
            return;
        const ContactFrameOf<Real> f = pairContactFrame<Real>(
            separation, ri, rj, p.velocity[i] - p.velocity[j], p.angularVelocity[i], p.angularVelocity[j]);
        const ContactInput in = pairContactInput(p, i, j, f, effectiveMass);
        const Real leverI = f.leverI, leverJ = f.leverJ;
        ContactHistory history = historyOf();
        const bool wasFormed = history.formed != 0;
        LawTerms terms;
        const ContactOutput out = evaluateContactReporting(params, in, history, dt, terms);
        if (jkr && history.formed == 0)
        {
            if (wasFormed && brokenEnergy) // it breaks in this step
                *brokenEnergy +=
                    jkrBreakingEnergy(params.effectiveModulus, in.effectiveRadius, params.workOfAdhesion);
            return;
        }
        ContactRecord r = recordOf(params, in, out, terms, history);
        r.i = i;
        r.partner = j;
        r.leverI = leverI;
        r.leverJ = leverJ;
        r.point = p.position[i] - leverI * in.normal;
        records.push_back(r);
    };
    for (std::size_t k = 0; k < list.size(); ++k)
    {
        const std::uint32_t i = list.first[k], j = list.second[k];
        // m* as the force stage takes it (NeighborList::activeMass; a frozen particle's is infinite)
        const Real effectiveMass = p.fixed[i]   ? p.mass[j]
                                   : p.fixed[j] ? p.mass[i]
                                                : effectivePairMass(p.mass[i], p.mass[j]);
        pairContact(i, j, p.position[i] - p.position[j], effectiveMass,
                    [&]
                    {
                        const std::size_t a = list.candidateOfSlot(k);
                        return a == NeighborList::kNotCandidate ? ContactHistory{} : world.pairHistory.at(a);
                    });
    }
    // Pairs through a periodic face (dem/periodic.h), in list order, with the shift the force
    // stage subtracts.
    const PeriodicPairs& periodic = world.periodicPairs;
    for (std::size_t k = 0; k < periodic.size(); ++k)
    {
        const std::uint32_t i = periodic.first[k], j = periodic.second[k];
        pairContact(i, j, (p.position[i] - p.position[j]) - periodic.shift[k], periodic.mass[k],
                    [&] { return periodic.history.at(k); });
    }
    // Formed JKR candidates beyond the reach: the force stage opens them without the law.
    if (brokenEnergy && list.reach > 0)
        for (std::size_t a = 0; a < list.activeFirst.size(); ++a)
        {
            const std::uint32_t i = list.activeFirst[a], j = list.activeSecond[a];
            const PairParams& params = world.pairs(p.material[i], p.material[j]);
            const Real touching = p.radius[i] + p.radius[j] + list.reach;
            if (world.pairHistory.formed[a] && params.normalModel == NormalModel::Jkr && books(i, j) &&
                lengthSquared(p.position[i] - p.position[j]) >= touching * touching)
                *brokenEnergy +=
                    jkrBreakingEnergy(params.effectiveModulus, pairEffectiveRadius(p.radius[i], p.radius[j]),
                                      params.workOfAdhesion);
        }
    // Walls: the contact frame of the force stage (wallContactFrame, contact_frame.h).
    const WallContactList& walls = world.wallContacts;
    if (walls.start.size() != p.size() + 1)
        return records;
    for (std::size_t k = 0; k < walls.size(); ++k)
    {
        const std::uint32_t i = walls.particle[k];
        if (i >= own)
            continue;
        const Wall& wall = world.walls[walls.wall[k]];
        const Real r = p.radius[i];
        const WallGap gap = std::holds_alternative<MeshShape>(wall.shape)
                                ? walls.meshSlotGapAsStored(k, wall, p.position[i], r)
                                : wallGap(wall, p.position[i], r);
        if (!gap.touching)
            continue;
        const PairParams& params = world.pairs(p.material[i], wall.material);
        const ContactInput in =
            wallContactInput(particleState(p, i), surfaceMotion(wall, -0.5 * dt), gap, dt);
        ContactHistory history = world.wallHistory.at(k);
        LawTerms terms;
        const ContactOutput out = evaluateContactReporting(params, in, history, dt, terms);
        ContactRecord rec = recordOf(params, in, out, terms, history);
        rec.i = i;
        rec.partner = walls.wall[k];
        rec.wall = true;
        rec.leverI = r;
        rec.point = p.position[i] + wallArm(r, gap.normal);
        records.push_back(rec);
    }
    return records;
}

} // namespace veridem::dem
