// A scene given as a Python dict (the TOML vocabulary: tables as dicts, arrays of tables as lists
// of dicts) as a toml::table for api::Simulation::fromTable.
#pragma once

#include <toml++/toml.h>

#include <pybind11/pybind11.h>
#include <string>

namespace veridem::python
{

/// Converts a dict; a value that is not a bool, int, float, str, list/tuple/array or dict is a
/// TypeError naming its key (as "table.key[index]"); NaN or infinity a ValueError.
toml::table sceneTable(const pybind11::dict& scene, const std::string& prefix = "");

} // namespace veridem::python
