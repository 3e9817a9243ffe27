// Stable time step of the explicit central-difference scheme (BENCHMARKS 1a and 6.1).
//
// Elements: dt_e = 0.98 h_min / c_p, h_min the smallest triangle altitude, c_p = sqrt((lambda + 2 mu)/rho)
//   (checked against power iteration of M^-1 K for CST meshes, BENCHMARKS 1a table). With the viscous
//   stress eta_v D the highest mode has damping ratio xi = eta_v omega_max / (2 (lambda + 2 mu)),
//   omega_max = 2 / dt_e, and the limit shrinks by (sqrt(1 + xi^2) - xi).
// Contact: a node of mass m on the contact spring k_c has dt_c = 2 sqrt(m / k_c) (times the same
//   damping factor for the dashpot's zeta). With k_c = 3 p L / H per edge (world.cpp) and up to two
//   edges of one element and both contact roles acting on a node, k_c = 4 * 3 p_max L_max / H_min is
//   used for every element with a free node (p_max = max(p_n, p_t), m the element's lightest node).
// Joints (fracture/joints.h): each end of a joint ties two nodes with the stiffness (L/2)(p/h) = p/2
//   (h = L) in both directions; a node has up to two joints (the two edges of its corner), so
//   omega_j^2 = 2 (p/2)(1/m_a + 1/m_b), added to the element's omega_e = 2/dt_e (Gershgorin bound):
//   dt_j = 2 / sqrt(omega_e^2 + omega_j^2).
#pragma once

#include "core/vec3.h"

#include <string>

namespace veridem::fdem
{

class World;

/// Damping reduction factor sqrt(1 + xi^2) - xi of the central-difference limit [1].
Real dampingFactor(Real dampingRatio);

/// 0.98 h_min / c_p reduced for the damping ratio xi of the highest mode [s].
Real elementTimeStep(Real minimumAltitude, Real pWaveSpeed, Real dampingRatio);

/// 2 sqrt(m / k) reduced for the damping ratio [s]; mass [kg/m], stiffness [N/m per m].
Real contactTimeStep(Real nodeMass, Real stiffness, Real dampingRatio);

struct TimeStepLimit
{
    Real element = 0;             ///< smallest element limit [s]
    Real contact = 0;             ///< smallest contact limit [s]
    Real joint = INFINITY;        ///< smallest joint limit [s] (infinite without joints)
    Real limit = 0;               ///< min of the two [s]
    std::string describe() const; ///< one line for the log, e.g. "dt_max = 1.2e-06 s (contact ...)"
};

/// Limits of every element that has a free node.
TimeStepLimit stableTimeStep(const World& world);

} // namespace veridem::fdem
