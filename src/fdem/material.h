// Elastic material of a 2D FEM/DEM body and the derived constants used by the element kernel.
//
// Lame constants from Young's modulus E and Poisson's ratio nu:
//   lambda = E nu / ((1 + nu)(1 - 2 nu)),  mu = E / (2 (1 + nu))            (plane strain, 3D values)
//   plane stress replaces lambda by lambda* = 2 lambda mu / (lambda + 2 mu) = E nu / (1 - nu^2).
// P-wave speed used by the time-step estimate: c_p = sqrt((lambda + 2 mu) / rho) with the in-plane lambda.
#pragma once

#include "core/vec3.h"
#include "fdem/fracture/cohesive_law.h"

#include <cmath>
#include <cstdint>

namespace veridem::fdem
{

/// Constitutive law of the constant-strain triangle (see elements/cst.h for the equations).
enum class StressLaw : std::uint8_t
{
    FiniteStrain, ///< Munjiza's finite-strain law T = (mu/J)(B - I) + (lambda/2)(J - 1/J) I
    Linear,       ///< T = lambda tr(E) I + 2 mu E with E = (B - I)/2 (small strain, exact rigid rotation)
};

enum class PlaneModel : std::uint8_t
{
    Strain, ///< plane strain (eps_zz = 0)
    Stress, ///< plane stress (sigma_zz = 0)
};

struct Material
{
    Real density = 0;       ///< rho [kg/m^3]
    Real youngsModulus = 0; ///< E [Pa]
    Real poissonRatio = 0;  ///< nu [1], in [0, 0.5)
    Real viscosity = 0;     ///< eta_v of the viscous stress eta_v D [Pa s]
    StressLaw law = StressLaw::FiniteStrain;
    PlaneModel plane = PlaneModel::Strain;
    FractureParameters fracture{}; ///< joint law of the bodies that crack (fracture/cohesive_law.h)
};

/// Constants the element kernel needs, computed once per material.
struct ElasticConstants
{
    Real lambda = 0;    ///< in-plane first Lame constant [Pa]
    Real shear = 0;     ///< mu, shear modulus [Pa]
    Real viscosity = 0; ///< eta_v [Pa s]
    StressLaw law = StressLaw::FiniteStrain;
};

inline ElasticConstants elasticConstants(const Material& m)
{
    const Real nu = m.poissonRatio;
    const Real shear = m.youngsModulus / (2 * (1 + nu));
    Real lambda = m.youngsModulus * nu / ((1 + nu) * (1 - 2 * nu));
    if (m.plane == PlaneModel::Stress)
        lambda = 2 * lambda * shear / (lambda + 2 * shear);
    return {lambda, shear, m.viscosity, m.law};
}

/// P-wave modulus lambda + 2 mu of the in-plane problem [Pa].
inline Real pWaveModulus(const Material& m)
{
    const ElasticConstants c = elasticConstants(m);
    return c.lambda + 2 * c.shear;
}

/// P-wave speed c_p = sqrt((lambda + 2 mu)/rho) [m/s].
inline Real pWaveSpeed(const Material& m)
{
    return std::sqrt(pWaveModulus(m) / m.density);
}

} // namespace veridem::fdem
