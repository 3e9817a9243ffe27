// Distributed potential contact force between two triangles (Munjiza 2004, book section 2.5,
// eqs 2.17-2.19 and 2.56-2.57; veridem BENCHMARKS.md section 6.2). Pure functions, no state.
//
// Potential of a triangle: phi(P) = 3 min_k lambda_k(P), lambda_k the barycentric coordinates
// (lambda_k = d_k / H_k: distance to edge k over the altitude onto it). phi = 1 at the centroid and
// 0 on the boundary. The contact force on the contactor c from the target t is
//     f_c = p * closed-integral over the boundary of (c intersect t) of n (phi_c - phi_t) dGamma,
// p the penalty [Pa]. On the part of the boundary made of contactor edges phi_c = 0, so each
// contactor edge inside the target receives -p n_c phi_t per unit length (n_c its outward unit
// normal); the target edges inside the contactor are covered when the roles are swapped. Every
// pair is therefore evaluated twice, once per role.
//
// Along a contactor edge P(s) = P0 + s (P1 - P0), s in [0, 1], each lambda_k is linear in s, so
// phi_t is the minimum of three linear functions: piecewise linear with break points where two of
// them are equal. It is integrated exactly on the sub-segment where all lambda_k >= 0:
//     I0 = int phi_t ds,  I1 = int phi_t s ds  (trapezoid rules exact for linear and quadratic).
// Edge force magnitude F = p L I0 (L the edge length) along -n_c, split between the edge's nodes as
// p L (I0 - I1) and p L I1 (linear shape functions); the reaction +F n_c goes to the target's nodes
// with weights int phi_t lambda_k ds / I0 (the same application points), so the pair's forces sum
// to zero and have zero net moment.
#pragma once

#include "fdem/vec2.h"

#include <array>

namespace veridem::fdem
{

/// phi_t integrated along one contactor edge inside one target triangle.
struct EdgePenetration
{
    Real integral = 0;                  ///< I0 = int_0^1 phi_t ds [1]
    Real firstMoment = 0;               ///< I1 = int_0^1 phi_t s ds [1]
    Real insideFraction = 0;            ///< (s_max - s_min): fraction of the edge inside the target [1]
    std::array<Real, 3> targetWeight{}; ///< int phi_t lambda_k ds / I0, sums to 1 [1]

    bool touching() const { return integral > 0; }
    /// Parametric position of the force's application point, I1 / I0.
    Real centre() const { return firstMoment / integral; }
};

/// Integrates the target's potential along the edge p0 -> p1. `target` must be counter-clockwise.
EdgePenetration edgeInTriangle(const Vec2& p0, const Vec2& p1, const std::array<Vec2, 3>& target);

/// Barycentric coordinates lambda_k of p in the counter-clockwise triangle `target` [1].
std::array<Real, 3> barycentric(const Vec2& p, const std::array<Vec2, 3>& target);

/// The same integral from the barycentric coordinates of the edge's end points in the target
/// (lets a caller share them between the edges of one triangle).
EdgePenetration edgeInTriangle(const std::array<Real, 3>& start, const std::array<Real, 3>& end);

/// The potential contact forces of a triangle pair, both roles, without friction [N/m].
struct TrianglePairForces
{
    std::array<Vec2, 3> onFirst{};
    std::array<Vec2, 3> onSecond{};
};

/// Frictionless potential contact between triangles a and b (counter-clockwise) with penalty p [Pa].
TrianglePairForces potentialContactForces(const std::array<Vec2, 3>& a, const std::array<Vec2, 3>& b,
                                          Real penalty);

/// Outward unit normal of the edge from p0 to p1 of a counter-clockwise triangle.
inline Vec2 outwardNormal(const Vec2& p0, const Vec2& p1)
{
    const Vec2 e = p1 - p0;
    return Vec2{e.y, -e.x} / length(e);
}

} // namespace veridem::fdem
