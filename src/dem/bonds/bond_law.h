// The parallel bond law (Potyondy & Cundall 2004, "A bonded-particle model for rock", Int. J. Rock
// Mech. Min. Sci. 41:1329, section 2.3), as pure functions of one bond's state and its partners'
// motion. A bond is a cylinder of cement of radius Rb = lambda min(ra, rb) between particles a and
// b, acting at the contact point c on the line of centres (the middle of the gap), carrying a
// force and a moment:
//
//   section        A = pi Rb^2,  I = pi Rb^4 / 4 (bending),  J = pi Rb^4 / 2 (twist)
//   normal         Fn = kn A (d - d0)                         tension > 0 [N]; d = |xb - xa|
//   shear          Fs <- rot(Fs) - ks A dUs,   dUs = (v_c,b - v_c,a)_t dt
//   twist          Mt <- Mt - ks J dtheta_n,   dtheta_n = (wb - wa) . n dt
//   bend           Mb <- rot(Mb) - kn I dtheta_s,  dtheta_s = ((wb - wa) - ((wb - wa) . n) n) dt
//   on b           F_b = -Fn n + Fs,   T_b = (c - xb) x F_b + Mt n + Mb
//   on a           F_a = -F_b,         T_a = (c - xa) x F_a - Mt n - Mb
//   strength       sigma = Fn / A + |Mb| Rb / I >= sigma_c  or  tau = |Fs| / A + |Mt| Rb / J >= tau_c
//                  breaks the bond (it then acts no more, from the step it breaks)
//
// kn, ks are stiffnesses per area [N/m^3] (Potyondy & Cundall's kn-bar, ks-bar), so a bond's beam
// properties are kn A (axial, N/m), ks A (shear, N/m), kn I (bending, N m/rad), ks J (twist,
// N m/rad). v_c,a = va + wa x (c - xa) is the velocity of a's material point at c.
//
// Formulation. The normal force is written in total form from the rest length d0 (the centre
// distance when the bond formed), so it is exact and objective; shear force, twisting and bending
// moment are incremental, as in the paper, because a sphere carries no orientation here. Their
// stored vectors are carried into the current frame each step before the increment (rot): the
// smallest rotation taking the previous bond normal to the current one, then the rotation about
// the current normal by the partners' mean spin times dt. Under a rigid rotation of the pair the
// increments are zero (the relative velocity at c and the relative spin vanish) and the stored
// vectors turn with the pair: the law is objective to round-off (tests/dem/bond_law_test.cpp).
//
// Damping (optional, not in the paper): a dashpot in each of the four modes with ratio beta of its
// critical value for the reduced mass or inertia, c = 2 beta sqrt(m* k). It is added to the force
// and torque but not to the stored state nor the strength test: it acts only while partners move.
#pragma once

#include "core/constants.h"
#include "core/vec3.h"

#include <cmath>
#include <limits>

namespace veridem::dem
{

/// A bond law's parameters (scene keys in docs/scene-format.md, `[bonds]`).
struct BondParams
{
    Real normalStiffness = 0;                                     // kn, per area [N/m^3]
    Real shearStiffness = 0;                                      // ks, per area [N/m^3]
    Real tensileStrength = std::numeric_limits<Real>::infinity(); // sigma_c [Pa]
    Real shearStrength = std::numeric_limits<Real>::infinity();   // tau_c [Pa]
    Real radiusMultiplier = 1;                                    // lambda: Rb = lambda min(ra, rb) [-]
    Real dampingRatio = 0;                                        // beta of each mode's critical damping [-]
};

/// The cement cylinder's section.
struct BondSection
{
    Real radius; // Rb [m]
    Real area;   // A [m^2]
    Real bend;   // I = pi Rb^4 / 4 [m^4]
    Real twist;  // J = pi Rb^4 / 2 [m^4]
};

inline BondSection bondSection(const BondParams& p, Real ra, Real rb)
{
    const Real r = p.radiusMultiplier * std::fmin(ra, rb);
    const Real r2 = r * r;
    return {r, kPi * r2, 0.25 * kPi * r2 * r2, 0.5 * kPi * r2 * r2};
}

/// One bond's state (its history): what the law carries from step to step.
struct BondState
{
    Vec3 normal;          // n at the last update, from a to b [-]
    Vec3 shearForce;      // Fs on b [N], perpendicular to n
    Vec3 bendMoment;      // Mb on b [N m], perpendicular to n
    Real twistMoment = 0; // Mt on b about n [N m]
    Real restLength = 0;  // d0 [m]
};

/// The partners' state as the law reads it (a and b).
struct BondPartners
{
    Vec3 xa, xb;         // positions [m]
    Vec3 va, vb;         // velocities [m/s]
    Vec3 wa, wb;         // angular velocities [rad/s]
    Real ra, rb;         // radii [m]
    Real reducedMass;    // m* [kg] (the free partner's mass if the other is frozen)
    Real reducedInertia; // I* [kg m^2] likewise
};

/// What a bond does this step.
struct BondLoad
{
    Vec3 forceOnB;      // F_b [N] (F_a = -F_b)
    Vec3 torqueOnA;     // T_a [N m]
    Vec3 torqueOnB;     // T_b [N m]
    Real tensileStress; // sigma [Pa]
    Real shearStress;   // tau [Pa]
    bool broken;        // sigma >= sigma_c or tau >= tau_c: no load applied
};

/// Rotates v by the rotation taking unit vector `from` to unit vector `to` (the smallest one,
/// about from x to; Rodrigues with the sine folded in: v' = c v + k x v + k (k.v) / (1 + c)).
inline Vec3 rotateWithNormal(const Vec3& v, const Vec3& from, const Vec3& to)
{
    const Vec3 k = cross(from, to);
    const Real c = dot(from, to);
    return c * v + cross(k, v) + (dot(k, v) / (1 + c)) * k;
}

/// Rotates v about unit axis n by angle phi [rad].
inline Vec3 rotateAbout(const Vec3& v, const Vec3& n, Real phi)
{
    const Real c = std::cos(phi), s = std::sin(phi);
    return c * v + s * cross(n, v) + ((1 - c) * dot(n, v)) * n;
}

/// The part of v perpendicular to unit n.
inline Vec3 tangentialPart(const Vec3& v, const Vec3& n)
{
    return v - dot(v, n) * n;
}

/// A new bond between partners at xa, xb: its rest length is their distance now, no load.
inline BondState formBond(const Vec3& xa, const Vec3& xb)
{
    const Vec3 d = xb - xa;
    const Real len = length(d);
    return {d / len, {}, {}, 0, len};
}

/// Advances one bond over dt [s] (the partners at x(t+dt) with the half-step velocities) and
/// returns its load; updates `s`. Damping uses the same relative motion as the increments.
inline BondLoad bondStep(const BondParams& p, BondState& s, const BondPartners& q, Real dt)
{
    const BondSection sec = bondSection(p, q.ra, q.rb);
    const Vec3 d = q.xb - q.xa;
    const Real dist = length(d);
    const Vec3 n = d / dist;
    const Real la = q.ra + 0.5 * (dist - q.ra - q.rb); // |c - xa|
    const Real lb = dist - la;                         // |xb - c|

    // The stored vectors into the current frame: tilt of the normal, then the mean spin about it.
    const Real spin = 0.5 * dot(q.wa + q.wb, n) * dt;
    Vec3 fs = tangentialPart(rotateAbout(rotateWithNormal(s.shearForce, s.normal, n), n, spin), n);
    Vec3 mb = tangentialPart(rotateAbout(rotateWithNormal(s.bendMoment, s.normal, n), n, spin), n);

    // Relative motion at the contact point and relative spin.
    const Vec3 vRel = (q.vb + cross(q.wb, -lb * n)) - (q.va + cross(q.wa, la * n));
    const Vec3 vt = tangentialPart(vRel, n);
    const Vec3 wRel = q.wb - q.wa;
    const Real wn = dot(wRel, n);
    const Vec3 ws = wRel - wn * n;

    const Real kn = p.normalStiffness * sec.area, ks = p.shearStiffness * sec.area;
    const Real kBend = p.normalStiffness * sec.bend, kTwist = p.shearStiffness * sec.twist;
    fs -= (ks * dt) * vt;
    mb -= (kBend * dt) * ws;
    s.twistMoment -= kTwist * wn * dt;
    s.shearForce = fs;
    s.bendMoment = mb;
    s.normal = n;
    const Real fn = kn * (dist - s.restLength); // tension > 0

    BondLoad out{};
    out.tensileStress = fn / sec.area + length(mb) * sec.radius / sec.bend;
    out.shearStress = length(fs) / sec.area + std::fabs(s.twistMoment) * sec.radius / sec.twist;
    out.broken = out.tensileStress >= p.tensileStrength || out.shearStress >= p.shearStrength;
    if (out.broken)
        return out;

    Vec3 force = (-fn) * n + fs;
    Vec3 moment = s.twistMoment * n + mb;
    if (p.dampingRatio > 0)
    {
        const Real twoBeta = 2 * p.dampingRatio;
        const Real vn = dot(vRel, n);
        force -= (twoBeta * std::sqrt(q.reducedMass * kn) * vn) * n +
                 (twoBeta * std::sqrt(q.reducedMass * ks)) * vt;
        moment -= (twoBeta * std::sqrt(q.reducedInertia * kTwist) * wn) * n +
                  (twoBeta * std::sqrt(q.reducedInertia * kBend)) * ws;
    }
    out.forceOnB = force;
    out.torqueOnB = cross(-lb * n, force) + moment;
    out.torqueOnA = cross(la * n, -force) - moment;
    return out;
}

} // namespace veridem::dem
