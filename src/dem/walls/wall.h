// Walls: analytic geometry plus prescribed motion. A wall contact goes through the same contact
// law as a particle pair; the wall is a partner of infinite mass whose surface velocity at the
// contact point P is  V(P) = velocity + angularVelocity x (P - rotationCentre).
//
// Shapes (all one-sided; the particle lives on the side the normal points to):
//   Plane     infinite plane through `point` with unit `normal`; optional finite disk radius
//             (a turntable is a disk that rotates about its own normal).
//   Dish      the inside of a sphere of radius R whose lowest point is `lowestPoint`
//             (centre C = lowestPoint + R z); only the lower hemisphere is solid.
//   Cylinder  the lateral surface of a finite circular cylinder, particles inside (a drum) or
//             outside (a post); dem/walls/cylinder.h.
//   Mesh      a triangle surface (two-sided), kept in its body frame (walls/mesh_wall.h); it
//             rotates about any axis through the rotation centre (moveWalls turns its frame).
//
// Rotation of an analytic shape is restricted to its symmetry axis (plane normal, dish vertical
// axis, cylinder axis), so the geometry itself never changes with time; translation moves the
// geometry. The velocity and the angular velocity may follow piecewise-linear tables in time
// (dem/walls/motion_table.h). A wall may exist only in a time window [activeFrom, activeUntil):
// outside it, it has no contacts.
#pragma once

#include "core/hot.h"
#include "core/vec3.h"
#include "dem/walls/cylinder.h"
#include "dem/walls/mesh_wall.h"
#include "dem/walls/motion_table.h"

#include <cmath>
#include <cstdint>
#include <limits>
#include <string>
#include <variant>

namespace veridem::dem
{

struct PlaneShape
{
    Vec3 point;                                              // a point of the plane [m] (disk centre)
    Vec3 normal{0, 0, 1};                                    // unit normal into the particle side
    Real diskRadius = std::numeric_limits<Real>::infinity(); // [m]; infinite plane by default
};

struct DishShape
{
    Vec3 lowestPoint;        // [m]
    Real sphereRadius = 1.0; // R [m]
};

struct WallMotion
{
    Vec3 velocity;        // translation [m/s]
    Vec3 angularVelocity; // [rad/s], along an analytic shape's symmetry axis; any axis for a mesh
    Vec3 rotationCentre;  // a point of the rotation axis at t = 0 [m] (moves with the translation)
    // Sinusoidal translation (vibrating plate): displacement A sin(Omega t) with amplitude vector
    // A [m] and angular frequency Omega [rad/s] (> 0 switches it on). The step then sets
    // `velocity` itself to A Omega cos(Omega t) at the half step (see moveWalls); a steady
    // translation cannot be combined with it.
    Vec3 oscillationAmplitude;
    Real oscillationAngularFrequency = 0;
    // Piecewise-linear tables in time (empty: none). With velocityTable, the step sets the
    // displacement to its exact integral and `velocity` to its value at the half step; with
    // angularVelocityTable [rad/s] (vectors along the symmetry axis), `angularVelocity` to its
    // value at the half step (see moveWalls).
    MotionTable velocityTable;
    MotionTable angularVelocityTable;
};

struct Wall
{
    std::string name;
    std::variant<PlaneShape, DishShape, CylinderShape, MeshShape> shape;
    WallMotion motion;
    std::uint32_t material = 0;
    Vec3 displacement; // accumulated translation since t = 0 [m] (updated by the step)
    Real clock = 0;    // time since t = 0 [s] (updated by the step; drives the oscillation)
    // The wall exists while activeFrom <= clock < activeUntil [s] (default: always).
    Real activeFrom = -std::numeric_limits<Real>::infinity();
    Real activeUntil = std::numeric_limits<Real>::infinity();
    Vec3 loadPoint; // reference point of the wall's load torque at t = 0 [m] (moves with the wall)
};

/// True if the wall exists at its current clock (Wall::activeFrom, activeUntil).
inline bool wallActive(const Wall& wall)
{
    return wall.clock >= wall.activeFrom && wall.clock < wall.activeUntil;
}

/// Contact of a sphere (centre x, radius r) with a wall shape.
struct WallGap
{
    bool touching = false;
    Real overlap = 0;         // [m]
    Vec3 normal;              // unit, from the wall towards the sphere centre
    Real effectiveRadius = 0; // R* for Hertz/rolling [m]
};

/// A plane's geometry at one instant, the part of the contact test that does not depend on the
/// sphere: its current point [m] (PlaneShape::point plus the wall's displacement), unit normal, and
/// the square of its disk radius [m^2] if it is a finite disk. The plane-wall pass of the force
/// stage (wall_forces.cpp) makes one per wall per step; wallGap(PlaneShape) makes it per call.
struct PlaneGeometry
{
    Vec3 origin, normal;
    bool finiteDisk;
    Real disk2;
};

inline PlaneGeometry planeGeometry(const PlaneShape& plane, const Vec3& offset)
{
    return {plane.point + offset, plane.normal, std::isfinite(plane.diskRadius),
            plane.diskRadius * plane.diskRadius};
}

/// The contact of a sphere (centre x, radius r [m]) with a plane: one-sided (a sphere wholly
/// behind it does not touch), and within the disk if finite.
VERIDEM_HOT_INLINE WallGap wallGap(const PlaneGeometry& plane, const Vec3& x, Real r)
{
    WallGap g;
    const Vec3 relative = x - plane.origin;
    const Real distance = dot(relative, plane.normal);
    const Real overlap = r - distance;
    // (Tests written so that NaN is never touching.)
    bool touching = !(overlap <= 0) && !(distance < -r);
    if (touching && plane.finiteDisk)
        touching = !(lengthSquared(relative - distance * plane.normal) > plane.disk2);
    if (!touching)
        return g;
    g.touching = true;
    g.overlap = overlap;
    g.normal = plane.normal;
    g.effectiveRadius = r;
    return g;
}

inline WallGap wallGap(const PlaneShape& plane, const Vec3& offset, const Vec3& x, Real r)
{
    return wallGap(planeGeometry(plane, offset), x, r);
}

inline WallGap wallGap(const DishShape& dish, const Vec3& offset, const Vec3& x, Real r)
{
    WallGap g;
    const Vec3 centre = dish.lowestPoint + offset + Vec3{0, 0, dish.sphereRadius};
    const Vec3 toCentre = centre - x;
    if (x.z > centre.z) // above the rim of the hemisphere
        return g;
    const Real distance = length(toCentre);
    const Real overlap = distance + r - dish.sphereRadius;
    if (overlap <= 0 || distance == 0)
        return g;
    g.touching = true;
    g.overlap = overlap;
    g.normal = toCentre / distance;
    // Concave contact: 1/R* = 1/r - 1/R.
    g.effectiveRadius = r * dish.sphereRadius / (dish.sphereRadius - r);
    return g;
}

inline WallGap wallGap(const Wall& wall, const Vec3& x, Real r)
{
    if (!wallActive(wall)) // (an inactive wall has no contact slots; the scene checks call this too)
        return {};
    return std::visit([&](const auto& shape) { return wallGap(shape, wall.displacement, x, r); }, wall.shape);
}

/// True if a sphere (centre x, radius r) may touch the wall after the sphere and the wall have
/// moved by at most `reach` [m] relative to each other: a conservative test for the wall-contact
/// candidate list, true whenever wallGap() could become touching within that motion.
inline bool wallNear(const PlaneShape& plane, const Vec3& offset, const Vec3& x, Real r, Real reach)
{
    const Vec3 relative = x - (plane.point + offset);
    const Real distance = dot(relative, plane.normal);
    if (r - distance <= -reach || distance < -r - reach)
        return false;
    if (std::isfinite(plane.diskRadius))
    {
        const Vec3 inPlane = relative - distance * plane.normal;
        const Real limit = plane.diskRadius + reach;
        if (lengthSquared(inPlane) > limit * limit)
            return false;
    }
    return true;
}

inline bool wallNear(const DishShape& dish, const Vec3& offset, const Vec3& x, Real r, Real reach)
{
    const Vec3 centre = dish.lowestPoint + offset + Vec3{0, 0, dish.sphereRadius};
    if (x.z > centre.z + reach)
        return false;
    return length(centre - x) + r - dish.sphereRadius > -reach;
}

inline bool wallNear(const Wall& wall, const Vec3& x, Real r, Real reach)
{
    if (!wallActive(wall))
        return false;
    return std::visit([&](const auto& shape) { return wallNear(shape, wall.displacement, x, r, reach); },
                      wall.shape);
}

/// A wall's rigid motion at one instant: the velocity field of its material, v(P) = velocity +
/// angularVelocity x (P - axisPoint) [m/s], with the rotation axis through axisPoint [m].
struct SurfaceMotion
{
    Vec3 velocity;        // [m/s]
    Vec3 angularVelocity; // [rad/s]
    Vec3 axisPoint;       // [m]
};

/// The wall's motion at time offset `timeOffset` [s] from its current position (the rotation axis
/// moves with the wall's translation).
inline SurfaceMotion surfaceMotion(const Wall& wall, Real timeOffset = 0)
{
    return {wall.motion.velocity, wall.motion.angularVelocity,
            wall.motion.rotationCentre + wall.displacement + timeOffset * wall.motion.velocity};
}

/// Velocity of the wall material at point P [m/s].
VERIDEM_HOT_INLINE Vec3 velocityAt(const SurfaceMotion& m, const Vec3& point)
{
    return m.velocity + cross(m.angularVelocity, point - m.axisPoint);
}

/// Velocity of the wall material at point P [m/s], at time offset `timeOffset` [s] from the
/// wall's current position.
inline Vec3 wallSurfaceVelocity(const Wall& wall, const Vec3& point, Real timeOffset = 0)
{
    return velocityAt(surfaceMotion(wall, timeOffset), point);
}

/// Unit normal of a plane tilted by `tilt` [rad] from +z so that its downhill direction (in the
/// plane) points at azimuth `downhillAzimuth` [rad] (0 = +x east, pi/2 = +y north).
inline Vec3 tiltedNormal(Real tilt, Real downhillAzimuth)
{
    return {std::sin(tilt) * std::cos(downhillAzimuth), std::sin(tilt) * std::sin(downhillAzimuth),
            std::cos(tilt)};
}

} // namespace veridem::dem
