// A scalar diagnostic pass over the touching contacts: the contact law (contact_law.h) evaluated
// on a COPY of each contact's history, in the state the force stage sees, reporting per contact
// the force and its split into spring and dashpot parts, the contact point, the stored elastic
// energy and the energy dissipated by slip over the step (LawTerms). The world is not changed, so
// a run with the pass gives the same bits as one without. Used by the energy ledger
// (energy_ledger.h), the contact network output (io/contact_output.h) and the region measures
// (region_measures.h). docs/measurements.md derives what is reported.
#pragma once

#include "dem/world.h"

#include <cstdint>
#include <vector>

namespace veridem::dem
{

struct ContactRecord
{
    std::uint32_t i = 0;       // particle
    std::uint32_t partner = 0; // the other particle (wall == false) or the wall index
    bool wall = false;
    Vec3 normal;             // unit, from the partner towards i
    Vec3 point;              // contact point [m]
    Real leverI = 0;         // distance from i's centre to the contact point [m]
    Real leverJ = 0;         // from the partner's centre (pairs) [m]
    Real overlap = 0;        // [m]
    Vec3 normalForce;        // on i, spring + dashpot [N]
    Vec3 tangentialForce;    // on i [N]
    Vec3 rollingTorque;      // rolling/twisting resistance torque on i [N m]
    Vec3 normalDamping;      // dashpot part of normalForce [N]
    Vec3 tangentialDamping;  // dashpot part of tangentialForce [N]
    Vec3 rollingDissipative; // the part of rollingTorque whose power is dissipated at once: all
                             // of it (constant torque, viscous) or the EPSD dashpot [N m]
    // Energies [J] of the springs: the normal one at this overlap; the tangential and EPSD rolling
    // ones after the step, and as stored before it (at this overlap: kt and kr are this step's).
    Real normalEnergy = 0, tangentialEnergy = 0, rollingEnergy = 0;
    Real tangentialEnergyBefore = 0, rollingEnergyBefore = 0;
    Real frictionWork = 0;    // dissipated by tangential slip over the step [J]
    Real rollingSlipWork = 0; // dissipated by EPSD rolling slip over the step [J]

    /// The energy in the springs after the step [J].
    Real elasticEnergy() const { return normalEnergy + tangentialEnergy + rollingEnergy; }
    /// The energy in the springs as stored before the step [J] (with dt = 0, the world's now).
    Real storedEnergy() const { return normalEnergy + tangentialEnergyBefore + rollingEnergyBefore; }
};

/// Every touching pair (in slot order) and wall contact (in slot order) of the world's current
/// lists, evaluated with step dt [s] as the force stage would (dt = 0: the law at the current
/// state with no increment, as for a run's initial forces). The contact lists must be current
/// (step()'s observer point, or between steps). A JKR pair is a contact while the law keeps it
/// formed (also at delta_c < delta <= 0). If `brokenEnergy` is given, the energy that the formed
/// JKR contacts breaking in this step lose, jkrBreakingEnergy each (models/cohesion.h), is added
/// to it [J]. On an MPI rank (world.ranks): the contacts it books, each contact booked by one rank
/// (a pair by the owner of its particle of lower id, a wall contact by its particle's owner).
std::vector<ContactRecord> evaluateContacts(const World& world, Real dt, Real* brokenEnergy = nullptr);

/// The energy stored in the normal spring of a formed pair at overlap delta [m] [J]: the integral
/// of the law's elastic normal force from 0 to delta (linear kn delta^2 / 2; Hertz
/// (8/15) E* sqrt(R*) delta^(5/2); DMT that minus 2 pi w R* delta; JKR jkrStoredEnergy,
/// models/cohesion.h, also for delta_c < delta <= 0; Thornton the work its unloading branch from
/// delta_max = history.scalars[0] [m] gives back, thorntonStoredEnergy). R* [m].
Real normalElasticEnergy(const PairParams& p, Real overlap, Real effectiveRadius,
                         const ContactHistory& history = {});

} // namespace veridem::dem
