// The paper's two balls (Table 1) as materials, shared by the verification cases and by the
// turntable benchmark (bench/dem_bench.cpp), so that both run the same ball. SI units.
#pragma once

#include "core/constants.h"
#include "dem/materials.h"

namespace veridem::verify
{

using dem::Material;

/// The paper's flat-turntable ball (Table 1): steel, a = 6.35 mm, rho = 7800, mu = 0.15, e = 0.8,
/// muR = 1.5e-6 m, k = 1e5 N/m (BENCHMARKS 1b decision), kt = 2/7 k.
inline Material flatTurntableBall()
{
    Material m;
    m.name = "steel";
    m.density = 7800;
    m.normalStiffness = 1e5;
    m.restitution = 0.8;
    m.friction = 0.15;
    m.rollingModel = dem::RollingModel::ConstantTorque;
    m.rollingFrictionLength = 1.5e-6;
    return m;
}
inline constexpr Real kFlatBallRadius = 6.35e-3; // [m]

/// The paper's dish ball (Table 1): a = 3 mm, rho = 7500, mu = 0.5, e = 0.8, muR = 5e-5 m, k = 1e3.
inline Material dishBall()
{
    Material m;
    m.name = "acrylic";
    m.density = 7500;
    m.normalStiffness = 1e3;
    m.restitution = 0.8;
    m.friction = 0.5;
    m.rollingModel = dem::RollingModel::ConstantTorque;
    m.rollingFrictionLength = 5e-5;
    return m;
}
inline constexpr Real kDishBallRadius = 3e-3; // [m]

} // namespace veridem::verify
