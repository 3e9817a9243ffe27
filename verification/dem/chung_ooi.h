// Shared set-up of the Chung & Ooi (2011) impact benchmarks (BENCHMARKS 4): the materials of the
// eight tests, Hertz closed forms, a sphere-wall and a sphere-sphere impact run until separation,
// and the no-slip Hertz-Mindlin reference integrated from its own equations.
//
// Tangential conventions used by every test (stated in each output file): V is the velocity of
// the sphere's contact point relative to the partner's, V_t its tangential part; v_t is the
// tangential velocity of the centre; primes are after the impact.
#pragma once

#include "support.h"

#include <string>
#include <vector>

namespace veridem::verify::chung_ooi
{

/// One of the paper's materials: Young's modulus E [Pa], Poisson's ratio nu [-], density [kg/m^3].
struct Solid
{
    std::string name;
    Real youngsModulus, poissonRatio, density;
};

inline const Solid kGlass{"glass", 48e9, 0.20, 2800};
inline const Solid kLimestone{"limestone", 20e9, 0.25, 2500};
inline const Solid kAluminiumAlloy{"al_alloy", 70e9, 0.30, 2699};
inline const Solid kMagnesiumAlloy{"mg_alloy", 40e9, 0.35, 1800};
inline const Solid kAluminiumOxide{"al_oxide", 380e9, 0.23, 4000};
inline const Solid kCastIron{"cast_iron", 100e9, 0.25, 7000};
inline const Solid kAluminiumAlloy033{"al_alloy", 70e9, 0.33, 2700}; // tests 4, 6-8
inline const Solid kSteel{"steel", 208e9, 0.30, 7850};
inline const Solid kPolyethylene{"polyethylene", 1e9, 0.40, 1400};
inline const Solid kNylon{"nylon", 2.5e9, 0.40, 1000};
inline const Solid kCopper{"copper", 120e9, 0.35, 8900};

/// Hertz-Mindlin material with restitution e and friction mu.
Material hertzMaterial(const Solid& s, Real restitution, Real friction);

/// Effective moduli of a sphere of `s` against a rigid plane (E* = E/(1 - nu^2),
/// G* = G/(2 - nu)) or against an identical sphere (half of each) [Pa].
Real effectiveModulus(const Solid& s, bool rigidPartner);
Real effectiveShearModulus(const Solid& s, bool rigidPartner);

/// Hertz closed forms for an elastic impact at relative normal speed v [m/s]
/// (Johnson 1985; BENCHMARKS 5.4).
struct HertzImpact
{
    Real maxOverlap;  // (15 m* v^2 / (16 E* sqrt(R*)))^(2/5) [m]
    Real maxForce;    // (4/3) E* sqrt(R*) maxOverlap^(3/2) [N]
    Real contactTime; // 2.868 (m*^2 / (R* E*^2 v))^(1/5) [s]
};
HertzImpact hertzImpact(Real effectiveMass, Real effectiveRadius, Real effectiveModulus, Real speed);

/// State after an impact and what the contact did.
struct Outcome
{
    Vec3 velocity, angularVelocity;               // of the moving sphere, after separation
    Vec3 partnerVelocity, partnerAngularVelocity; // of the second sphere (zero for a wall)
    Real contactTime = 0;                         // [s], interpolated at both ends
    Real maxOverlap = 0;                          // [m]
    Real maxNormalForce = 0;                      // [N]
    // Share of the normal impulse sum(max(F_n, 0) dt) carried by steps whose tangential force was
    // below the Coulomb cap mu max(F_n, 0) (sticking steps).
    Real stickingImpulseFraction = 0;
    // Gross sliding: the sticking steps carry at most 1e-3 of the normal impulse, so the
    // tangential impulse differs from mu times the normal impulse by at most 0.1 % (a damped
    // contact sticks for its first few steps, where the dashpot raises the cap).
    bool slidThroughout = true;
    Real normalImpulse = 0;                   // sum F_n dt over the contact [N s] (attractive end included)
    Real compressiveImpulse = 0;              // sum max(F_n, 0) dt [N s]: what the Coulomb cap sees
    Real dt = 0;                              // [s]
    std::vector<std::vector<double>> history; // t, overlap, F_n rows (if requested)
};

/// A sphere of `ball` (radius [m]) hits the rigid plane z = 0 with centre velocity v0 and angular
/// velocity w0; runs until it separates. dt = t_c / stepsPerContact with t_c from hertzImpact at
/// the normal speed. The ball starts `startSteps` steps of normal travel above the plane (the
/// fraction sets where first touch falls between steps).
Outcome wallImpact(const Solid& ball, Real restitution, Real friction, Real radius, Vec3 v0, Vec3 w0,
                   Real stepsPerContact, const CaseContext& context, bool keepHistory = false,
                   Real startSteps = 2.5);

/// Sphere 1 (radius r1) starts touching distance above sphere 2 (radius r2, density scaled by
/// `densityFactor2`) along +z, both of `solid`; velocities and spins given; runs until separation.
Outcome sphereImpact(const Solid& solid, Real restitution, Real friction, Real r1, Vec3 v1, Vec3 w1, Real r2,
                     Vec3 v2, Vec3 w2, Real densityFactor2, Real stepsPerContact, const CaseContext& context,
                     bool keepHistory = false);

/// No-slip Hertz-Mindlin reference for a sphere hitting a rigid plane with e = 1: the ratio
/// V_t'/V_t of the contact point when the tangential spring F_t = -8 G* sqrt(R* delta) xi never
/// slides. Integrated by RK4 in the dimensionless form delta'' = -delta^(3/2),
/// xi'' = -(21 G*/E*) sqrt(delta) xi (sphere: contact-point mass (2/7) m), independent of the
/// impact speed and size.
Real noSlipReversal(Real shearToNormalModulus);

/// Worst relative error of measured vs expected over the given index set (0 if empty).
Real worstRelative(const std::vector<Real>& measured, const std::vector<Real>& expected,
                   const std::vector<std::size_t>& indices);

} // namespace veridem::verify::chung_ooi
