// Constant-strain triangle (CST) with finite strain and finite rotation (Munjiza 2004, ch. 4;
// veridem BENCHMARKS.md section 6.1). Pure function of the triangle's nodes; no state.
//
// Nodes 0, 1, 2 counter-clockwise. Edge matrices (columns):
//   X0 = [x1 - x0, x2 - x0] (reference), X = [same, current], V = [v1 - v0, v2 - v0].
//   Deformation gradient F = X X0^-1, J = det F = A / A0, velocity gradient L = V X^-1.
//   Left Cauchy-Green B = F F^T, strain E = (B - I)/2 (zero for any rigid rotation),
//   rate of deformation D = (L + L^T)/2.
// Cauchy stress T (in-plane; lambda is the plane-strain or plane-stress value, see material.h):
//   finite strain (Munjiza): T = (mu/J)(B - I) + (lambda/2)(J - 1/J) I + eta_v D
//   linear:                  T = lambda tr(E) I + 2 mu E + eta_v D
// Both reduce to Hooke's law sigma = lambda tr(eps) I + 2 mu eps at small strain
// ((mu/J)(B - I) -> 2 mu eps and (lambda/2)(J - 1/J) -> lambda tr(eps)).
// Nodal internal force (per unit thickness, N/m): f_i = T n_i / 2 where n_i is the outward normal of
// the edge opposite node i, with the length of that edge: n_i = (y_k - y_j, x_j - x_k), j = i+1, k = i+2.
// (The traction T n on each edge is shared equally by its two nodes; the two edges at node i have
// normals summing to -n_i.) Tension pulls the nodes towards the element: f_i points along +n_i.
#pragma once

#include "fdem/material.h"
#include "fdem/vec2.h"

#include <array>

namespace veridem::fdem
{

struct CstResult
{
    std::array<Vec2, 3> force{}; ///< internal nodal forces [N/m]
    SymTensor2 stress{};         ///< Cauchy stress T [Pa]
    Real jacobian = 1;           ///< J = A / A0 [1]; <= 0 means the element is inverted
};

/// Reference inverse X0^-1 of a triangle; the caller checks the area first.
inline Mat2 referenceInverse(const std::array<Vec2, 3>& x0)
{
    return inverse(Mat2::fromColumns(x0[1] - x0[0], x0[2] - x0[0]));
}

/// Signed area (positive for counter-clockwise nodes) [m^2].
inline Real signedArea(const Vec2& a, const Vec2& b, const Vec2& c)
{
    return 0.5 * cross(b - a, c - a);
}

/// Internal forces and stress of one CST. x: current node positions [m]; v: node velocities [m/s];
/// X0inv: reference inverse [1/m]; c: material constants. If J <= 0 the forces are zero and
/// `jacobian` reports the inversion (the caller raises the error with the element's id).
inline CstResult cstInternalForces(const std::array<Vec2, 3>& x, const std::array<Vec2, 3>& v,
                                   const Mat2& X0inv, const ElasticConstants& c)
{
    CstResult r;
    const Mat2 X = Mat2::fromColumns(x[1] - x[0], x[2] - x[0]);
    const Mat2 F = X * X0inv;
    const Real J = determinant(F);
    r.jacobian = J;
    if (!(J > 0))
        return r;
    const Mat2 B = F * transpose(F);
    SymTensor2 T;
    if (c.law == StressLaw::FiniteStrain)
    {
        const Real a = c.shear / J;
        const Real p = 0.5 * c.lambda * (J - 1 / J);
        T = {a * (B.xx - 1) + p, a * (B.yy - 1) + p, a * B.xy};
    }
    else
    {
        const SymTensor2 E{0.5 * (B.xx - 1), 0.5 * (B.yy - 1), 0.5 * B.xy};
        const Real p = c.lambda * (E.xx + E.yy);
        T = {2 * c.shear * E.xx + p, 2 * c.shear * E.yy + p, 2 * c.shear * E.xy};
    }
    if (c.viscosity != 0)
    {
        const Mat2 V = Mat2::fromColumns(v[1] - v[0], v[2] - v[0]);
        const Mat2 L = V * inverse(X);
        T.xx += c.viscosity * L.xx;
        T.yy += c.viscosity * L.yy;
        T.xy += c.viscosity * 0.5 * (L.xy + L.yx);
    }
    r.stress = T;
    for (int i = 0; i < 3; ++i)
    {
        const Vec2& xj = x[(i + 1) % 3];
        const Vec2& xk = x[(i + 2) % 3];
        const Vec2 n{xk.y - xj.y, xj.x - xk.x};
        r.force[i] = 0.5 * (T * n);
    }
    return r;
}

/// Small-strain elastic energy per unit thickness of the element, A0 (lambda tr(E)^2 / 2 + mu E:E) [J/m],
/// with E = (B - I)/2. Used for energy balances (exact to O(strain^3)).
inline Real cstStrainEnergy(const std::array<Vec2, 3>& x, const Mat2& X0inv, Real referenceArea,
                            const ElasticConstants& c)
{
    const Mat2 F = Mat2::fromColumns(x[1] - x[0], x[2] - x[0]) * X0inv;
    const Mat2 B = F * transpose(F);
    const Real exx = 0.5 * (B.xx - 1), eyy = 0.5 * (B.yy - 1), exy = 0.5 * B.xy;
    const Real tr = exx + eyy;
    return referenceArea * (0.5 * c.lambda * tr * tr + c.shear * (exx * exx + eyy * eyy + 2 * exy * exy));
}

} // namespace veridem::fdem
