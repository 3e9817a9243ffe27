// The paper's spherically concave rotating dish (section 4.2, Figs. 10-12; BENCHMARKS 1c) as a
// reusable set-up, and the rigid-rolling reference integrator of BENCHMARKS 1c.
//
// Dish: the inside of a sphere of radius R = 20 m whose lowest point is the origin (sphere centre
// C = (0, 0, R)), rotating at Omega about the vertical axis through C. Ball (Table 1): a = 3 mm,
// rho = 7500, mu = 0.5, e = 0.8, muR = 5e-5 m (type A), k = 1e3 N/m. Released at rest (lab frame,
// no spin) with its centre at horizontal radius r0 at 180 deg, at its equilibrium overlap.
// Heights h are those of the ball centre above its lowest possible position (z = a).
//
// Equilibrium (paper eq. 5, with the ball-size correction): a ball co-rotating at Omega sits at
//   h_c* = (R - a) - g / Omega^2   for Omega > Omega_c = sqrt(g / (R - a)), else 0.
// Rolling-resistance band (BENCHMARKS 1c): a type-A torque decelerates relative motion wherever the
// in-plane effective force per unit normal force is below muR' = muR / a, i.e. within
//   |dh| <= rho_s muR' / sin(theta*)   about h_c* (rho_s = R - a, cos(theta*) = g / (Omega^2 rho_s)),
//   r <= rho_s muR' / (1 - Omega^2 rho_s / g)   below Omega_c.
//
// Reference integrator (BENCHMARKS 1c, rigid rolling on the sphere of radius rho_s about C; n is the
// unit vector from C to the ball centre, P = C + R n the contact point, V(P) = Omega R z x n):
//   (dv/dt)_t = (2/7) [ -(5/2) g z_t - (a/rho_s) (w x v)_t + (Omega R / rho_s) (z x v)_t ] - 5/(7 m a) (M x
//   n)_t dv/dt . n = -|v|^2 / rho_s w         = w_n n + n x (Omega R z x n - v) / a dw_n/dt   = M . n / I + w
//   . v / rho_s N         = m (|v|^2 / rho_s - g z . n),   M = -muR N unit(w - Omega z)  (its part normal to
//   n
//                                                  removed when twist resistance is off)
#pragma once

#include "dem/walls/wall.h"
#include "mesh_floors.h"
#include "support.h"

namespace veridem::verify
{

inline constexpr Real kDishRadius = 20.0; // R [m]

struct DishSetup
{
    Real omega = 0.9;         // [rad/s]
    Real releaseRadius = 1.0; // horizontal radius of the ball centre at release [m]
    bool twist = true;        // rolling torque resists twist (engine default)
    Real meshEdge = 0;        // > 0: the dish as a triangle mesh of this edge [m] (meshedSphericalCap)
};

/// Polar angle [rad] from the bottom up to which a meshed dish is built: 86 deg, a ball-centre
/// height of 18.6 m, above h_c* at every Omega of the meshed case (17.54 m at 2 rad/s).
inline constexpr Real kMeshedDishPolar = 86.0 * kPi / 180.0;

/// Ball-centre equilibrium height h_c* [m] (0 below Omega_c).
inline Real dishEquilibriumHeight(Real omega, Real g = kG)
{
    const Real rhoS = kDishRadius - kDishBallRadius;
    return omega * omega * rhoS > g ? rhoS - g / (omega * omega) : 0.0;
}

inline World dishWorld(const DishSetup& s)
{
    Material ball = dishBall();
    ball.rollingTwist = s.twist;
    World world = worldWith(ball, {0, 0, -kG});
    const Vec3 sphereCentre{0, 0, kDishRadius};
    dem::Wall dish = s.meshEdge > 0
                         ? meshedSphericalCap(sphereCentre, kDishRadius, kMeshedDishPolar, s.meshEdge)
                         : dem::Wall{};
    dish.name = "dish";
    if (s.meshEdge <= 0)
        dish.shape = dem::DishShape{{0, 0, 0}, kDishRadius};
    dish.motion.angularVelocity = {0, 0, s.omega};
    dish.motion.rotationCentre = {0, 0, kDishRadius};
    world.walls.push_back(dish);

    const Real a = kDishBallRadius;
    const Real m = sphereMass(ball.density, a);
    const Real rhoS = kDishRadius - a;
    const Real cosTheta = std::sqrt(1 - (s.releaseRadius / rhoS) * (s.releaseRadius / rhoS));
    const Real distance = rhoS + m * kG * cosTheta / ball.normalStiffness; // equilibrium overlap
    Vec3 x{-s.releaseRadius, 0,
           kDishRadius - std::sqrt(distance * distance - s.releaseRadius * s.releaseRadius)};
    if (s.meshEdge > 0)
    {
        // A facet lies inside the sphere by up to its sag (edge^2 / (8 R) = 0.4 mm at 0.25 m): put
        // the ball at the same equilibrium overlap on the facet under it, along the facet's normal.
        const dem::WallGap gap = dem::wallGap(std::get<dem::MeshShape>(dish.shape), {}, x, a);
        x += (gap.overlap - m * kG * gap.normal.z / ball.normalStiffness) * gap.normal;
    }
    world.particles.add(x, {}, {}, a, ball.density, 0);
    dem::prepare(world);
    return world;
}

struct DishState
{
    Vec3 x;        // ball centre relative to the sphere centre C (|x| = rho_s) [m]
    Vec3 v;        // velocity (tangent to the sphere) [m/s]
    Real spin = 0; // w . n [rad/s]
};

struct DishTheory
{
    Real omega = 0;
    bool twist = true;
    Real g = kG;
    Real a = kDishBallRadius;
    Real rhoS = kDishRadius - kDishBallRadius;
    Real muR = 5e-5;

    Vec3 angularVelocity(const DishState& s) const
    {
        const Vec3 n = s.x / length(s.x);
        const Vec3 z{0, 0, 1};
        return s.spin * n + cross(n, omega * kDishRadius * cross(z, n) - s.v) / a;
    }

    DishState rate(const DishState& s) const
    {
        const Vec3 n = s.x / length(s.x);
        const Vec3 z{0, 0, 1};
        const Vec3 w = angularVelocity(s);
        const Real normalPerMass = dot(s.v, s.v) / rhoS - g * dot(z, n); // N / m
        Vec3 relative = w - omega * z;
        if (!twist)
            relative -= dot(relative, n) * n;
        const Real relativeLength = length(relative);
        // Torque per unit mass, M / m = -muR (N/m) unit(w_rel).
        const Vec3 torquePerMass =
            relativeLength > 0 ? (-muR * normalPerMass / relativeLength) * relative : Vec3{};
        auto tangential = [&](const Vec3& u) { return u - dot(u, n) * n; };
        const Vec3 accelTangent = (2.0 / 7.0) * tangential(-2.5 * g * z - (a / rhoS) * cross(w, s.v) +
                                                           (omega * kDishRadius / rhoS) * cross(z, s.v)) -
                                  (5.0 / (7.0 * a)) * tangential(cross(torquePerMass, n));
        const Real inertiaPerMass = 0.4 * a * a;
        return {s.v, accelTangent - (dot(s.v, s.v) / rhoS) * n,
                dot(torquePerMass, n) / inertiaPerMass + dot(w, s.v) / rhoS};
    }

    /// One RK4 step; the state is projected back onto the sphere afterwards.
    DishState step(const DishState& s, Real h) const
    {
        auto add = [](const DishState& p, const DishState& q, Real f) {
            return DishState{p.x + f * q.x, p.v + f * q.v, p.spin + f * q.spin};
        };
        const DishState k1 = rate(s), k2 = rate(add(s, k1, h / 2)), k3 = rate(add(s, k2, h / 2)),
                        k4 = rate(add(s, k3, h));
        DishState next{s.x + (h / 6) * (k1.x + 2.0 * k2.x + 2.0 * k3.x + k4.x),
                       s.v + (h / 6) * (k1.v + 2.0 * k2.v + 2.0 * k3.v + k4.v),
                       s.spin + (h / 6) * (k1.spin + 2 * k2.spin + 2 * k3.spin + k4.spin)};
        const Vec3 n = next.x / length(next.x);
        next.x = rhoS * n;
        next.v -= dot(next.v, n) * n;
        return next;
    }
};

} // namespace veridem::verify
