// The declared parameters of the contact models: one row per scene key of [[material]] that a
// model reads, written once. From this table come the scene reader's keys, defaults, range checks
// and "required by" / "is not read by" errors (io/material_keys.cpp), the pair mixing of the rows
// with a simple rule (mixMaterials), validateMaterial's ranges, the [[pair]] overrides, and the
// checked table of docs/scene-format.md (tests/io/material_keys_test.cpp compares each row's key,
// unit, default and models with the doc).
//
// A row names the model family whose choice decides whether the key is read (the normal model of
// `model`, the rolling model of `rolling_model`, or the tangential law, which every material has),
// the models of that family that read it and those that require it, its default, its valid range
// (with an optional upper limit derived from the material's other values, e.g. Thornton's p_y <
// E / (pi (1 - nu^2))), how a pair mixes it and the Material / PairParams fields it fills.
// A new model parameter is one row here, its Material field and, if it mixes by a simple rule,
// its PairParams field (read by the law, dem/contact_law.h); the reader and the doc check follow.
#pragma once

#include "dem/materials.h"
#include "dem/models/thornton.h"

#include <cstddef>
#include <iterator>
#include <limits>
#include <sstream>
#include <string>
#include <string_view>

namespace veridem::dem
{

/// Which model choice decides whether a parameter is read.
enum class ModelFamily
{
    Normal,     // `model` (kNormalModelList): linear, hertz, jkr, dmt, thornton
    Tangential, // the Coulomb spring of every material (no choice: read by every material)
    Rolling     // `rolling_model` (kRollingModelList)
};

/// A set of models of one family: bit k is the model of enumerator k.
using ModelSet = unsigned;
constexpr ModelSet modelBit(NormalModel m)
{
    return 1u << static_cast<unsigned>(m);
}
constexpr ModelSet modelBit(RollingModel m)
{
    return 1u << static_cast<unsigned>(m);
}
inline constexpr ModelSet kEveryModel = ~0u;

/// How the values a and b of two materials make the pair's value (docs/models.md).
enum class Mixing
{
    Series,         // springs in series: 2 a b / (a + b) (= a for equal materials)
    Mean,           // (a + b) / 2; a [[pair]] value overrides it
    Smaller,        // min(a, b) (Thornton's p_y: the softer surface flows first)
    WorkOfAdhesion, // w = 2 sqrt(a b) (Girifalco & Good 1957: 2 gamma for like surfaces)
    Both,           // a AND b (a flag: false wins)
    Derived         // mixed into derived pair values by mixMaterials (E*, G*, damping)
};

/// A valid range [lo, hi] with open or closed ends (infinite ends are open).
struct ValueRange
{
    Real lo = -std::numeric_limits<Real>::infinity();
    bool loOpen = true;
    Real hi = std::numeric_limits<Real>::infinity();
    bool hiOpen = true;
};
inline constexpr ValueRange kPositive{0, true};
inline constexpr ValueRange kNonNegative{0, false};

/// One declared parameter (a [[material]] key a model reads).
struct ModelParam
{
    std::string_view key;  // scene key
    std::string_view unit; // SI unit ("-": dimensionless)
    ModelFamily family;
    ModelSet readBy;   // the models of `family` that read it
    ModelSet required; // those of them that need it given (no default)
    Real defaultValue; // when not given (and not required); `absent` if it has none
    ValueRange range;
    Mixing mixing;
    Real Material::*field = nullptr;  // the material's value (a number) ...
    bool Material::*flag = nullptr;   // ... or its flag (a boolean key)
    Real PairParams::*pair = nullptr; // the pair's value, mixed by `mixing` (not Derived)
    bool PairParams::*pairFlag = nullptr;
    bool pairOverride = false;           // a [[pair]] table may give it (Mean rows only: (x + x)/2 = x)
    std::string_view exclusiveWith = {}; // a key that cannot be > 0 with this one (the pair's
                                         // override of one sets the other to 0)
    std::string_view defaultNote = {};   // the default as the doc writes it, if not a number
    Real (*upperLimit)(const Material&) = nullptr; // a limit from the material's other values
    std::string_view upperLimitText = {};          // that limit's formula
};

/// The value of `defaultValue` that means "not given: the model uses another rule".
inline constexpr Real kAbsent = -1;

namespace model_param_detail
{
constexpr ModelSet kHertzian = modelBit(NormalModel::Hertz) | modelBit(NormalModel::Jkr) |
                               modelBit(NormalModel::Dmt) | modelBit(NormalModel::Thornton);
constexpr ModelSet kDashpot = kEveryModel & ~modelBit(NormalModel::Thornton); // (Thornton: plastic)
constexpr ModelSet kAdhesive = modelBit(NormalModel::Jkr) | modelBit(NormalModel::Dmt);
constexpr ModelSet kFrictionCapped = modelBit(RollingModel::ConstantTorque) | modelBit(RollingModel::Epsd) |
                                     modelBit(RollingModel::ConstantTorqueAbsolute);
// Twist about the normal: the models that resist the relative angular velocity (the absolute
// model resists the particle's own).
constexpr ModelSet kRelativeRolling =
    modelBit(RollingModel::ConstantTorque) | modelBit(RollingModel::Epsd) | modelBit(RollingModel::Viscous);
inline Real thorntonLimitOf(const Material& m)
{
    return thorntonYieldStressLimit(m.youngsModulus, m.poissonRatio);
}
} // namespace model_param_detail

// clang-format off
/// Every declared model parameter, in the order the reader reads them (a derived limit's inputs
/// come before it).
inline constexpr ModelParam kModelParams[] = {
    // Normal models.
    {.key = "kn", .unit = "N/m", .family = ModelFamily::Normal,
     .readBy = modelBit(NormalModel::Linear), .required = modelBit(NormalModel::Linear),
     .defaultValue = 1e5, .range = kPositive, .mixing = Mixing::Series,
     .field = &Material::normalStiffness, .pair = &PairParams::kn},
    {.key = "kt_over_kn", .unit = "-", .family = ModelFamily::Normal,
     .readBy = modelBit(NormalModel::Linear), .required = 0, .defaultValue = 2.0 / 7.0,
     .range = kNonNegative, .mixing = Mixing::Mean,
     .field = &Material::tangentialStiffnessRatio, .pair = &PairParams::ktRatio, .defaultNote = "2/7"},
    {.key = "youngs_modulus", .unit = "Pa", .family = ModelFamily::Normal,
     .readBy = model_param_detail::kHertzian, .required = model_param_detail::kHertzian,
     .defaultValue = 0, .range = kPositive, .mixing = Mixing::Derived, .field = &Material::youngsModulus},
    {.key = "poisson_ratio", .unit = "-", .family = ModelFamily::Normal,
     .readBy = model_param_detail::kHertzian, .required = model_param_detail::kHertzian,
     .defaultValue = 0, .range = {-1, true, 0.5, true}, .mixing = Mixing::Derived,
     .field = &Material::poissonRatio},
    {.key = "surface_energy", .unit = "J/m^2", .family = ModelFamily::Normal,
     .readBy = model_param_detail::kAdhesive, .required = model_param_detail::kAdhesive,
     .defaultValue = 0, .range = kNonNegative, .mixing = Mixing::WorkOfAdhesion,
     .field = &Material::surfaceEnergy, .pair = &PairParams::workOfAdhesion},
    {.key = "yield_stress", .unit = "Pa", .family = ModelFamily::Normal,
     .readBy = modelBit(NormalModel::Thornton), .required = modelBit(NormalModel::Thornton),
     .defaultValue = 0, .range = kPositive, .mixing = Mixing::Smaller,
     .field = &Material::yieldStress, .pair = &PairParams::yieldPressure,
     .upperLimit = model_param_detail::thorntonLimitOf, .upperLimitText = "E / (pi (1 - nu^2))"},
    {.key = "restitution", .unit = "-", .family = ModelFamily::Normal,
     .readBy = model_param_detail::kDashpot, .required = 0, .defaultValue = 0.8,
     .range = {0, true, 1, false}, .mixing = Mixing::Mean, .field = &Material::restitution,
     .pairOverride = true},
    {.key = "damping_rate", .unit = "1/s", .family = ModelFamily::Normal,
     .readBy = model_param_detail::kDashpot, .required = 0, .defaultValue = kAbsent,
     .range = kNonNegative, .mixing = Mixing::Derived, .field = &Material::normalDampingRate,
     .defaultNote = "-"},
    {.key = "tangential_damping_ratio", .unit = "-", .family = ModelFamily::Normal,
     .readBy = model_param_detail::kDashpot, .required = 0, .defaultValue = kAbsent,
     .range = kNonNegative, .mixing = Mixing::Derived, .field = &Material::tangentialDampingRatio,
     .defaultNote = "√((2/7) kt/kn)"},
    // The tangential law (Coulomb spring, models/tangential.h).
    {.key = "friction", .unit = "-", .family = ModelFamily::Tangential, .readBy = kEveryModel,
     .required = 0, .defaultValue = 0.5, .range = kNonNegative, .mixing = Mixing::Mean,
     .field = &Material::friction, .pair = &PairParams::mu, .pairOverride = true},
    // Rolling models (models/rolling.h).
    {.key = "rolling_friction", .unit = "m", .family = ModelFamily::Rolling,
     .readBy = model_param_detail::kFrictionCapped, .required = 0, .defaultValue = 0,
     .range = kNonNegative, .mixing = Mixing::Mean, .field = &Material::rollingFrictionLength,
     .pair = &PairParams::rollingLength, .pairOverride = true,
     .exclusiveWith = "rolling_friction_dimensionless"},
    {.key = "rolling_friction_dimensionless", .unit = "-", .family = ModelFamily::Rolling,
     .readBy = model_param_detail::kFrictionCapped, .required = 0, .defaultValue = 0,
     .range = kNonNegative, .mixing = Mixing::Mean, .field = &Material::rollingFrictionDimensionless,
     .pair = &PairParams::rollingDimensionless, .exclusiveWith = "rolling_friction"},
    {.key = "rolling_damping_ratio", .unit = "-", .family = ModelFamily::Rolling,
     .readBy = modelBit(RollingModel::Epsd), .required = 0, .defaultValue = 0.3,
     .range = kNonNegative, .mixing = Mixing::Mean, .field = &Material::rollingDampingRatio,
     .pair = &PairParams::rollingDampingRatio},
    {.key = "rolling_viscous_coefficient", .unit = "s/m", .family = ModelFamily::Rolling,
     .readBy = modelBit(RollingModel::Viscous), .required = modelBit(RollingModel::Viscous),
     .defaultValue = 0, .range = kPositive, .mixing = Mixing::Mean,
     .field = &Material::rollingViscousCoefficient, .pair = &PairParams::rollingViscous},
    {.key = "rolling_twist", .unit = "-", .family = ModelFamily::Rolling,
     .readBy = model_param_detail::kRelativeRolling, .required = 0, .defaultValue = 1,
     .range = {0, false, 1, false}, .mixing = Mixing::Both, .flag = &Material::rollingTwist,
     .pairFlag = &PairParams::rollingTwist, .defaultNote = "true"},
};
// clang-format on

/// Whether the material's models read parameter p (`rolling` is the rolling model named by the
/// scene, before a friction-capped model without rolling friction becomes none).
constexpr bool readsParam(const ModelParam& p, NormalModel normal, RollingModel rolling)
{
    switch (p.family)
    {
    case ModelFamily::Normal:
        return (p.readBy & modelBit(normal)) != 0;
    case ModelFamily::Rolling:
        return (p.readBy & modelBit(rolling)) != 0;
    case ModelFamily::Tangential:
        return true;
    }
    return false;
}
/// Whether the material's models need parameter p given.
constexpr bool requiresParam(const ModelParam& p, NormalModel normal, RollingModel rolling)
{
    switch (p.family)
    {
    case ModelFamily::Normal:
        return (p.required & modelBit(normal)) != 0;
    case ModelFamily::Rolling:
        return (p.required & modelBit(rolling)) != 0;
    case ModelFamily::Tangential:
        return p.required != 0;
    }
    return false;
}

/// Whether `value` lies in p's declared range (and below its derived limit, `limit`).
constexpr bool inRange(const ModelParam& p, Real value, Real limit)
{
    const ValueRange& r = p.range;
    const bool aboveLow = r.loOpen ? value > r.lo : value >= r.lo;
    const bool belowHigh = r.hiOpen ? value < r.hi : value <= r.hi;
    return aboveLow && belowHigh && value < limit && value == value; // (NaN fails)
}

/// The declared parameter of scene key `key` (nullptr if none).
constexpr const ModelParam* findModelParam(std::string_view key)
{
    for (const ModelParam& p : kModelParams)
        if (p.key == key)
            return &p;
    return nullptr;
}

/// A model's scene name (`model`, `rolling_model`): model k of p's family.
inline std::string_view modelName(ModelFamily family, unsigned k)
{
    if (family == ModelFamily::Rolling)
        return kRollingModelList[k].name;
    return kNormalModelList[k].name;
}

/// The scene names of a set of models of one family, comma-separated; "every" for all of them.
inline std::string modelNames(ModelFamily family, ModelSet set)
{
    const std::size_t count = family == ModelFamily::Rolling  ? std::size(kRollingModelList)
                              : family == ModelFamily::Normal ? std::size(kNormalModelList)
                                                              : 0;
    if (family == ModelFamily::Tangential || (set & ((1u << count) - 1)) == (1u << count) - 1)
        return "every";
    std::string names;
    for (unsigned k = 0; k < count; ++k)
        if ((set & (1u << k)) != 0)
            names += (names.empty() ? "" : ", ") + std::string(modelName(family, k));
    return names;
}

/// The models that read p, as docs/scene-format.md's `models` column writes them.
inline std::string readersText(const ModelParam& p)
{
    return modelNames(p.family, p.readBy);
}

/// p's default as docs/scene-format.md's `default` column writes it: "required (linear)", the
/// declared note, or the number.
inline std::string defaultText(const ModelParam& p)
{
    if (p.required != 0)
        return "required (" + modelNames(p.family, p.required) + ")";
    if (!p.defaultNote.empty())
        return std::string(p.defaultNote);
    std::ostringstream s;
    s << p.defaultValue;
    return s.str();
}

/// p's valid range in words with its unit, e.g. "> 0 N/m", "in (0, 1]" or, with a derived upper
/// limit `limit` (infinite if none), "in (0, E / (pi (1 - nu^2)) = 3.2e+10) Pa".
inline std::string rangeText(const ModelParam& p, Real limit = std::numeric_limits<Real>::infinity())
{
    const ValueRange& r = p.range;
    std::ostringstream s;
    const bool limited = limit < r.hi;
    if (r.hi == std::numeric_limits<Real>::infinity() && !limited)
        s << (r.loOpen ? "> " : ">= ") << r.lo;
    else
    {
        s << "in " << (r.loOpen ? "(" : "[") << r.lo << ", ";
        if (limited)
            s << p.upperLimitText << " = " << limit << ")";
        else
            s << r.hi << (r.hiOpen ? ")" : "]");
    }
    if (p.unit != "-")
        s << " " << p.unit;
    return s.str();
}

namespace model_param_detail
{
constexpr bool wellFormed()
{
    for (const ModelParam& p : kModelParams)
    {
        if ((p.field == nullptr) == (p.flag == nullptr))
            return false; // exactly one Material field
        if ((p.required & ~p.readBy) != 0)
            return false; // a model requires only what it reads
        const bool simple = p.mixing != Mixing::Derived;
        if (simple && p.mixing != Mixing::Both && p.pair == nullptr && !p.pairOverride)
            return false; // a simple rule has its pair field
        if (p.pairOverride && p.mixing != Mixing::Mean)
            return false;
    }
    return true;
}
static_assert(wellFormed(), "a kModelParams row is inconsistent (see the checks in wellFormed)");
// (Each row's exclusiveWith names a declared key: checked by tests/io/material_keys_test.cpp, not
// here: GCC 12 does not evaluate the string comparisons of findModelParam as a constant expression
// under -fsanitize=undefined.)
} // namespace model_param_detail

} // namespace veridem::dem
