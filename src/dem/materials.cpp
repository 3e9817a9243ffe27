#include "dem/materials.h"

#include "core/error.h"
#include "dem/model_params.h"
#include "dem/models/normal.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <limits>
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
    if (!(m.density > 0))
        bad(m, "density must be > 0 kg/m^3");
    // Every declared parameter the material's models read, and every one given a value other than
    // its default, in its declared range (a parameter without a default, kAbsent, is absent < 0).
    for (const ModelParam& p : kModelParams)
    {
        if (p.flag)
            continue;
        const Real value = m.*p.field;
        const bool reads = readsParam(p, m.normalModel, m.rollingModel);
        if ((!reads && value == p.defaultValue) || (p.defaultValue == kAbsent && value < 0))
            continue;
        const Real limit = reads && p.upperLimit ? p.upperLimit(m) : std::numeric_limits<Real>::infinity();
        if (!inRange(p, value, limit))
        {
            std::ostringstream s;
            s << "'" << p.key << "' = " << value << " must be " << rangeText(p, limit);
            bad(m, s.str());
        }
    }
    if (m.rollingFrictionLength > 0 && m.rollingFrictionDimensionless > 0)
        bad(m, "give rolling friction either as a length (m) or dimensionless, not both");
    if (m.surfaceEnergy > 0 && !isAdhesive(m.normalModel))
        bad(m, "surface energy is read only by the \"jkr\" and \"dmt\" models");
    if (m.normalModel == NormalModel::Thornton && m.normalDampingRate >= 0)
        bad(m, "the \"thornton\" model has no viscous damping (its energy is lost to plastic flow)");
    if (m.normalModel != NormalModel::Thornton && m.yieldStress != 0)
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
    // The declared parameters with a rule of their own (dem/model_params.h).
    for (const ModelParam& param : kModelParams)
    {
        if (param.pairFlag)
            p.*param.pairFlag = a.*param.flag && b.*param.flag; // (Mixing::Both)
        if (!param.pair)
            continue;
        const Real x = a.*param.field, y = b.*param.field;
        switch (param.mixing)
        {
        case Mixing::Series:
            p.*param.pair = seriesStiffness(x, y);
            break;
        case Mixing::Mean:
            p.*param.pair = 0.5 * (x + y);
            break;
        case Mixing::Smaller:
            p.*param.pair = std::min(x, y);
            break;
        case Mixing::WorkOfAdhesion:
            p.*param.pair = 2.0 * std::sqrt(x * y);
            break;
        case Mixing::Both:
        case Mixing::Derived:
            break;
        }
    }
    // Derived: Hertz's E* and G* from E and nu, the damping from e or gamma_n, and the rolling
    // model (the first material's unless it has none).
    if (isHertzian(p.normalModel))
    {
        p.effectiveModulus = 1.0 / ((1 - a.poissonRatio * a.poissonRatio) / a.youngsModulus +
                                    (1 - b.poissonRatio * b.poissonRatio) / b.youngsModulus);
        const Real ga = a.youngsModulus / (2 * (1 + a.poissonRatio));
        const Real gb = b.youngsModulus / (2 * (1 + b.poissonRatio));
        p.effectiveShearModulus = 1.0 / ((2 - a.poissonRatio) / ga + (2 - b.poissonRatio) / gb);
    }
    const Real e = 0.5 * (a.restitution + b.restitution);
    p.dampingRatio = dampingRatioFromRestitution(e);
    p.hertzBeta = p.normalModel == NormalModel::Thornton ? 0 : hertzBetaFromRestitution(p.normalModel, e);
    if (a.normalDampingRate >= 0 || b.normalDampingRate >= 0)
        p.dampingRate = 0.5 * (std::fmax(a.normalDampingRate, 0) + std::fmax(b.normalDampingRate, 0));
    const Real ratioA = a.tangentialDampingRatio, ratioB = b.tangentialDampingRatio;
    if (ratioA >= 0 && ratioB >= 0)
        p.tangentialDampingRatio = 0.5 * (ratioA + ratioB);
    else
        p.tangentialDampingRatio = std::sqrt((2.0 / 7.0) * p.ktRatio);
    p.rollingModel = a.rollingModel != RollingModel::None ? a.rollingModel : b.rollingModel;
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
