// Runs registered verification cases and reports them: a table on stdout, optional JSON, and
// optional per-case CSV series (used by the HTML report).
#pragma once

#include "case.h"

#include <optional>
#include <string>
#include <vector>

namespace veridem::verify
{

struct RunRequest
{
    std::vector<std::string> names;  // run these (exact names); empty = all matching labels
    std::vector<std::string> labels; // run cases having any of these labels; empty = all
    std::optional<std::string> jsonPath;
    std::optional<std::string> seriesDir; // write <dir>/<case>/<series>.csv
    bool showProgress = true;
    int jobs = 0; // cases run at once, on threads of their own (0: one per core)
    /// false (`--no-dt-sweep`): each case runs at its dt only, without the runs at dt/2 and dt/4
    /// and their observed orders (the sanitizer build's verify_quick: the same code at smaller dt).
    bool dtSweep = true;
    /// Under `mpirun -np N veridem verify` (N > 1): the ranks. Only the cases labelled "ranks"
    /// run (a case named with `--case` that is not one is refused), one at a time on the calling
    /// thread (the collectives of every rank in one order), their worlds stepped over the ranks
    /// (dem/case_stepper.h); every rank computes the results, the caller prints them on one.
    const distributed::Collective* ranks = nullptr;
};

/// Prints the case list (name, labels, summary).
void listCases();

/// Runs the selected cases, `jobs` at a time (one at a time on several ranks), and reports them in
/// registry order as each finishes (results do not depend on `jobs`: the cases share nothing, and a case's
/// own loops give the same bits on any number of threads); returns the process exit code (0 when every case
/// passed).
int runCases(const RunRequest& request);

} // namespace veridem::verify
