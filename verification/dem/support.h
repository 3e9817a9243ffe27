// Shared set-ups and measurement helpers for the DEM verification cases: the paper's two balls,
// single-sphere worlds, a stepping loop with progress, and small fits.
#pragma once

#include "case.h"
#include "core/constants.h"
#include "dem/paper_balls.h"
#include "dem/time_step.h"
#include "dem/world.h"

#include <array>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <functional>
#include <string>
#include <vector>

namespace veridem::verify
{

using dem::Material;
using dem::World;

inline constexpr Real kG = kStandardGravity; // [m/s^2]

inline Real sphereMass(Real density, Real radius)
{
    return density * 4.0 / 3.0 * kPi * radius * radius * radius;
}

/// A world with one material and gravity g (vector).
inline World worldWith(const Material& material, Vec3 gravity)
{
    World w;
    w.addMaterial(material);
    w.gravity = gravity;
    return w;
}

/// A horizontal fixed plane z = 0 (normal +z) of material 0.
inline dem::Wall floorWall()
{
    dem::Wall wall;
    wall.name = "floor";
    wall.shape = dem::PlaneShape{{0, 0, 0}, {0, 0, 1}};
    return wall;
}

/// Steps `world` for `duration` [s] with step dt [s]; calls observe(world) after every step.
/// Prints progress on stderr for runs longer than a few seconds when requested. Throws
/// SimulationError if the state becomes non-finite.
void runFor(World& world, Real duration, Real dt, const CaseContext& context, const std::string& label,
            const std::function<void(const World&)>& observe);

/// Least-squares slope of y(x).
Real fitSlope(const std::vector<Real>& x, const std::vector<Real>& y);

/// Algebraic least-squares circle through points (x, y): returns {cx, cy, radius}.
std::array<Real, 3> fitCircle(const std::vector<Real>& x, const std::vector<Real>& y);

/// Time at which a linearly interpolated signal crosses zero between (t0, y0) and (t1, y1).
inline Real crossingTime(Real t0, Real y0, Real t1, Real y1)
{
    return t0 + (t1 - t0) * y0 / (y0 - y1);
}

} // namespace veridem::verify
