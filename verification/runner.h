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
};

/// Prints the case list (name, labels, summary).
void listCases();

/// Runs the selected cases; returns the process exit code (0 when every case passed).
int runCases(const RunRequest& request);

} // namespace veridem::verify
