// Ready-made scenarios shared by the verification cases, the benchmark and the examples.
#pragma once

#include "fdem/world.h"

#include <cstdint>

namespace veridem::fdem
{

/// Paper Fig. 1 (Xiang, Munjiza, Latham & Guises, section 3; BENCHMARKS 1a): a square block on a
/// fixed base, given a horizontal velocity, stops after L = v^2 / (2 mu g).
struct SlidingBlockSetup
{
    Real velocity = 1;                  ///< v_i [m/s]
    Real timeStep = 1e-6;               ///< dt [s]
    int cells = 4;                      ///< n x n cells of 2 triangles in the block
    Real side = 0.05;                   ///< l [m]
    Real density = 2650;                ///< rho [kg/m^3]
    Real youngsModulus = 1e9;           ///< E [Pa]
    Real poissonRatio = 0.25;           ///< nu [1], plane strain
    Real friction = 0.5;                ///< mu [1]
    Real gravity = 9.81;                ///< g [m/s^2]
    Real penaltyFactor = 10;            ///< p_n = p_t = penaltyFactor * E
    Real normalDampingRatio = 0.3;      ///< zeta_n while settling
    Real slidingNormalDampingRatio = 0; ///< zeta_n after v_i is imposed (see docs/fdem.md)
    Real highestModeDampingRatio =
        0.5;                 ///< sets the element viscosity eta_v = 2 xi (lambda + 2 mu) / omega_max
    Real baseCellFactor = 4; ///< base cell size / block cell size (rigid base, one cell thick)
    Real settleTime = 0.005; ///< [s] at rest under gravity before v_i is imposed
    Real stopSpeed = 1e-4;   ///< [m/s] the block is stopped when |v_c| < stopSpeed ...
    Real stopHold = 0.05;    ///< [s] ... for this long (BENCHMARKS 1a "Measure")
    Real creepTime = 0.1;    ///< [s] drift measured over this time after the hold
};

struct SlidingBlockResult
{
    bool stopped = false;
    Real stopDistance = 0;     ///< centroid displacement at the first time |v_c| < stopSpeed (that held) [m]
    Real stopTime = 0;         ///< that time, from the impulse [s]
    Real creep = 0;            ///< centroid drift over creepTime after the hold [m]
    Real frictionWork = 0;     ///< work of the tangential contact forces from the impulse to the stop [J/m]
    Real kineticEnergy = 0;    ///< m v_i^2 / 2 [J/m]
    Real meanCapRatio = 0;     ///< mean of sum|F_t| / sum mu|F_n| while |v_c| > 0.01 v_i [1]
    Real dampingWork = 0;      ///< normal-dashpot work from the impulse to the stop [J/m]
    std::uint64_t steps = 0;   ///< all steps, settling included
    std::size_t triangles = 0; ///< triangles with a free node (block)
    double wallSeconds = 0;
};

/// The world of the sliding block (block body 1 on base body 0), at rest, before settling.
World makeSlidingBlockWorld(const SlidingBlockSetup& setup);

/// Settles, imposes v_i and runs to the stop criterion (or 2 t_s + 1 s).
SlidingBlockResult runSlidingBlock(const SlidingBlockSetup& setup);

} // namespace veridem::fdem
