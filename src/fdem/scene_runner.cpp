#include "fdem/scene_runner.h"

#include "core/error.h"
#include "fdem/output.h"
#include "fdem/scene.h"
#include "fdem/time_step.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>

namespace veridem::fdem
{

int runScene(const toml::table& sceneTable, const std::string& sceneFile, const std::filesystem::path& outDir,
             bool progress, bool allowUnstableTimeStep)
{
    const Scene scene = readScene(sceneTable, sceneFile);
    World world = buildWorld(scene, scene.settleTime > 0);
    // The limit covers both phases: the settling may use a stronger normal dashpot.
    ContactParameters worst = scene.settings.contact;
    worst.normalDampingRatio = std::max(worst.normalDampingRatio, scene.settleNormalDampingRatio);
    world.setContactParameters(worst);
    const TimeStepLimit limit = stableTimeStep(world);
    world.setContactParameters(scene.settings.contact);
    const Real dt = scene.settings.timeStep;
    std::printf("fdem2d: %zu nodes, %zu triangles, %zu bodies; %s; dt = %g s\n", world.nodes().size(),
                world.triangles().size(), world.bodyCount(), limit.describe().c_str(), dt);
    if (dt > limit.limit)
    {
        char message[256];
        std::snprintf(
            message, sizeof message,
            "%s: [simulation] dt = %g s exceeds the stable limit %g s (elements %g s, contact %g s); "
            "use --force-dt to run anyway",
            sceneFile.c_str(), dt, limit.limit, limit.element, limit.contact);
        if (!allowUnstableTimeStep)
            throw InputError(message);
        std::fprintf(stderr, "veridem: warning: %s (running anyway)\n", message);
    }
    if (scene.settleTime > 0)
    {
        const auto settleSteps = static_cast<std::uint64_t>(std::ceil(scene.settleTime / dt));
        ContactParameters settling = scene.settings.contact;
        settling.normalDampingRatio = scene.settleNormalDampingRatio;
        world.setContactParameters(settling);
        for (std::uint64_t i = 0; i < settleSteps; ++i)
            world.step();
        world.setContactParameters(scene.settings.contact);
        for (std::uint32_t b = 0; b < world.bodyCount(); ++b)
            if (!scene.bodies[b].fixed)
                world.setBodyVelocity(b, scene.bodies[b].velocity);
        if (progress)
            std::fprintf(stderr, "settled for %g s (%llu steps)\n", scene.settleTime,
                         static_cast<unsigned long long>(settleSteps));
    }
    const Real start = world.time();
    OutputWriter output(outDir, scene.vtk, io::chooseVtkFormat(scene.vtkFormat, world.nodes().size()));
    output.write(world, 0);
    const auto totalSteps = static_cast<std::uint64_t>(std::llround(scene.duration / dt));
    const std::uint64_t outputEvery =
        scene.outputInterval > 0
            ? std::max<std::uint64_t>(1, static_cast<std::uint64_t>(std::llround(scene.outputInterval / dt)))
            : totalSteps;
    const auto wallStart = std::chrono::steady_clock::now();
    auto lastReport = wallStart;
    for (std::uint64_t i = 1; i <= totalSteps; ++i)
    {
        world.step();
        if (i % outputEvery == 0 || i == totalSteps)
            output.write(world, world.time() - start);
        if (progress && (i & 1023) == 0)
        {
            const auto now = std::chrono::steady_clock::now();
            if (now - lastReport > std::chrono::seconds(2))
            {
                lastReport = now;
                const double elapsed = std::chrono::duration<double>(now - wallStart).count();
                const double fraction = static_cast<double>(i) / static_cast<double>(totalSteps);
                std::fprintf(stderr, "\rt = %.4g s (%.1f %%), ETA %.0f s   ", world.time() - start,
                             100 * fraction, elapsed * (1 - fraction) / fraction);
            }
        }
    }
    output.finish();
    if (progress)
        std::fprintf(stderr, "\n");
    const double wall = std::chrono::duration<double>(std::chrono::steady_clock::now() - wallStart).count();
    std::printf("fdem2d: %llu steps in %.2f s (%.3g element-steps/s); output in %s\n",
                static_cast<unsigned long long>(totalSteps), wall,
                static_cast<double>(totalSteps) * static_cast<double>(world.triangles().size()) / wall,
                outDir.string().c_str());
    return 0;
}

} // namespace veridem::fdem
