#include "dem/time_step.h"

#include "dem/contact_law.h"

#include <cmath>
#include <limits>
#include <vector>

namespace veridem::dem
{

// Viscous rolling (type B). The torque on the particle is M = -c w_rel with c = c_r Fn R_r^2,
// evaluated in the force pass with the half-step angular velocity (integrate.h: w += dt/2 T/I
// before the forces and again after them). For one step, with T_n = -c w_(n-1/2) and
// lambda = c / I_r:
//     w_(n+1/2) = w_(n-1/2) + dt T_n / I_r = (1 - lambda dt) w_(n-1/2),
// so the half-step spin is multiplied by g = 1 - lambda dt each step; |g| < 1 requires
// lambda dt < 2 (and g > 0, a monotone decay without sign flips, lambda dt < 1). I_r is the
// particle's own moment of inertia I (reduced over a pair, since the reaction -M acts on the
// partner): within a step the tangential spring cannot take part in the response (dt is far
// below its period), so the effective rolling inertia I + m a^2 of the slow decay does not help.
// Fn is not constant; the estimate takes the largest expected load (header).
Real viscousRollingLimit(Real coefficient, Real normalForce, Real rollingRadius, Real inertia)
{
    const Real c = coefficient * normalForce * rollingRadius * rollingRadius;
    return c > 0 ? 2.0 * inertia / c : std::numeric_limits<Real>::infinity();
}

namespace
{

struct Limit
{
    Real critical, contactTime;
    bool byViscousRolling = false; // the viscous rolling bound is the smaller one
};

Limit contactLimit(const PairParams& params, Real effectiveMass, Real effectiveRadius, Real rollingInertia,
                   Real speed, Real weight)
{
    Real kn = 0;
    Real contactTime = 0;
    Real deltaMax = 0; // [m] Hertz: peak overlap of an impact at the characteristic speed
    const Real v = std::fmax(speed, 1e-3);
    if (params.normalModel == NormalModel::Linear)
        kn = params.kn;
    else
    {
        deltaMax = std::pow(15.0 * effectiveMass * v * v /
                                (16.0 * params.effectiveModulus * std::sqrt(effectiveRadius)),
                            0.4);
        if (params.normalModel == NormalModel::Thornton) // deeper (plastic loading); its unloading
            deltaMax = thorntonPeakOverlap(params.effectiveModulus, effectiveRadius, // stiffness is
                                           params.yieldPressure, effectiveMass, v);  // Hertz's there
        kn = hertzNormalStiffness(params.effectiveModulus, effectiveRadius, deltaMax);
        contactTime =
            2.868 * std::pow(effectiveMass * effectiveMass /
                                 (effectiveRadius * params.effectiveModulus * params.effectiveModulus * v),
                             0.2);
    }
    const ContactCoefficients c = contactCoefficients(params, 0, effectiveMass, effectiveRadius);
    const Real etaN =
        params.normalModel == NormalModel::Linear
            ? c.etaN
            : (params.dampingRate >= 0 ? params.dampingRate * effectiveMass
                                       : hertzDampingCoefficient(params.hertzBeta, kn, effectiveMass));
    const Real omegaN = std::sqrt(kn / effectiveMass);
    const Real zeta = std::fmin(etaN / (2.0 * std::sqrt(effectiveMass * kn)), 0.999);
    if (params.normalModel == NormalModel::Linear)
        contactTime = kPi / (omegaN * std::sqrt(1 - zeta * zeta));
    const Real kt =
        params.normalModel == NormalModel::Linear ? params.ktRatio * kn : kn; // Hertz-Mindlin kt ~ kn
    Real omegaMax = std::fmax(omegaN, std::sqrt(kt / ((2.0 / 7.0) * effectiveMass)));
    if (params.rollingModel == RollingModel::Epsd)
    {
        const Real muR = rollingFrictionLength(params, effectiveRadius);
        omegaMax = std::fmax(omegaMax, std::sqrt(epsdRollingStiffness<Real>(kn, muR) / rollingInertia));
    }
    const Real critical = 2.0 / omegaMax * (std::sqrt(1 + zeta * zeta) - zeta);
    if (params.rollingModel == RollingModel::Viscous)
    {
        // Peak normal force of an impact at the characteristic speed (the load that sizes the
        // Hertz stiffness above): undamped sqrt(kn m*) v for the linear spring, (4/3) E* sqrt(R*)
        // delta_max^(3/2) = kn delta_max (2/3) for Hertz (kn is the tangent stiffness there).
        const Real impact = params.normalModel == NormalModel::Linear ? std::sqrt(kn * effectiveMass) * v
                                                                      : (2.0 / 3.0) * kn * deltaMax;
        const Real viscous = viscousRollingLimit(params.rollingViscous, std::fmax(impact, weight),
                                                 effectiveRadius, rollingInertia);
        if (viscous < critical)
            return {viscous, contactTime, true};
    }
    return {critical, contactTime};
}

} // namespace

TimeStepEstimate estimateTimeStep(const World& world, Real characteristicSpeed)
{
    const ParticleStore& p = world.particles;
    const std::size_t materialCount = world.materials.size();
    const Real inf = std::numeric_limits<Real>::infinity();
    std::vector<Real> minMass(materialCount, inf), minRadius(materialCount, inf),
        minInertia(materialCount, inf);
    for (std::size_t i = 0; i < p.size(); ++i)
    {
        const auto m = p.material[i];
        minMass[m] = std::fmin(minMass[m], p.mass[i]);
        minRadius[m] = std::fmin(minRadius[m], p.radius[i]);
        minInertia[m] = std::fmin(minInertia[m], 1.0 / p.invInertia[i]); // twist: I alone
    }
    PairTable table = world.pairs; // with any [[pair]] overrides once prepared
    if (table.count() != materialCount)
        table.build(world.materials);
    TimeStepEstimate estimate{inf, inf, inf, ""};
    const Real g = length(world.gravity); // [m/s^2]: the weight is a load of a resting contact
    auto consider = [&](const Limit& limit, const std::string& what)
    {
        if (limit.critical < estimate.critical)
        {
            estimate.critical = limit.critical;
            estimate.limitedBy =
                limit.byViscousRolling ? "viscous rolling, c_r Fn R_r^2 dt / I_r < 2, " + what : what;
        }
        estimate.contactTime = std::fmin(estimate.contactTime, limit.contactTime);
    };
    for (std::uint32_t a = 0; a < materialCount; ++a)
    {
        if (!std::isfinite(minMass[a]))
            continue;
        for (std::uint32_t b = a; b < materialCount; ++b)
            if (std::isfinite(minMass[b]) && p.size() > 1)
            {
                const Real mStar = minMass[a] * minMass[b] / (minMass[a] + minMass[b]);
                const Real rStar = minRadius[a] * minRadius[b] / (minRadius[a] + minRadius[b]);
                const Real iStar = 1.0 / (1.0 / minInertia[a] + 1.0 / minInertia[b]);
                consider(contactLimit(table(a, b), mStar, rStar, iStar, characteristicSpeed,
                                      std::fmin(minMass[a], minMass[b]) * g),
                         "contact " + world.materials[a].name + "-" + world.materials[b].name);
            }
        for (const Wall& wall : world.walls)
            consider(contactLimit(table(a, wall.material), minMass[a], minRadius[a], minInertia[a],
                                  characteristicSpeed, minMass[a] * g),
                     "contact " + world.materials[a].name + "-wall '" + wall.name + "'");
    }
    estimate.recommended = estimate.contactTime / 50.0;
    return estimate;
}

} // namespace veridem::dem
