// Stable time step of the explicit integrator.
//
// For every material pair present (particle-particle with the two smallest masses, and
// particle-wall with m* = m) the contact is a damped oscillator:
//   normal       omega_n = sqrt(kn / m*)
//   tangential   omega_t = sqrt(kt / ((2/7) m*))   (sphere contact point: effective mass 2/7 m*)
//   EPSD rolling omega_r = sqrt(kr / I_r)
// Velocity Verlet is stable for dt < (2 / omega_max) (sqrt(1 + zeta^2) - zeta).
// Viscous (type B) rolling, M = -c_r Fn R_r^2 w_rel, is a first-order decay of w_rel with
// rate lambda = c_r Fn R_r^2 / I_r; its explicit update is stable only for lambda dt < 2
// (derivation in time_step.cpp), with Fn the peak force of an impact at the characteristic speed,
// or the lighter particle's weight if larger. For Hertz the
// stiffness 2 E* sqrt(R* delta) is taken at the maximum overlap of an impact at the
// characteristic speed (R* of the two smallest spheres). Accuracy needs far smaller steps:
// the recommended step is tc / 50 (e within 0.3 %, BENCHMARKS 2.1).
#pragma once

#include "dem/world.h"

#include <string>

namespace veridem::dem
{

struct TimeStepEstimate
{
    Real critical = 0;     // stability limit [s]
    Real contactTime = 0;  // shortest contact duration tc [s]
    Real recommended = 0;  // tc / 50 [s]
    std::string limitedBy; // which contact sets the limit, for messages
};

/// Stability limit [s] of the explicit update of w under a viscous rolling torque
/// -c_r Fn R_r^2 w_rel: 2 I_r / (c_r Fn R_r^2). coefficient c_r [s/m], normalForce Fn [N],
/// rollingRadius R_r [m], inertia I_r [kg m^2] (reduced moment of inertia of the pair; I for a
/// wall). Infinite when c_r Fn = 0.
Real viscousRollingLimit(Real coefficient, Real normalForce, Real rollingRadius, Real inertia);

/// characteristicSpeed [m/s]: impact speed used to size Hertz stiffness (ignored for linear).
TimeStepEstimate estimateTimeStep(const World& world, Real characteristicSpeed);

} // namespace veridem::dem
