// Stable time step of the explicit integrator.
//
// For every material pair present (particle-particle with the two smallest masses, and
// particle-wall with m* = m) the contact is a damped oscillator:
//   normal       omega_n = sqrt(kn / m*)
//   tangential   omega_t = sqrt(kt / ((2/7) m*))   (sphere contact point: effective mass 2/7 m*)
//   EPSD rolling omega_r = sqrt(kr / I_r)
// Velocity Verlet is stable for dt < (2 / omega_max) (sqrt(1 + zeta^2) - zeta). For Hertz the
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

/// characteristicSpeed [m/s]: impact speed used to size Hertz stiffness (ignored for linear).
TimeStepEstimate estimateTimeStep(const World& world, Real characteristicSpeed);

} // namespace veridem::dem
