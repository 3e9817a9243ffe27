// A Python dict in the TOML vocabulary turned into a toml::table, so that a scene built from
// Python goes through the scene reader's own checks and messages (docs/scene-format.md).
#include "scene_dict.h"

#include <cmath>
#include <string>

namespace veridem::python
{

namespace py = pybind11;

namespace
{

toml::array toArray(const py::handle& list, const std::string& key);

/// Calls put(node) with the TOML node of a Python value (a toml::value, array or table).
template <class Put> void withNode(const py::handle& value, const std::string& key, Put&& put)
{
    if (py::isinstance<py::bool_>(value))
        return put(toml::value<bool>(value.cast<bool>()));
    if (py::isinstance<py::int_>(value))
        return put(toml::value<std::int64_t>(value.cast<std::int64_t>()));
    if (py::isinstance<py::str>(value))
        return put(toml::value<std::string>(value.cast<std::string>()));
    if (py::isinstance<py::dict>(value))
        return put(sceneTable(value.cast<py::dict>(), key + "."));
    if (py::isinstance<py::float_>(value) ||
        (py::hasattr(value, "__float__") && !py::hasattr(value, "__len__")))
    {
        const double v = value.cast<double>();
        if (!std::isfinite(v))
            throw py::value_error("scene key '" + key + "': " + std::to_string(v) +
                                  " is not a finite number (NaN and infinity are refused)");
        return put(toml::value<double>(v));
    }
    if (py::isinstance<py::sequence>(value) || py::hasattr(value, "tolist"))
    {
        // (a numpy array: as a list of Python numbers)
        const py::object list =
            py::hasattr(value, "tolist") ? value.attr("tolist")() : py::reinterpret_borrow<py::object>(value);
        return put(toArray(list, key));
    }
    throw py::type_error("scene key '" + key + "': a " +
                         py::str(value.get_type().attr("__name__")).cast<std::string>() +
                         " cannot be a scene value (expected a number, bool, string, list or dict)");
}

toml::array toArray(const py::handle& list, const std::string& key)
{
    toml::array array;
    std::size_t k = 0;
    for (const py::handle item : list)
        withNode(item, key + "[" + std::to_string(k++) + "]",
                 [&](auto&& node) { array.push_back(std::move(node)); });
    return array;
}

} // namespace

toml::table sceneTable(const py::dict& scene, const std::string& prefix)
{
    toml::table table;
    for (const auto& [k, v] : scene)
    {
        if (!py::isinstance<py::str>(k))
            throw py::type_error("scene keys must be strings (got " +
                                 py::str(k.get_type().attr("__name__")).cast<std::string>() + " in '" +
                                 prefix + "')");
        const std::string key = k.cast<std::string>();
        withNode(v, prefix + key, [&](auto&& node) { table.insert(key, std::move(node)); });
    }
    return table;
}

} // namespace veridem::python
