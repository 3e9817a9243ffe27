#include "io/material_keys.h"

#include <cstdint>
#include <limits>
#include <optional>
#include <set>
#include <sstream>
#include <stdexcept>
#include <utility>
#include <vector>

namespace veridem::io
{

namespace
{

/// The scene names of a model list (dem/materials.h: kNormalModelList, kRollingModelList).
template <class Model, std::size_t kCount>
std::vector<std::string> listedNames(const dem::ModelEntry<Model> (&list)[kCount])
{
    std::vector<std::string> names;
    for (const dem::ModelEntry<Model>& entry : list)
        names.emplace_back(entry.name);
    return names;
}

/// The listed model named `name` (one of listedNames(list): TableReader::choice checked it).
template <class Model, std::size_t kCount>
Model listedModel(const dem::ModelEntry<Model> (&list)[kCount], const std::string& name)
{
    for (const dem::ModelEntry<Model>& entry : list)
        if (name == entry.name)
            return entry.model;
    throw std::logic_error("unlisted model '" + name + "'");
}

/// The choice that decides whether a key of `family` is read, e.g. `model = "thornton"`.
std::string choiceText(dem::ModelFamily family, dem::NormalModel normal, dem::RollingModel rolling)
{
    if (family == dem::ModelFamily::Rolling)
        return "rolling_model = \"" + std::string(dem::modelName(family, static_cast<unsigned>(rolling))) +
               "\"";
    return "model = \"" + std::string(dem::modelName(family, static_cast<unsigned>(normal))) + "\"";
}

/// The declared keys of `family` that the chosen models read, comma-separated.
std::string keysRead(dem::ModelFamily family, dem::NormalModel normal, dem::RollingModel rolling)
{
    std::string keys;
    for (const dem::ModelParam& p : dem::kModelParams)
        if (p.family == family && dem::readsParam(p, normal, rolling))
            keys += (keys.empty() ? "" : ", ") + std::string(p.key);
    return keys.empty() ? "nothing" : keys;
}

std::string numberText(Real value)
{
    std::ostringstream s;
    s << value;
    return s.str();
}

/// Reads declared parameter p of material m (whose earlier parameters are read); returns the
/// message for p if it is required and missing (given after finish(), which names a typo first).
std::string readParam(TableReader& t, dem::Material& m, const dem::ModelParam& p, dem::NormalModel normal,
                      dem::RollingModel rolling)
{
    const std::string of = "material '" + m.name + "'";
    if (!dem::readsParam(p, normal, rolling))
    {
        if (t.has(p.key))
            t.fail(p.key, "is not read by " + choiceText(p.family, normal, rolling) +
                              " (it reads: " + keysRead(p.family, normal, rolling) + "; " + of + ")");
        return "";
    }
    if (p.flag)
    {
        m.*p.flag = t.boolean(p.key, p.defaultValue != 0);
        return "";
    }
    const Real limit = p.upperLimit ? p.upperLimit(m) : std::numeric_limits<Real>::infinity();
    const std::optional<Real> value = t.optionalNumber(p.key);
    if (!value)
    {
        m.*p.field = p.defaultValue;
        if (dem::requiresParam(p, normal, rolling))
            return "is required by " + choiceText(p.family, normal, rolling) + ": give a value " +
                   dem::rangeText(p, limit) + " (" + of + ")";
        return "";
    }
    if (!dem::inRange(p, *value, limit))
        t.fail(p.key,
               "must be " + dem::rangeText(p, limit) + " (got " + numberText(*value) + "; " + of + ")");
    m.*p.field = *value;
    return "";
}

/// A declared key's partner that cannot be > 0 with it (exclusiveWith), reported once.
void checkExclusive(const TableReader& t, const dem::Material& m)
{
    for (const dem::ModelParam& p : dem::kModelParams)
    {
        const dem::ModelParam* other =
            p.exclusiveWith.empty() ? nullptr : dem::findModelParam(p.exclusiveWith);
        if (other && other > &p && m.*p.field > 0 && m.*other->field > 0)
            t.fail(other->key, "cannot be > 0 together with '" + std::string(p.key) +
                                   "': give one of the two (" + "material '" + m.name + "')");
    }
}

} // namespace

dem::Material readMaterial(TableReader& t)
{
    dem::Material m;
    m.name = t.requiredString("name");
    if (m.name.empty() || m.name.find_first_of(", \t\r\n\"#") != std::string::npos)
        t.fail("name", "must be a non-empty name without commas, spaces, quotes or '#' (it is a column of "
                       "state.csv and particles.csv)");
    m.density = t.requiredNumber("density");
    t.requirePositive("density", m.density, "kg/m^3");
    m.normalModel =
        listedModel(dem::kNormalModelList, t.choice("model", "linear", listedNames(dem::kNormalModelList)));
    const dem::RollingModel rolling =
        listedModel(dem::kRollingModelList,
                    t.choice("rolling_model", "constant_torque", listedNames(dem::kRollingModelList)));
    const dem::ModelParam* missing = nullptr; // (the first required key not given)
    std::string missingMessage;
    for (const dem::ModelParam& p : dem::kModelParams)
        if (std::string message = readParam(t, m, p, m.normalModel, rolling); !message.empty() && !missing)
        {
            missing = &p;
            missingMessage = std::move(message);
        }
    t.finish(); // (an unknown key first: it may be the missing one misspelt)
    if (missing)
        t.fail(missing->key, missingMessage);
    checkExclusive(t, m);
    // A friction-capped rolling model given no rolling friction resists nothing: none.
    const bool anyRolling = m.rollingFrictionLength > 0 || m.rollingFrictionDimensionless > 0;
    m.rollingModel = rolling != dem::RollingModel::Viscous && !anyRolling ? dem::RollingModel::None : rolling;
    return m;
}

void applyPairOverrides(std::vector<TableReader>& pairs, dem::World& world)
{
    std::string pairKeys; // (for the message of a key a pair cannot take)
    for (const dem::ModelParam& p : dem::kModelParams)
        if (p.pairOverride)
            pairKeys += (pairKeys.empty() ? "" : ", ") + std::string(p.key);
    std::set<std::pair<std::uint32_t, std::uint32_t>> given;
    for (TableReader& t : pairs)
    {
        const std::string a = t.requiredString("first"), b = t.requiredString("second");
        const std::uint32_t ia = world.materialId(a), ib = world.materialId(b);
        const std::string of = "pair '" + a + "'-'" + b + "'";
        if (!given.insert(std::minmax(ia, ib)).second)
            t.fail("second", "repeats the " + of + " of an earlier [[pair]] (give each pair once)");
        const dem::PairParams& mixed = world.pairs(ia, ib);
        // The pair's values are mixed as if both materials had them ((x + x) / 2 = x exactly).
        dem::Material first = world.materials[ia], second = world.materials[ib];
        for (const dem::ModelParam& p : dem::kModelParams)
        {
            if (!p.pairOverride)
            {
                if (t.has(p.key))
                    t.fail(p.key, "is a material's key: a [[pair]] takes " + pairKeys + " (" + of + ")");
                continue;
            }
            const std::optional<Real> value = t.optionalNumber(p.key);
            if (!value)
                continue;
            if (!dem::readsParam(p, mixed.normalModel, mixed.rollingModel))
                t.fail(p.key, "is not read by the pair's " +
                                  choiceText(p.family, mixed.normalModel, mixed.rollingModel) + " (" + of +
                                  ")");
            if (!dem::inRange(p, *value, std::numeric_limits<Real>::infinity()))
                t.fail(p.key,
                       "must be " + dem::rangeText(p) + " (got " + numberText(*value) + "; " + of + ")");
            first.*p.field = second.*p.field = *value;
            if (const dem::ModelParam* other = dem::findModelParam(p.exclusiveWith))
                first.*other->field = second.*other->field = 0;
        }
        t.finish();
        const dem::PairParams params = dem::mixMaterials(first, second);
        world.pairs.set(ia, ib, params);
        world.pairs.set(ib, ia, params);
    }
}

} // namespace veridem::io
