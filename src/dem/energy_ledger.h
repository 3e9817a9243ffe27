// The energy ledger of a run (docs/measurements.md derives it): the work of gravity and of the
// walls, and the energy dissipated by normal damping, tangential damping, friction (slip) and
// rolling resistance, accumulated step by step from the contact law's own force terms
// (contact_diagnostics.h), so that
//     E_kin + E_elastic - W_gravity - W_walls + D_normal + D_tangential + D_friction + D_rolling
//       + D_adhesion
// equals E_initial up to the integrator's O(dt^2) error. It observes every step (StepObserver):
// a scalar pass over the contacts per step, on request only.
// On MPI ranks each rank's ledger books its share (its own particles' gravity work and kinetic
// energy, the contacts evaluateContacts gives it: each contact on one rank). Every amount is a sum
// over particles or contacts, so the ranks' states add up to the whole run's (forEachAmount;
// distributed/rank_sums.h), however the particles move between ranks.
#pragma once

#include "dem/contact_diagnostics.h"
#include "dem/world.h"

#include <vector>

namespace veridem::dem
{

/// What the ledger accumulates; every field survives a restart (io/dem_checkpoint.cpp).
struct EnergyLedgerState
{
    bool started = false;
    Real initialEnergy = 0;     // E_kin + E_elastic when the ledger started [J]
    Real elasticEnergy = 0;     // stored in the contact springs after the last step [J]
    Real gravityWork = 0;       // [J]
    Real wallWork = 0;          // work of the walls' prescribed motion on the particles [J]
    Real normalDamping = 0;     // dissipated by the normal dashpots [J]
    Real tangentialDamping = 0; // dissipated by the tangential dashpots [J]
    Real friction = 0;          // dissipated by tangential slip [J]
    Real rolling = 0;           // dissipated by rolling resistance [J]
    Real adhesion = 0;          // lost by JKR contacts breaking at delta_c (the hysteresis) [J]
    // The tangential and EPSD rolling springs' energies after the last step [J]: what the next
    // step starts from, so that the energy a spring loses outside the law's increment (its
    // contact opened, or its stiffness changed with the overlap: Hertz-Mindlin) is booked as
    // friction (tangential) or rolling dissipation.
    Real tangentialSpringEnergy = 0, rollingSpringEnergy = 0;
    // The powers at the end of the last step, the left ends of the trapezoids [W].
    Real wallPower = 0, normalDampingPower = 0, tangentialDampingPower = 0, rollingPower = 0;
};

static_assert(sizeof(EnergyLedgerState) == 16 * sizeof(Real), "forEachAmount lists every amount");

/// Calls f(amount) for every amount of the state (all but `started`): each is a sum over particles
/// or contacts.
template <class State, class F> void forEachAmount(State& s, F f)
{
    for (auto* amount : {&s.initialEnergy, &s.elasticEnergy, &s.gravityWork, &s.wallWork, &s.normalDamping,
                         &s.tangentialDamping, &s.friction, &s.rolling, &s.adhesion,
                         &s.tangentialSpringEnergy, &s.rollingSpringEnergy, &s.wallPower,
                         &s.normalDampingPower, &s.tangentialDampingPower, &s.rollingPower})
        f(*amount);
}

/// The particles a ledger books: the store's first bookedParticles() (on an MPI rank its own).
std::size_t bookedParticles(const World& world);

/// The powers of a set of contacts at the velocities `velocity`, `angularVelocity` [m/s, rad/s]
/// (the store's, or on an MPI rank RankExchange::velocitiesAfterStep's) [W] (docs/measurements.md).
struct LedgerPowers
{
    Real wall = 0, normalDamping = 0, tangentialDamping = 0, rolling = 0;
};
LedgerPowers ledgerPowers(const World& world, const std::vector<ContactRecord>& records,
                          const std::vector<Vec3>& velocity, const std::vector<Vec3>& angularVelocity);

class EnergyLedger final : public StepObserver
{
  public:
    /// Sets the initial energy and powers from the world's current state (its contact lists
    /// current: after prepare()), unless the state was restored (started).
    void start(const World& world);
    void beforeForces(const World& world, Real dt) override;
    void afterStep(const World& world, Real dt) override;

    EnergyLedgerState state;

    /// E_kin + E_elastic - W_gravity - W_walls + D (all) - E_initial [J], with E_kin of `world`.
    Real residual(const World& world) const;
    /// D_normal + D_tangential + D_friction + D_rolling + D_adhesion [J].
    Real dissipated() const;

  private:
    std::vector<ContactRecord> records_;           // this step's contacts (beforeForces to afterStep)
    std::vector<Vec3> velocity_, angularVelocity_; // on an MPI rank: afterStep's, ghosts' from their owners
};

} // namespace veridem::dem
