#include "dem/time_step.h"

#include "dem/contact_law.h"

#include <cmath>
#include <limits>
#include <vector>

namespace veridem::dem
{

namespace
{

struct Limit
{
    Real critical, contactTime;
};

Limit contactLimit(const PairParams& params, Real effectiveMass, Real effectiveRadius, Real rollingInertia,
                   Real speed)
{
    Real kn = 0;
    Real contactTime = 0;
    if (params.normalModel == NormalModel::Linear)
        kn = params.kn;
    else
    {
        const Real v = std::fmax(speed, 1e-3);
        const Real deltaMax = std::pow(15.0 * effectiveMass * v * v /
                                           (16.0 * params.effectiveModulus * std::sqrt(effectiveRadius)),
                                       0.4);
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
        omegaMax = std::fmax(omegaMax, std::sqrt(2.25 * kn * muR * muR / rollingInertia));
    }
    return {2.0 / omegaMax * (std::sqrt(1 + zeta * zeta) - zeta), contactTime};
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
    auto consider = [&](const Limit& limit, const std::string& what)
    {
        if (limit.critical < estimate.critical)
        {
            estimate.critical = limit.critical;
            estimate.limitedBy = what;
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
                consider(contactLimit(table(a, b), mStar, rStar, iStar, characteristicSpeed),
                         "contact " + world.materials[a].name + "-" + world.materials[b].name);
            }
        for (const Wall& wall : world.walls)
            consider(contactLimit(table(a, wall.material), minMass[a], minRadius[a], minInertia[a],
                                  characteristicSpeed),
                     "contact " + world.materials[a].name + "-wall '" + wall.name + "'");
    }
    estimate.recommended = estimate.contactTime / 50.0;
    return estimate;
}

} // namespace veridem::dem
