// Coulomb friction with a tangential elastic spring and a viscous term (Xiang, Munjiza, Latham &
// Guises, paper eqs 1-2; veridem BENCHMARKS.md section 1a "robust algorithm" and 6.3).
// Pure function of one contact's history; the caller stores the returned spring.
//
//   xi  <- xi + v_t dt                      (v_t: relative tangential velocity at the positions' time level)
//   F*  =  -k_t xi - eta_t v_t              (paper eq. 1: elastic part plus viscous part)
//   |F*| <= mu |F_n|  -> stick, F_t = F*
//   otherwise         -> slide, F_t = mu |F_n| F*/|F*|   (paper eq. 2)
//                        and the spring is reset to the cap: xi = -(F_t + eta_t v_t) / k_t,
//                        so the dashpot sits inside the cap and the stored spring never exceeds it.
// In 2D the spring is a scalar along the current contact tangent, so re-projecting it onto the
// rotated tangent keeps its magnitude by construction.
#pragma once

#include "core/vec3.h"

#include <cmath>

namespace veridem::fdem
{

struct FrictionResult
{
    Real force = 0;       ///< F_t along the tangent, acting on the contactor [N/m]
    Real spring = 0;      ///< updated xi [m]
    bool sliding = false; ///< true when the Coulomb cap was active
};

/// spring: xi from the previous step [m]; tangentialVelocity: v_t [m/s]; dt [s];
/// stiffness: k_t > 0 [N/m per m]; damping: eta_t [N s/m per m]; cap: mu |F_n| [N/m].
inline FrictionResult coulombFriction(Real spring, Real tangentialVelocity, Real dt, Real stiffness,
                                      Real damping, Real cap)
{
    FrictionResult r;
    r.spring = spring + tangentialVelocity * dt;
    const Real trial = -stiffness * r.spring - damping * tangentialVelocity;
    if (std::abs(trial) <= cap)
    {
        r.force = trial;
        return r;
    }
    r.force = std::copysign(cap, trial);
    r.spring = -(r.force + damping * tangentialVelocity) / stiffness;
    r.sliding = true;
    return r;
}

} // namespace veridem::fdem
