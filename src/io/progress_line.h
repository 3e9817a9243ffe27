// The progress of a run on stderr: "veridem: 41.2 %  t = 0.1442 s  step 14420/35000  ETA 73 s".
// On a terminal (isatty) the line is redrawn in place with '\r' at most once a second; written to a
// file or a pipe (a batch log), it is a plain line ending in '\n', at most one every
// kPlainInterval seconds, so a log holds readable lines, not one line of megabytes. Nothing is
// shown in the first two seconds of a run.
//
// The ETA is the remaining steps over the step rate measured in the last kRateWindow seconds (not
// since the start: a pour slows down as particles arrive, and the first steps of any run are
// quicker or slower than the rest).
#pragma once

#include <chrono>
#include <cstdint>
#include <cstdio>
#include <deque>
#include <string>

namespace veridem::io
{

class ProgressLine
{
  public:
    using Clock = std::chrono::steady_clock;
    /// Seconds between plain lines (not a terminal), and the window of the measured rate [s].
    static constexpr double kPlainInterval = 10;
    static constexpr double kRateWindow = 20;

    /// `enabled` false: update() and finish() print nothing. `terminal`: whether `stream` is a
    /// terminal (default: isatty on it). `label` opens each line.
    explicit ProgressLine(bool enabled, std::FILE* stream = stderr, int terminal = -1,
                          std::string label = "veridem", Clock::time_point start = Clock::now());

    /// Called after each run of steps: `step` of `totalSteps` (counted from the scene's start),
    /// simulated time `time` [s].
    void update(std::uint64_t step, std::uint64_t totalSteps, double time,
                Clock::time_point now = Clock::now());
    /// Before the run's last messages: clears a redrawn line (terminal) so they start clean.
    void finish();

    /// The last ETA shown [s] (negative before one is known; tests).
    double lastEta() const { return eta_; }

  private:
    bool enabled_, terminal_;
    std::FILE* stream_;
    std::string label_;
    Clock::time_point start_, lastShown_;
    bool shown_ = false;
    double eta_ = -1;
    struct Sample
    {
        Clock::time_point when;
        std::uint64_t step;
    };
    std::deque<Sample> samples_; // at least 0.25 s apart, the last kRateWindow seconds
};

} // namespace veridem::io
