// veridem: the command-line program.
//   veridem run SCENE [--out DIR] [--threads N] [--restart FILE] [--stop-at-step N] [--strict]
//                                                  run a scene file (DEM 3D or FEM/DEM 2D)
//   veridem verify [--list] [--case NAME]... [--label L]... [--json FILE] [--report DIR] [--jobs N]
//   veridem --version                             version, commit, build type, kernel, MPI
// A bad command line ends like any bad input: one line "veridem: error: ..." naming the option and
// what it accepts, exit status 2.
#include "app/mpi_launch.h"
#include "app/run_scene.h"
#include "app/silenced_stream.h"
#include "core/error.h"
#include "exec/isa.h"
#include "exec/thread_pool.h"
#include "io/toml_reader.h"
#include "runner.h"

#include <CLI/CLI.hpp>

#include <charconv>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <iostream>
#include <memory>
#include <optional>
#include <set>
#include <string>
#include <thread>
#include <vector>

#ifdef VERIDEM_HAVE_FDEM
#include "fdem/scene_runner.h"
#endif

namespace
{

/// A CLI11 check that the value is a whole number from `lowest` to `highest` (no bound above if
/// `highest` is 0), saying so in words: "must be a whole number of threads from 1 to 256 (got
/// '0')".
CLI::Validator wholeNumber(std::uint64_t lowest, std::uint64_t highest, const std::string& what)
{
    const std::string range = "a whole number of " + what + " from " + std::to_string(lowest) +
                              (highest ? " to " + std::to_string(highest) : " up");
    return CLI::Validator(
        [=](std::string& text)
        {
            std::uint64_t value = 0;
            const char* end = text.data() + text.size();
            const auto [stop, problem] = std::from_chars(text.data(), end, value);
            if (problem != std::errc() || stop != end || value < lowest || (highest && value > highest))
                return "must be " + range + " (got '" + text + "')";
            return std::string();
        },
        range);
}

/// `veridem --version`: the version, the commit it was configured from, the build type, the
/// instruction set of the contact kernel on this CPU and whether MPI was built in.
std::string versionText()
{
#ifdef VERIDEM_HAVE_MPI
    const char* mpi = "on";
#else
    const char* mpi = "off";
#endif
    std::string isa;
    try
    {
        isa = veridem::exec::isaName();
    }
    catch (const std::exception& e) // (a bad VERIDEM_KERNEL)
    {
        isa = e.what();
    }
    return std::string("veridem ") + VERIDEM_VERSION + "\ncommit " + VERIDEM_GIT_COMMIT +
           " (when configured)\nbuild " + VERIDEM_BUILD_TYPE + "\ninstruction set " + isa + "\nMPI " + mpi;
}

/// Refuses a --label that no case carries (a typo would otherwise select nothing and pass).
void checkLabels(const std::vector<std::string>& labels)
{
    std::set<std::string> known;
    for (const auto& c : veridem::verify::registry())
        known.insert(c.labels.begin(), c.labels.end());
    for (const auto& l : labels)
        if (!known.count(l))
        {
            std::string list;
            for (const auto& k : known)
                list += (list.empty() ? "" : ", ") + k;
            throw veridem::InputError("unknown verification label '" + l + "' (known labels: " + list + ")");
        }
}

int runCommand(const veridem::app::RunOptions& options)
{
    const toml::table scene = veridem::io::parseFile(options.sceneFile);
    std::string type = "dem";
    if (const auto* simulation = scene["simulation"].as_table())
        if (const auto t = (*simulation)["type"].value<std::string>())
            type = *t;
    if (type == "dem")
        return veridem::app::runDemScene(scene, options);
    if (options.ranks && options.ranks->size() > 1)
        throw veridem::InputError(options.sceneFile + ": [simulation] type \"" + type +
                                  "\" runs in one process; only \"dem\" scenes run on several MPI ranks");
#ifdef VERIDEM_HAVE_FDEM
    if (type == "fdem2d")
        return veridem::fdem::runScene(scene, options.sceneFile, options.outDir, options.progress,
                                       options.allowUnstableTimeStep,
                                       veridem::fdem::RunControl{options.restartFile, options.stopAtStep});
#endif
    throw veridem::InputError(options.sceneFile +
                              ": [simulation] 'type' must be \"dem\" or \"fdem2d\" (got \"" + type + "\")");
}

/// Reports an error and returns its exit code. As one of several MPI ranks, the error may be this
/// rank's alone (the others would wait for it in their next collective), so the job is ended; a
/// rank other than the first waits a moment first, so that an error every rank meets (the scene's)
/// is printed once, by the first rank, whose abort ends the others.
int fail(const veridem::app::MpiLaunch* launch, int code, const char* what, const char* message)
{
    if (launch && launch->size() > 1)
    {
        if (launch->rank() != 0)
            std::this_thread::sleep_for(std::chrono::milliseconds(500));
        std::fprintf(stderr, "veridem: rank %d of %d: %s: %s\n", launch->rank(), launch->size(), what,
                     message);
        std::fflush(stderr);
        launch->abort(code);
    }
    std::fprintf(stderr, "veridem: %s: %s\n", what, message);
    return code;
}

} // namespace

int main(int argc, char** argv)
{
    std::unique_ptr<veridem::app::MpiLaunch> launch;
    try
    {
        launch = std::make_unique<veridem::app::MpiLaunch>(argc, argv);
    }
    catch (const veridem::InputError& e)
    {
        return fail(nullptr, 2, "error", e.what());
    }
    CLI::App app{"veridem: verified DEM and FEM/DEM contact physics (SI units throughout)"};
    app.require_subcommand(1);
    app.set_version_flag("--version", versionText());

    veridem::app::RunOptions runOptions;
    std::string outDir = "out";
    bool quiet = false;
    auto* run =
        app.add_subcommand("run", "Run a scene file; writes particles.csv and ParaView files to --out");
    run->add_option("scene", runOptions.sceneFile, "TOML scene file (see docs/scene-format.md)")->required();
    run->add_option("--out", outDir, "output directory")->capture_default_str();
    run->add_flag("--quiet", quiet, "no progress output");
    run->add_flag("--force-dt", runOptions.allowUnstableTimeStep,
                  "run even if dt exceeds the stability limit (a warning is printed)");
    run->add_option("--restart", runOptions.restartFile,
                    "continue from this checkpoint (DIR/checkpoint.bin of a run of the same scene file), "
                    "with the same bits as the run that wrote it");
    std::uint64_t stopAtStep = 0;
    auto* stopOption = run->add_option("--stop-at-step", stopAtStep,
                                       "stop after this step (counted from the scene's start), writing "
                                       "DIR/checkpoint.bin as on SIGINT; exit status 0")
                           ->check(wholeNumber(1, 0, "steps"));
    run->add_flag("--strict", runOptions.strict,
                  "treat the plausibility warnings (units, positions: docs/scene-format.md) as errors");
    // Default: every CPU this process may use. A waiting thread blocks after a few microseconds
    // (exec/thread_pool.h), so a second thread does not slow a run down on a busy machine.
    // As one of several MPI ranks on a node whose CPUs it may all use (not bound to some): its share.
    int threads = veridem::exec::availableCpus();
    if (const char* local = std::getenv("OMPI_COMM_WORLD_LOCAL_SIZE"); local && std::atoi(local) > 1)
        if (threads >= std::atoi(local))
            threads /= std::atoi(local);
    run->add_option("--threads", threads,
                    "threads of the DEM loops (default: the CPUs this process may run on; the same "
                    "results on any count)")
        ->capture_default_str()
        ->check(wholeNumber(1, veridem::exec::kMaxThreads, "threads"));

    veridem::verify::RunRequest verifyRequest;
    bool list = false;
    std::string jsonPath, reportDir;
    auto* verify = app.add_subcommand("verify", "Run verification cases against their analytical solutions");
    verify->add_flag("--list", list, "list the cases and exit");
    verify->add_option("--case", verifyRequest.names, "run only this case (repeatable)");
    verify->add_option("--label", verifyRequest.labels,
                       "run cases with this label, e.g. quick, paper (repeatable)");
    verify->add_option("--json", jsonPath, "also write the results as JSON");
    verify->add_option("--report", reportDir, "write an HTML report with figures to this directory");
    verify->add_flag("--quiet", quiet, "no progress output");
    bool noDtSweep = false;
    verify->add_flag("--no-dt-sweep", noDtSweep,
                     "run each case at its dt only: no dt/2 and dt/4 runs, no observed orders");
    verify
        ->add_option("--jobs", verifyRequest.jobs,
                     "cases run at once, each on a thread of its own (default: one per core)")
        ->check(wholeNumber(0, 256, "cases (0: one per core)"));

    try
    {
        app.parse(argc, argv);
    }
    catch (const CLI::ParseError& e)
    {
        if (e.get_exit_code() == 0) // --help, --version
            return app.exit(e);
        std::string message = e.what();
        if (!dynamic_cast<const CLI::ValidationError*>(&e)) // (a validator's message says the range)
            message += " (`veridem run --help` and `veridem verify --help` list the options)";
        return fail(launch.get(), 2, "error", message.c_str());
    }

    try
    {
        if (run->parsed())
        {
            runOptions.ranks = launch->collective();
            runOptions.outDir = outDir;
            runOptions.progress = !quiet;
            if (stopOption->count() > 0)
                runOptions.stopAtStep = stopAtStep;
            veridem::exec::setThreads(threads);
            return runCommand(runOptions);
        }
        if (list)
        {
            veridem::verify::listCases();
            return 0;
        }
        checkLabels(verifyRequest.labels);
        // Several ranks: the cases labelled "ranks" step over them, one case at a time; every rank
        // computes the results, the first prints and writes them.
        const bool root = launch->rank() == 0;
        std::optional<veridem::app::SilencedStream> quietOthers;
        if (launch->size() > 1)
        {
            verifyRequest.ranks = launch->collective();
            veridem::exec::setThreads(threads);
            if (!root)
            {
                quietOthers.emplace(stdout, true);
                quiet = true;
                jsonPath.clear();
                reportDir.clear();
            }
        }
        verifyRequest.showProgress = !quiet;
        verifyRequest.dtSweep = !noDtSweep;
        if (!jsonPath.empty())
            verifyRequest.jsonPath = jsonPath;
        if (!reportDir.empty())
        {
            verifyRequest.seriesDir = reportDir + "/data";
            if (jsonPath.empty())
                verifyRequest.jsonPath = reportDir + "/data/results.json";
        }
        const int code = veridem::verify::runCases(verifyRequest);
        if (!reportDir.empty())
        {
            const std::string command = "/usr/bin/python3 \"" VERIDEM_SOURCE_DIR "/scripts/report.py\" \"" +
                                        reportDir + "\" \"" + *verifyRequest.jsonPath + "\"";
            if (std::system(command.c_str()) != 0)
            {
                std::fprintf(stderr, "veridem: the report could not be drawn (command: %s)\n",
                             command.c_str());
                return code ? code : 1;
            }
        }
        return code;
    }
    catch (const veridem::app::RanksStopped& e) // every rank stopped at the same step; the first reports
    {
        std::fprintf(stderr, "veridem: simulation stopped: %s\n", e.what());
        return 3;
    }
    catch (const veridem::InputError& e)
    {
        return fail(launch.get(), 2, "error", e.what());
    }
    catch (const veridem::OutputError& e) // a failed write: the run stops, what was written before stays
    {
        return fail(launch.get(), 4, "output failed", e.what());
    }
    catch (const veridem::SimulationError& e)
    {
        return fail(launch.get(), 3, "simulation stopped", e.what());
    }
    catch (const std::exception& e) // anything else (a file system error, memory): a message, not an abort
    {
        return fail(launch.get(), 1, "error", e.what());
    }
}
