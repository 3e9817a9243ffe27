// A verification case: a scene, the observables it measures, and the analytical expectation
// computed from a formula in the case's own file. Every quantity carries a two-sided tolerance
// and the reason for it. Cases register themselves with VERIDEM_CASE so that adding a case is
// adding one file (see docs/architecture.md).
#pragma once

#include <filesystem>
#include <functional>
#include <string>
#include <vector>

namespace veridem::distributed
{
class Collective;
}
namespace veridem::exec
{
class TaskSharing;
}

namespace veridem::verify
{

/// One compared number. The check is |measured - expected| <= tolerance * (relative ? |expected| : 1),
/// or, for a lower bound (atLeast), expected - measured <= tolerance.
struct Quantity
{
    std::string name;     // e.g. "v_final"
    std::string unit;     // e.g. "m/s" ("" for dimensionless)
    double expected = 0;  // from the formula
    double measured = 0;  // from the simulation
    double tolerance = 0; // relative (fraction) or absolute (in `unit`)
    bool relative = true; // how `tolerance` is read
    std::string why;      // where the tolerance comes from
    bool atLeast = false; // one-sided: passes when measured >= expected - tolerance (error: the shortfall)

    double error() const; // relative error if `relative`, else absolute error
    bool passed() const;
};

/// A time series a case writes for the report (CSV with a header line).
struct Series
{
    std::string name;                 // file stem, e.g. "t1b_trajectory"
    std::vector<std::string> columns; // header
    std::vector<std::vector<double>> rows;
};

struct CaseResult
{
    std::vector<Quantity> quantities;
    std::vector<std::string> notes; // free-text findings printed under the table
    std::vector<Series> series;     // written to <out>/<case>/<series>.csv when an output dir is set
    double wallSeconds = 0;         // filled by the runner
    bool passed() const;
};

struct CaseContext
{
    bool showProgress = false; // long cases print progress on stderr
    double dtScale = 1;        // every time step of the case is multiplied by this (dt sweeps)
    /// Under `mpirun -np N veridem verify` (N > 1): the ranks, over which the cases labelled
    /// "ranks" step their worlds (dem/case_stepper.h); null in one process.
    const distributed::Collective* ranks = nullptr;
    /// The runner's task sharing (exec/task_sharing.h) when cases run side by side; null otherwise.
    exec::TaskSharing* tasks = nullptr;

    /// Runs task(i) for every i in [0, count) and returns when all have returned: on the runner's
    /// idle workers as well as this thread when cases run side by side, in index order on this
    /// thread otherwise (one worker, or on ranks). For the independent parts of a case (its fills,
    /// its piles, its sweep's runs); each must write only its own results, which then do not depend
    /// on where it ran. The first exception (by index) is rethrown once all have returned.
    void forEach(std::size_t count, const std::function<void(std::size_t)>& task) const;
};

/// An expected order of the dt error of the quantities whose name starts with `prefix`.
struct SweepOrder
{
    std::string prefix;
    double expected = 0; // order p of the error ~ dt^p
    std::string why;     // where it comes from (the scheme and the quantity)
};

/// A dt sweep (sweep.h): the case runs again at dt/2 and dt/4, and every quantity's observed order
/// is printed; those matching `orders` are checked against it within +-`margin`.
struct DtSweep
{
    std::vector<SweepOrder> orders;
    double margin = 0.3;
};

/// Declares the dt sweep of the case `caseName` (VERIDEM_SWEEP).
struct SweepRegistrar
{
    SweepRegistrar(std::string caseName, DtSweep sweep);
};
/// The sweep declared for a case, or null.
const DtSweep* sweepOf(const std::string& caseName);

struct Case
{
    std::string name;                // unique, snake_case
    std::string summary;             // one line
    std::string reference;           // where the formula comes from
    std::vector<std::string> labels; // "quick" (CI), "paper", "dem", "fdem", "slow", "ranks" ...
    std::function<CaseResult(const CaseContext&)> run;
};

/// All registered cases, sorted by name.
std::vector<Case>& registry();

struct Registrar
{
    explicit Registrar(Case c);
};

/// Relative-tolerance quantity helper.
Quantity relativeQuantity(std::string name, std::string unit, double expected, double measured,
                          double tolerance, std::string why);
/// Absolute-tolerance quantity helper.
Quantity absoluteQuantity(std::string name, std::string unit, double expected, double measured,
                          double tolerance, std::string why);

} // namespace veridem::verify

#define VERIDEM_CONCAT_INNER(a, b) a##b
#define VERIDEM_CONCAT(a, b) VERIDEM_CONCAT_INNER(a, b)
/// Registers a case at static-initialisation time: VERIDEM_CASE({.name = ..., .run = ...});
#define VERIDEM_CASE(...)                                                                                    \
    static const ::veridem::verify::Registrar VERIDEM_CONCAT(veridemCaseRegistrar_,                          \
                                                             __LINE__)(::veridem::verify::Case __VA_ARGS__)
/// Declares a case's dt sweep: VERIDEM_SWEEP("case_name", {.orders = {{"prefix", 2.0, "why"}}});
#define VERIDEM_SWEEP(caseName, ...)                                                                         \
    static const ::veridem::verify::SweepRegistrar VERIDEM_CONCAT(veridemSweepRegistrar_, __LINE__)(         \
        caseName, ::veridem::verify::DtSweep __VA_ARGS__)
