#include "app/run_scene.h"
#include "core/error.h"

namespace veridem::app
{
int runDemScene(const toml::table&, const RunOptions& options)
{
    throw InputError(options.sceneFile + ": DEM scenes are not implemented yet");
}
} // namespace veridem::app
