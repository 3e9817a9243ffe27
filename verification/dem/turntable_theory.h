// Rigid rolling of a ball on a flat, possibly tilted, rotating table (BENCHMARKS 1b, equation T2),
// integrated with classical RK4. This is the "theory" the DEM trajectories are compared with.
//
// Table coordinates (u, v) in the table plane, k = table normal, the table spins at Omega about k.
// The ball (radius a, I = 2/5 m a^2) rolls without slipping; u_rel = v - Omega k x r is the centre's
// velocity relative to the table material beneath it. With the Beer-Johnson torque
// M = -muR N w_rel / |w_rel| (w_rel = w - Omega k, N = m gN, gN = g cos(alpha)):
//
//   dr/dt = v
//   dv/dt = (2/7) Omega k x v + (5/7) gPlane - (5/7) (muR gN / a) (u_rel / a) / |w_rel|      (T2)
//   ds/dt = -(5/2) (muR gN / a^2) (s - Omega) / |w_rel|                                     (twist)
//   |w_rel| = sqrt(|u_rel|^2 / a^2 + (s - Omega)^2),   s = w . k
//
// With `twist` false the torque opposes only the rolling part w_rel,perp (|w_rel| = |u_rel| / a): this
// is BENCHMARKS' T2 as printed, M = -muR N unit(w_rel,perp). With `twist` true it is the engine's
// default convention (the torque opposes the whole relative angular velocity, twist included), which
// dilutes the rolling torque by |w_perp| / |w_rel| while the ball's spin about k differs from Omega
// (the balls start with s = 0) and relaxes s towards Omega. The two coincide once s = Omega.
// With `absoluteFrame` the torque opposes the ball's own w (EDEM "standard", MUSEN): twistRate = s,
// so the spin the ball shares with the table dilutes the rolling torque and is itself braked.
//
// Guiding centre: c = r + k x v / omega_o, rho = |v| / omega_o with omega_o = (2/7) Omega. Far from
// the axis (|c| >> (5/7) rho) the centre drifts at  dc/dt = V_t k x g_hat - V_r c_hat  with
// V_t = (5/2) g sin(alpha) / Omega and V_r = (5/2) muR g cos(alpha) / (a Omega); an orbit centred on
// the axis keeps its centre and grows at drho/dt = V_r.
#pragma once

#include "core/vec3.h"

#include <cmath>

namespace veridem::verify
{

struct RollingTableParams
{
    Real omega = 0;             // table angular velocity about k [rad/s]
    Vec3 gravityInPlane;        // in-plane part of gravity, table coordinates (z = 0) [m/s^2]
    Real gravityNormal = 0;     // g cos(alpha) [m/s^2]
    Real rollingFriction = 0;   // muR [m]
    Real radius = 0;            // a [m]
    bool twist = true;          // torque opposes the whole w_rel (engine default) or only its rolling part
    bool absoluteFrame = false; // torque opposes the ball's own w (type A absolute frame): the
                                // spin about k counts in full, not relative to Omega
};

struct RollingTableState
{
    Vec3 r, v;     // in-plane position and velocity, table coordinates (z = 0) [m, m/s]
    Real spin = 0; // w . k [rad/s]
};

inline Vec3 kCross(const Vec3& a)
{
    return {-a.y, a.x, 0};
} // k x a for in-plane a

inline RollingTableState rollingTableRate(const RollingTableParams& p, const RollingTableState& s)
{
    const Vec3 slip = s.v - p.omega * kCross(s.r); // u_rel [m/s]
    const Real rolling = length(slip) / p.radius;  // |w_perp| [rad/s]
    const Real twistRate = p.absoluteFrame ? s.spin : p.twist ? s.spin - p.omega : 0.0;
    const Real relative = std::sqrt(rolling * rolling + twistRate * twistRate); // |w_rel|
    const Real resistance = p.rollingFriction * p.gravityNormal / p.radius;     // muR gN / a [m/s^2]
    RollingTableState rate;
    rate.r = s.v;
    rate.v = (2.0 / 7.0) * p.omega * kCross(s.v) + (5.0 / 7.0) * p.gravityInPlane;
    if (relative > 0)
    {
        rate.v -= (5.0 / 7.0) * resistance * (slip / p.radius) / relative;
        rate.spin = -2.5 * resistance / p.radius * twistRate / relative;
    }
    return rate;
}

/// One classical RK4 step of length h [s].
inline RollingTableState rollingTableStep(const RollingTableParams& p, const RollingTableState& s, Real h)
{
    auto add = [](const RollingTableState& a, const RollingTableState& b, Real f) {
        return RollingTableState{a.r + f * b.r, a.v + f * b.v, a.spin + f * b.spin};
    };
    const RollingTableState k1 = rollingTableRate(p, s);
    const RollingTableState k2 = rollingTableRate(p, add(s, k1, 0.5 * h));
    const RollingTableState k3 = rollingTableRate(p, add(s, k2, 0.5 * h));
    const RollingTableState k4 = rollingTableRate(p, add(s, k3, h));
    RollingTableState next = s;
    next.r += (h / 6.0) * (k1.r + 2.0 * k2.r + 2.0 * k3.r + k4.r);
    next.v += (h / 6.0) * (k1.v + 2.0 * k2.v + 2.0 * k3.v + k4.v);
    next.spin += (h / 6.0) * (k1.spin + 2.0 * k2.spin + 2.0 * k3.spin + k4.spin);
    return next;
}

/// Guiding centre c = r + k x v / omega_o of a state [m].
inline Vec3 orbitCentre(const RollingTableState& s, Real omega)
{
    return s.r + kCross(s.v) / (2.0 / 7.0 * omega);
}
/// Orbit radius rho = |v| / omega_o [m].
inline Real orbitRadius(const RollingTableState& s, Real omega)
{
    return length(s.v) / (2.0 / 7.0 * omega);
}

} // namespace veridem::verify
