// The [[material]] and [[pair]] tables of a scene (docs/scene-format.md). The keys a contact model
// reads are not listed here: the reader walks their declarations (dem/model_params.h), which give
// each key's default, range, the models that read or require it and its pair mixing.
#pragma once

#include "dem/materials.h"
#include "dem/model_params.h"
#include "dem/world.h"
#include "io/toml_reader.h"

#include <string_view>
#include <vector>

namespace veridem::io
{

/// The [[material]] keys that are the reader's own, not a model's parameters: the name, the
/// density and the two model choices.
inline constexpr std::string_view kMaterialOwnKeys[] = {"name", "density", "model", "rolling_model"};
/// The [[pair]] keys that are the reader's own: the two material names.
inline constexpr std::string_view kPairOwnKeys[] = {"first", "second"};

/// One [[material]] table: its own keys, then every declared model parameter (a value its models
/// do not read, a required one missing or a value out of its range is refused with the key, the
/// material and the valid range).
dem::Material readMaterial(TableReader& t);

/// The [[pair]] tables: each replaces the mixed values of one material pair by the pair's values
/// of the declared parameters that a pair may override (dem::ModelParam::pairOverride), mixed as if
/// both materials had them. Runs after the pair table is built (World::pairs). A pair given twice
/// is refused.
void applyPairOverrides(std::vector<TableReader>& pairs, dem::World& world);

} // namespace veridem::io
