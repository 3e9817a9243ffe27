#include "fdem/scene_runner.h"

#include "core/error.h"
#include "fdem/checkpoint.h"
#include "fdem/output.h"
#include "fdem/scene.h"
#include "fdem/time_step.h"
#include "io/checkpoint_file.h"
#include "io/output_options.h"
#include "io/progress_line.h"
#include "io/run_control.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <optional>
#include <string>

namespace veridem::fdem
{

int runScene(const toml::table& sceneTable, const std::string& sceneFile, const std::filesystem::path& outDir,
             bool progress, bool allowUnstableTimeStep, const RunControl& control)
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
        std::string parts =
            limit.describe(); // "stable time step L s (elements ..., contact ...[, joints ...])"
        parts = parts.substr(parts.find('('));
        char head[64];
        std::snprintf(head, sizeof head, "dt = %g s exceeds the stable limit %g s ", dt, limit.limit);
        const std::string message =
            sceneFile + ": [simulation] " + head + parts + "; use --force-dt to run anyway";
        if (!allowUnstableTimeStep)
            throw InputError(message);
        std::fprintf(stderr, "veridem: warning: %s (running anyway)\n", message.c_str());
    }
    // The scene file's hash ties a checkpoint to it. A caller with a table of its own (no file)
    // gets hash 0, and may not ask for checkpoints or a restart.
    const bool checkpoints = scene.checkpointInterval > 0 || !control.restartFile.empty();
    const std::uint64_t sceneHash =
        checkpoints || std::filesystem::is_regular_file(sceneFile) ? io::sceneFileHash(sceneFile) : 0;
    const auto settleSteps = scene.settleTime > 0
                                 ? static_cast<std::uint64_t>(std::ceil(scene.settleTime / dt))
                                 : std::uint64_t(0);
    const auto totalSteps = static_cast<std::uint64_t>(std::llround(scene.duration / dt));
    const std::uint64_t outputEvery =
        scene.outputInterval > 0
            ? std::max<std::uint64_t>(1, static_cast<std::uint64_t>(std::llround(scene.outputInterval / dt)))
            : totalSteps;
    const std::uint64_t checkpointEvery =
        scene.checkpointInterval > 0
            ? std::max<std::uint64_t>(1,
                                      static_cast<std::uint64_t>(std::llround(scene.checkpointInterval / dt)))
            : 0;
    std::optional<OutputWriter::Resume> resume;
    Real start = 0;
    std::uint64_t firstStep = 0; // steps after the settling already done
    if (!control.restartFile.empty())
    {
        const io::CheckpointOutputs saved = readCheckpoint(control.restartFile, world, sceneHash);
        if (saved.fileBytes.size() != 3 || world.stepCount() < settleSteps ||
            world.stepCount() - settleSteps > totalSteps)
            throw InputError("checkpoint '" + control.restartFile + "' is corrupt: its step " +
                             std::to_string(world.stepCount()) + " or output files do not fit the scene");
        resume = OutputWriter::Resume{saved.frameTimes, saved.fileBytes};
        start = saved.timeOrigin;
        firstStep = world.stepCount() - settleSteps;
        std::fprintf(stderr, "veridem: restarting from '%s' at step %llu (t = %.9g s)\n",
                     control.restartFile.c_str(), static_cast<unsigned long long>(firstStep),
                     world.time() - start);
    }
    else if (scene.settleTime > 0)
    {
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
    if (!resume)
        start = world.time();
    if (control.stopAtStep && *control.stopAtStep <= firstStep)
        throw InputError("--stop-at-step " + std::to_string(*control.stopAtStep) +
                         " is not after the start step " + std::to_string(firstStep));
    OutputWriter output(outDir, scene.vtk, io::chooseVtkFormat(scene.vtkFormat, world.nodes().size()),
                        resume ? &*resume : nullptr);
    if (!resume)
        output.write(world, 0);
    const std::filesystem::path checkpointPath = outDir / "checkpoint.bin";
    const auto writeCheckpointNow = [&]
    {
        OutputWriter::Resume state = output.resumeState();
        writeCheckpoint(checkpointPath, world, sceneHash, {state.frameTimes, state.csvBytes, start});
    };
    io::stopOnSignals();
    const auto wallStart = std::chrono::steady_clock::now();
    io::ProgressLine progressLine(progress, stderr, -1, "fdem2d"); // (io/progress_line.h)
    for (std::uint64_t i = firstStep + 1; i <= totalSteps; ++i)
    {
        world.step();
        if (i % outputEvery == 0 || i == totalSteps)
            output.write(world, io::outputTime(i, dt)); // (exact: step count x dt)
        bool checkpointed = false;
        if (checkpointEvery && (i % checkpointEvery == 0 || i == totalSteps))
        {
            writeCheckpointNow();
            checkpointed = true;
        }
        const int signal = io::stopSignal();
        const bool stop = signal || (control.stopAtStep && i == *control.stopAtStep);
        if (stop && !checkpointed)
            writeCheckpointNow();
        if (stop && i < totalSteps)
        {
            output.finish();
            progressLine.finish();
            std::fprintf(stderr,
                         "veridem: %s at step %llu of %llu (t = %.9g s); checkpoint written; continue with: "
                         "veridem run %s --restart %s --out %s\n",
                         signal ? (std::string("stopped by ") + io::signalName(signal)).c_str() : "stopped",
                         static_cast<unsigned long long>(i), static_cast<unsigned long long>(totalSteps),
                         world.time() - start, sceneFile.c_str(), checkpointPath.string().c_str(),
                         outDir.string().c_str());
            return signal ? io::kInterruptedBase + signal : 0;
        }
        if ((i & 1023) == 0)
            progressLine.update(i, totalSteps, world.time() - start);
    }
    output.finish();
    writeFragments(world, outDir / "fragments.csv");
    progressLine.finish();
    const double wall = std::chrono::duration<double>(std::chrono::steady_clock::now() - wallStart).count();
    std::printf("fdem2d: %llu steps in %.2f s (%.3g element-steps/s); output in %s\n",
                static_cast<unsigned long long>(totalSteps - firstStep), wall,
                static_cast<double>(totalSteps - firstStep) * static_cast<double>(world.triangles().size()) /
                    wall,
                outDir.string().c_str());
    return 0;
}

} // namespace veridem::fdem
