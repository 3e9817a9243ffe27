// The progress line (io/progress_line.h): plain lines without '\r' when stderr is not a terminal,
// at most one every kPlainInterval seconds; redrawn with '\r' on a terminal; the ETA from the
// rate of the recent steps, not from the start.
#include "io/progress_line.h"

#include <gtest/gtest.h>

#include <cstdio>
#include <string>

namespace veridem::io
{
namespace
{

using Clock = ProgressLine::Clock;

std::string contents(std::FILE* file)
{
    std::fflush(file);
    std::rewind(file);
    std::string text;
    for (int c; (c = std::fgetc(file)) != EOF;)
        text += static_cast<char>(c);
    return text;
}

Clock::time_point at(Clock::time_point start, int milliseconds)
{
    return start + std::chrono::milliseconds(milliseconds);
}

TEST(ProgressLine, PlainLinesEveryFewSecondsWithoutATerminal)
{
    std::FILE* log = std::tmpfile();
    ASSERT_NE(log, nullptr);
    const Clock::time_point start{};
    ProgressLine progress(true, log, 0, "veridem", start);
    // 100 s of a run updated every 20 ms, 100 steps per second.
    for (int k = 1; k <= 5000; ++k)
        progress.update(std::uint64_t(2 * k), 20000, 1e-5 * 2 * k, at(start, 20 * k));
    progress.finish();
    const std::string text = contents(log);
    EXPECT_EQ(text.find('\r'), std::string::npos);
    // One line per kPlainInterval = 10 s from t = 10 s to 100 s: 10 lines.
    std::size_t lines = 0;
    for (char c : text)
        lines += c == '\n';
    EXPECT_EQ(lines, 10u) << text;
    EXPECT_NE(text.find("veridem:  50.0 %  t = 0.1 s  step 10000/20000  ETA 100 s\n"), std::string::npos)
        << text;
    std::fclose(log);
}

TEST(ProgressLine, RedrawnOnATerminal)
{
    std::FILE* screen = std::tmpfile();
    ASSERT_NE(screen, nullptr);
    const Clock::time_point start{};
    ProgressLine progress(true, screen, 1, "veridem", start);
    for (int k = 1; k <= 250; ++k) // 5 s: redrawn each second from 2 s
        progress.update(std::uint64_t(k), 1000, 0, at(start, 20 * k));
    progress.finish();
    const std::string text = contents(screen);
    EXPECT_EQ(text.find('\n'), std::string::npos);
    std::size_t redraws = 0;
    for (std::size_t i = 0; (i = text.find("\rveridem:", i)) != std::string::npos; ++i)
        ++redraws;
    EXPECT_EQ(redraws, 4u) << text;                                               // at 2, 3, 4 and 5 s
    EXPECT_EQ(text.substr(text.size() - 80), "\r" + std::string(78, ' ') + "\r"); // cleared
    std::fclose(screen);
}

TEST(ProgressLine, EtaFromTheRecentRate)
{
    // A pour: 1000 steps/s for the first 30 s, then 100 steps/s (more particles). After 30 s more,
    // the rate of the last kRateWindow = 20 s is 100 steps/s: ETA = remaining / 100. (From the
    // start, (30000 + 3000) steps in 60 s would give 550 steps/s and an ETA 5.5 times too short.)
    std::FILE* log = std::tmpfile();
    ASSERT_NE(log, nullptr);
    const Clock::time_point start{};
    ProgressLine progress(true, log, 0, "veridem", start);
    const std::uint64_t total = 100000;
    std::uint64_t step = 0;
    for (int k = 1; k <= 6000; ++k) // every 10 ms for 60 s
    {
        step += k <= 3000 ? 10 : 1;
        progress.update(step, total, 0, at(start, 10 * k));
    }
    // The last line shown was at 60 s (lines every 10 s); the window then held 20-20.25 s of
    // steps at 100 steps/s: ETA = (100000 - 33000) / 100 = 670 s, to the window's 0.25 s sampling.
    EXPECT_NEAR(progress.lastEta(), 670, 670 * 0.25 / 20 + 1);
    std::fclose(log);
}

TEST(ProgressLine, SilentWhenDisabled)
{
    std::FILE* log = std::tmpfile();
    ASSERT_NE(log, nullptr);
    ProgressLine progress(false, log, 0, "veridem", Clock::time_point{});
    for (int k = 1; k <= 1000; ++k)
        progress.update(std::uint64_t(k), 1000, 0, at(Clock::time_point{}, 100 * k));
    progress.finish();
    EXPECT_TRUE(contents(log).empty());
    std::fclose(log);
}

} // namespace
} // namespace veridem::io
