// The cohesive law of the joint (crack) elements of the combined finite-discrete element method: a
// pure function of the opening and slip of one integration point and its damage history.
//
// Published formulas (clean-room; no Y code read): Munjiza, Andrews & White, "Combined single and
// smeared crack model in combined finite-discrete element analysis", IJNME 44:41-57 (1999), and
// Munjiza 2004, "The Combined Finite-Discrete Element Method", Wiley, ch. 7. Notation:
//   o   normal opening [m] (> 0 opens),      s   tangential slip [m],
//   h   joint size [m] (its reference length),  p   joint penalty [Pa],
//   f_t tensile strength [Pa],  f_s = c + max(0, -sigma_n) tan(phi) Mohr-Coulomb shear strength [Pa]
//       (compression raises it; tension does not lower it, it interacts through D below),
//   G_f mode I fracture energy [J/m^2],  G_II shear fracture energy [J/m^2].
// Before the peak (Munjiza 2004 eq. 7.x, "hardening" part, reversible):
//   o_p = 2 h f_t / p,  s_p = 2 h f_s / p,  g(r) = 2 r - r^2 for r < 1, else 1
//   (initial stiffness p / h, zero slope at the peak).
// Softening: o_c - o_p = G_f / (f_t Z),  s_c - s_p = G_II / (c Z),  Z = integral_0^1 z(D) dD, so the
// area under the softening branch of a pure mode is exactly G_f (mode I) or G_II (mode II at
// sigma_n = 0). Mixed mode (the stated interaction rule, an ellipse in the softening openings):
//   D = min(1, sqrt(D_n^2 + D_s^2)),  D_n = max(0, (o - o_p)/(o_c - o_p)),
//   D_s = max(0, (|s| - s_p)/(s_c - s_p)).
// Damage is irreversible: the history variable is D_max = max over time of D, and
//   sigma = f_t g(o / o_p) z(D_max)   (o >= 0; compression is carried by the joint as the linear
//                                      penalty sigma = p o / h, and by the contact once broken),
//   tau   = f_s g(|s| / s_p) z(D_max) sign(s).
// Unloading after damage therefore follows the scaled pre-peak curve back to zero (no energy is
// created by unload-reload cycles). The joint is broken when D_max reaches 1.
// Softening curves z(D), z(0) = 1, z(1) = 0, selectable:
//   linear:       z = 1 - D                                                       (Z = 1/2)
//   exponential:  z = (exp(-k D) - exp(-k)) / (1 - exp(-k)), k = 5 (shifted to reach 0 at D = 1)
//   munjiza:      z = [1 - (a+b-1)/(a+b) exp(D (a+c b)/((a+b)(1-a-b)))] [a (1-D) + b (1-D)^c],
//                 a = 0.63, b = 1.8, c = 6.0 (Munjiza, Andrews & White 1999, fitted to concrete
//                 tests after Hordijk); Z is integrated numerically (softeningArea()).
#pragma once

#include "fdem/vec2.h"

#include <algorithm>
#include <cmath>
#include <cstdint>

namespace veridem::fdem
{

enum class SofteningCurve : std::uint8_t
{
    Munjiza,
    Linear,
    Exponential,
};

/// Softening function z(D) of the curve [1], D in [0, 1].
inline Real softening(SofteningCurve curve, Real d)
{
    d = std::clamp(d, Real(0), Real(1));
    switch (curve)
    {
    case SofteningCurve::Linear:
        return 1 - d;
    case SofteningCurve::Exponential:
    {
        constexpr Real k = 5;
        return (std::exp(-k * d) - std::exp(-k)) / (1 - std::exp(-k));
    }
    case SofteningCurve::Munjiza:
    default:
    {
        constexpr Real a = 0.63, b = 1.8, c = 6.0;
        const Real first = 1 - (a + b - 1) / (a + b) * std::exp(d * (a + c * b) / ((a + b) * (1 - a - b)));
        return first * (a * (1 - d) + b * std::pow(1 - d, c));
    }
    }
}

/// Z = integral_0^1 z(D) dD [1], by composite 5-point Gauss-Legendre on 64 panels (exact to
/// round-off for the linear curve; below 1e-12 for the smooth ones).
inline Real softeningArea(SofteningCurve curve)
{
    static constexpr Real x[5] = {-0.9061798459386640, -0.5384693101056831, 0.0, 0.5384693101056831,
                                  0.9061798459386640};
    static constexpr Real w[5] = {0.2369268850561891, 0.4786286704993665, 0.5688888888888889,
                                  0.4786286704993665, 0.2369268850561891};
    constexpr int panels = 64;
    Real sum = 0;
    for (int p = 0; p < panels; ++p)
        for (int i = 0; i < 5; ++i)
            sum += w[i] * softening(curve, (p + 0.5 + 0.5 * x[i]) / panels);
    return sum / (2 * panels);
}

/// Largest |dz/dD| on [0, 1] [1], sampled at 4001 points by central differences (the snap-back check).
inline Real softeningMaxSlope(SofteningCurve curve)
{
    Real slope = 0;
    constexpr int n = 4000;
    for (int i = 0; i < n; ++i)
        slope = std::max(slope, (softening(curve, Real(i) / n) - softening(curve, Real(i + 1) / n)) * n);
    return slope;
}

/// Fracture parameters of a material (0 tensile strength: the material does not crack).
struct FractureParameters
{
    Real tensileStrength = 0;     ///< f_t [Pa]
    Real fractureEnergy = 0;      ///< G_f, mode I [J/m^2]
    Real shearFractureEnergy = 0; ///< G_II [J/m^2]
    Real cohesion = 0;            ///< c [Pa]
    Real frictionAngle = 0;       ///< phi, internal friction angle [rad]
    Real penalty = 0;             ///< p, joint penalty [Pa]
    SofteningCurve curve = SofteningCurve::Munjiza;
};

/// Derived constants of one material's joints (computed once).
struct CohesiveConstants
{
    FractureParameters p;
    Real area = 0.5;          ///< Z of the curve [1]
    Real normalSoftening = 0; ///< o_c - o_p = G_f / (f_t Z) [m]
    Real shearSoftening = 0;  ///< s_c - s_p = G_II / (c Z) [m]
    Real tanPhi = 0;          ///< tan(phi) [1]
};

inline CohesiveConstants cohesiveConstants(const FractureParameters& p)
{
    CohesiveConstants c;
    c.p = p;
    c.area = softeningArea(p.curve);
    c.normalSoftening = p.fractureEnergy / (p.tensileStrength * c.area);
    c.shearSoftening = p.shearFractureEnergy / (p.cohesion * c.area);
    c.tanPhi = std::tan(p.frictionAngle);
    return c;
}

/// Tractions on one integration point [Pa] and its updated damage.
struct CohesiveResult
{
    Real normal = 0;     ///< sigma, > 0 tension [Pa]
    Real tangential = 0; ///< tau, along the slip [Pa]
    Real damage = 0;     ///< D_max after this evaluation [1]
};

inline Real prePeak(Real r)
{
    return r < 1 ? 2 * r - r * r : Real(1);
}

/// The law of the header comment for opening `o` [m], slip `s` [m], joint size `h` [m] and the
/// previous damage `damage` [1].
inline CohesiveResult cohesiveTraction(Real o, Real s, Real h, Real damage, const CohesiveConstants& k)
{
    CohesiveResult r;
    const Real p = k.p.penalty;
    const Real compression = o < 0 ? -p * o / h : Real(0); // [Pa], > 0 in compression
    const Real ft = k.p.tensileStrength;
    const Real fs = k.p.cohesion + compression * k.tanPhi;
    const Real op = 2 * h * ft / p, sp = 2 * h * fs / p;
    const Real dn = std::max(Real(0), (o - op) / k.normalSoftening);
    const Real ds = std::max(Real(0), (std::abs(s) - sp) / k.shearSoftening);
    r.damage = std::max(damage, std::min(Real(1), std::sqrt(dn * dn + ds * ds)));
    const Real z = softening(k.p.curve, r.damage);
    r.normal = o < 0 ? -compression : ft * prePeak(o / op) * z;
    const Real tau = fs * prePeak(std::abs(s) / sp) * z;
    r.tangential = s < 0 ? -tau : tau;
    return r;
}

} // namespace veridem::fdem
