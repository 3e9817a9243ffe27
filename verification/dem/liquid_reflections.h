// "Liquid Reflections" (Liliane Lijn, 1966-68; the artwork that inspired the paper): acrylic balls
// free on a rotating shallow concave dish, colliding with each other. Scene shared by the
// verification case and mirrored by examples/liquid_reflections.toml.
//
// Dish: inside of a sphere of radius R = 1.5 m (lowest point at the origin) turning at
// Omega = 3.2 rad/s, above Omega_c = sqrt(g / (R - a)) = 2.59 rad/s, so each ball's co-rotating
// height is h_c* = (R - a) - g / Omega^2 = 0.502 m (orbit radius 1.10 m).
// Balls: 7 acrylic spheres, a = 40 mm, rho = 1190 kg/m^3 (PMMA), e = 0.8, mu = 0.4, type-A rolling
// friction muR = 4e-4 m (muR' = 0.01), linear kn = 1e6 N/m (static overlap m g / kn = 3 um,
// 1e-4 a), kt = 2/7 kn. Released at rest (lab frame) in a hexagonal cluster centred at r = 0.3 m,
// 180 deg, gaps of 10 mm between neighbours: they start sliding at different speeds and collide.
#pragma once

#include "dem/walls/wall.h"
#include "support.h"

namespace veridem::verify
{

struct LiquidReflectionsScene
{
    Real dishRadius = 1.5;    // R [m]
    Real omega = 3.2;         // [rad/s]
    Real ballRadius = 0.04;   // a [m]
    Real gap = 0.01;          // between neighbouring balls at release [m]
    Real clusterRadius = 0.3; // horizontal radius of the cluster centre [m]
};

inline Material acrylicBall()
{
    Material m;
    m.name = "acrylic";
    m.density = 1190;
    m.normalStiffness = 1e6;
    m.restitution = 0.8;
    m.friction = 0.4;
    m.rollingModel = dem::RollingModel::ConstantTorque;
    m.rollingFrictionLength = 4e-4;
    return m;
}

inline World liquidReflectionsWorld(const LiquidReflectionsScene& s)
{
    World world = worldWith(acrylicBall(), {0, 0, -kG});
    dem::Wall dish;
    dish.name = "dish";
    dish.shape = dem::DishShape{{0, 0, 0}, s.dishRadius};
    dish.motion.angularVelocity = {0, 0, s.omega};
    dish.motion.rotationCentre = {0, 0, s.dishRadius};
    world.walls.push_back(dish);

    // Hexagonal cluster: one ball in the middle, six around it.
    const Real spacing = 2 * s.ballRadius + s.gap;
    const Real rhoS = s.dishRadius - s.ballRadius;
    const Vec3 middle{-s.clusterRadius, 0, 0};
    for (int k = -1; k < 6; ++k)
    {
        Vec3 p = middle;
        if (k >= 0)
            p += spacing * Vec3{std::cos(k * kPi / 3), std::sin(k * kPi / 3), 0};
        const Real r2 = p.x * p.x + p.y * p.y;
        p.z = s.dishRadius - std::sqrt(rhoS * rhoS - r2); // resting on the dish
        world.particles.add(p, {}, {}, s.ballRadius, acrylicBall().density, 0);
    }
    dem::prepare(world);
    return world;
}

} // namespace veridem::verify
