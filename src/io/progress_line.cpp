#include "io/progress_line.h"

#include <unistd.h>
#include <utility>

namespace veridem::io
{

ProgressLine::ProgressLine(bool enabled, std::FILE* stream, int terminal, std::string label,
                           Clock::time_point start)
    : enabled_(enabled), terminal_(terminal < 0 ? ::isatty(::fileno(stream)) != 0 : terminal != 0),
      stream_(stream), label_(std::move(label)), start_(start), lastShown_(start)
{
}

void ProgressLine::update(std::uint64_t step, std::uint64_t totalSteps, double time, Clock::time_point now)
{
    if (!enabled_)
        return;
    const auto seconds = [](Clock::duration d) { return std::chrono::duration<double>(d).count(); };
    if (samples_.empty() || seconds(now - samples_.back().when) >= 0.25)
        samples_.push_back({now, step});
    while (samples_.size() > 2 && seconds(now - samples_[1].when) >= kRateWindow)
        samples_.pop_front();
    if (seconds(now - start_) < 2 || seconds(now - lastShown_) < (terminal_ ? 1 : kPlainInterval))
        return;
    lastShown_ = now;
    const Sample& oldest = samples_.front();
    const double span = seconds(now - oldest.when);
    if (span > 0 && step > oldest.step)
        eta_ = double(totalSteps - step) * span / double(step - oldest.step);
    const double percent = totalSteps ? 100 * double(step) / double(totalSteps) : 100;
    char eta[32] = "ETA unknown";
    if (eta_ >= 0)
        std::snprintf(eta, sizeof eta, "ETA %.0f s", eta_);
    std::fprintf(stream_, "%s%s: %5.1f %%  t = %.4g s  step %llu/%llu  %s%s", terminal_ ? "\r" : "",
                 label_.c_str(), percent, time, static_cast<unsigned long long>(step),
                 static_cast<unsigned long long>(totalSteps), eta, terminal_ ? "   " : "\n");
    std::fflush(stream_);
    shown_ = true;
}

void ProgressLine::finish()
{
    if (enabled_ && terminal_ && shown_)
        std::fprintf(stream_, "\r%*s\r", 78, "");
    shown_ = false;
}

} // namespace veridem::io
