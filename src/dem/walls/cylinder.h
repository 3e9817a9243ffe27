// A finite circular cylinder wall (a rotating drum, a post): the lateral surface between two
// planes normal to its axis. Its ends are open here; closed ends are separate finite disk planes
// (PlaneShape with diskRadius) that the scene reader adds as walls of their own, NAME/cap0 and
// NAME/cap1, sharing the cylinder's motion and material (io/dem_scene.cpp), so that the plane's
// contact code serves them unchanged.
#pragma once

#include "core/vec3.h"

namespace veridem::dem
{

struct WallGap; // dem/walls/wall.h

struct CylinderShape
{
    Vec3 point;         // the start of the axis [m] (the centre of the end face at s = 0)
    Vec3 axis{0, 0, 1}; // unit axis direction; the cylinder spans s in [0, length] along it
    Real radius = 1.0;  // R [m]
    Real length = 1.0;  // [m]
    bool inside = true; // particles inside (a drum) or outside (a post)
};

/// The contact of a sphere (centre x, radius r [m]) with the lateral surface of the cylinder
/// displaced by `offset` [m] (wall.h, WallGap). One-sided like a plane: a sphere wholly on the
/// solid side does not touch. Only a sphere whose centre lies between the end planes
/// (0 <= s <= length) touches: a sphere beyond an end has no contact with the side (no rim/edge
/// contact; close the ends with caps). On the outside, a centre on the axis (possible only if
/// r > R) takes a fixed direction normal to the axis, so the normal is never NaN.
WallGap wallGap(const CylinderShape& cylinder, const Vec3& offset, const Vec3& x, Real r);

/// wallNear() for a cylinder: true whenever wallGap could become touching after a relative motion
/// of at most `reach` [m] (the axial coordinate and the distance from the axis change by at most
/// `reach`).
bool wallNear(const CylinderShape& cylinder, const Vec3& offset, const Vec3& x, Real r, Real reach);

/// A unit vector normal to the unit vector `axis` (a fixed choice, for degenerate geometry).
Vec3 normalTo(const Vec3& axis);

} // namespace veridem::dem
