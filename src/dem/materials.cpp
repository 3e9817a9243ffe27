#include "dem/materials.h"

#include "core/error.h"
#include "dem/models/normal.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <sstream>

namespace veridem::dem
{

void unregisteredContactModel(unsigned value)
{
    std::fprintf(stderr, "veridem: internal error: contact model %u is not in its list (dem/materials.h)\n",
                 value);
    std::abort();
}

namespace
{
Real seriesStiffness(Real a, Real b)
{
    return (a + b) > 0 ? 2.0 * a * b / (a + b) : 0.0;
}

[[noreturn]] void bad(const Material& m, const std::string& what)
{
    throw InputError("material '" + m.name + "': " + what);
}
} // namespace

void validateMaterial(const Material& m)
{
    std::ostringstream s;
    if (!(m.density > 0))
        bad(m, "density must be > 0 kg/m^3");
    if (!(m.restitution > 0 && m.restitution <= 1))
        bad(m, "restitution e must be in (0, 1]");
    if (!(m.friction >= 0))
        bad(m, "friction mu must be >= 0");
    if (!(m.rollingFrictionLength >= 0) || !(m.rollingFrictionDimensionless >= 0))
        bad(m, "rolling friction must be >= 0");
    if (!(m.rollingViscousCoefficient >= 0))
        bad(m, "rolling viscous coefficient must be >= 0 s/m");
    if (m.rollingFrictionLength > 0 && m.rollingFrictionDimensionless > 0)
        bad(m, "give rolling friction either as a length (m) or dimensionless, not both");
    if (m.normalModel == NormalModel::Linear)
    {
        if (!(m.normalStiffness > 0))
            bad(m, "normal stiffness kn must be > 0 N/m");
        if (!(m.tangentialStiffnessRatio >= 0))
            bad(m, "kt/kn must be >= 0");
    }
    else
    {
        if (!(m.youngsModulus > 0))
            bad(m, "Young's modulus must be > 0 Pa for the Hertz, JKR and DMT models");
        if (!(m.poissonRatio > -1 && m.poissonRatio < 0.5))
            bad(m, "Poisson's ratio must be in (-1, 0.5)");
    }
    if (!(m.surfaceEnergy >= 0) || !std::isfinite(m.surfaceEnergy))
        bad(m, "surface energy must be finite and >= 0 J/m^2");
    if (m.surfaceEnergy > 0 && !isAdhesive(m.normalModel))
        bad(m, "surface energy is read only by the \"jkr\" and \"dmt\" models");
    if (m.normalModel == NormalModel::Thornton)
    {
        if (!(m.yieldStress > 0))
            bad(m, "yield stress must be > 0 Pa for the \"thornton\" model");
        const Real limit = thorntonYieldStressLimit(m.youngsModulus, m.poissonRatio);
        if (!(m.yieldStress < limit))
            bad(m, "yield stress must be below E / (pi (1 - nu^2)) = " + std::to_string(limit) +
                       " Pa: at that pressure a like pair would yield only at a contact radius of R*");
        if (m.normalDampingRate >= 0)
            bad(m, "the \"thornton\" model has no viscous damping (its energy is lost to plastic flow)");
    }
    else if (m.yieldStress != 0)
        bad(m, "yield stress is read only by the \"thornton\" model");
}

Real hertzBetaFromRestitution(NormalModel model, Real e)
{
    // Hertz is clipped at Fn >= 0 (models/normal.h); JKR and DMT keep their attractive end and
    // beta = -ln e / sqrt(ln^2 e + pi^2), the linear model's expression.
    return model == NormalModel::Hertz ? hertzDampingFactorWithoutTension(e) : dampingRatioFromRestitution(e);
}

PairParams mixMaterials(const Material& a, const Material& b)
{
    PairParams p;
    if (a.normalModel != b.normalModel)
        throw InputError("materials '" + a.name + "' and '" + b.name +
                         "' use different normal models; give them the same model");
    p.normalModel = a.normalModel;
    p.kn = seriesStiffness(a.normalStiffness, b.normalStiffness);
    p.ktRatio = 0.5 * (a.tangentialStiffnessRatio + b.tangentialStiffnessRatio);
    if (isHertzian(p.normalModel))
    {
        p.effectiveModulus = 1.0 / ((1 - a.poissonRatio * a.poissonRatio) / a.youngsModulus +
                                    (1 - b.poissonRatio * b.poissonRatio) / b.youngsModulus);
        const Real ga = a.youngsModulus / (2 * (1 + a.poissonRatio));
        const Real gb = b.youngsModulus / (2 * (1 + b.poissonRatio));
        p.effectiveShearModulus = 1.0 / ((2 - a.poissonRatio) / ga + (2 - b.poissonRatio) / gb);
        p.workOfAdhesion = 2.0 * std::sqrt(a.surfaceEnergy * b.surfaceEnergy);
    }
    const Real e = 0.5 * (a.restitution + b.restitution);
    p.dampingRatio = dampingRatioFromRestitution(e);
    p.hertzBeta = hertzBetaFromRestitution(p.normalModel, e);
    if (p.normalModel == NormalModel::Thornton) // (no dashpot: beta = 0)
    {
        p.hertzBeta = 0;
        p.yieldPressure = std::min(a.yieldStress, b.yieldStress);
    }
    if (a.normalDampingRate >= 0 || b.normalDampingRate >= 0)
        p.dampingRate = 0.5 * (std::fmax(a.normalDampingRate, 0) + std::fmax(b.normalDampingRate, 0));
    const Real ratioA = a.tangentialDampingRatio, ratioB = b.tangentialDampingRatio;
    if (ratioA >= 0 && ratioB >= 0)
        p.tangentialDampingRatio = 0.5 * (ratioA + ratioB);
    else
        p.tangentialDampingRatio = std::sqrt((2.0 / 7.0) * p.ktRatio);
    p.mu = 0.5 * (a.friction + b.friction);
    p.rollingModel = a.rollingModel != RollingModel::None ? a.rollingModel : b.rollingModel;
    p.rollingLength = 0.5 * (a.rollingFrictionLength + b.rollingFrictionLength);
    p.rollingDimensionless = 0.5 * (a.rollingFrictionDimensionless + b.rollingFrictionDimensionless);
    p.rollingDampingRatio = 0.5 * (a.rollingDampingRatio + b.rollingDampingRatio);
    p.rollingViscous = 0.5 * (a.rollingViscousCoefficient + b.rollingViscousCoefficient);
    p.rollingTwist = a.rollingTwist && b.rollingTwist;
    return p;
}

void PairTable::build(const std::vector<Material>& materials)
{
    count_ = static_cast<std::uint32_t>(materials.size());
    table_.assign(static_cast<std::size_t>(count_) * count_, PairParams{});
    for (std::uint32_t a = 0; a < count_; ++a)
        for (std::uint32_t b = 0; b < count_; ++b)
            table_[a * count_ + b] = mixMaterials(materials[a], materials[b]);
}

unsigned PairTable::historyScalars() const
{
    unsigned most = 0;
    for (const PairParams& p : table_)
        most = std::max(most, historyScalarsOf(p.normalModel));
    return most;
}

void PairTable::set(std::uint32_t a, std::uint32_t b, const PairParams& params)
{
    table_.at(static_cast<std::size_t>(a) * count_ + b) = params;
}

} // namespace veridem::dem
