// Test helpers: a DEM scene read from TOML text (as from a file named scene.toml), and the message
// of the InputError it raises ("" if it loads).
#pragma once

#include "core/error.h"
#include "io/dem_scene.h"

#include <string>
#include <string_view>

namespace veridem::test
{

inline io::DemScene loadScene(const std::string& text)
{
    return io::readDemScene(toml::parse(std::string_view{text}, std::string_view{"scene.toml"}),
                            "scene.toml");
}

inline std::string sceneError(const std::string& text)
{
    try
    {
        loadScene(text);
    }
    catch (const InputError& e)
    {
        return e.what();
    }
    return "";
}

} // namespace veridem::test
