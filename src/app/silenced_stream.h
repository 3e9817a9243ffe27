// A scope in which one of this process's output streams goes nowhere: the MPI ranks other than
// the first read the scene too, and its warnings are the first rank's to print (app/run_dem.cpp);
// under `mpirun veridem verify` the first rank alone prints the results (app/main.cpp).
#pragma once

#include <cstdio>
#include <fcntl.h>  // open
#include <unistd.h> // dup, dup2, close

namespace veridem::app
{

/// Silences `stream` (stdout or stderr) while it lives, if `quiet` (an error still reaches the
/// user: it is printed after the scope, by main).
class SilencedStream
{
  public:
    SilencedStream(std::FILE* stream, bool quiet) : stream_(stream)
    {
        if (!quiet)
            return;
        std::fflush(stream_);
        saved_ = dup(fileno(stream_));
        const int null = open("/dev/null", O_WRONLY);
        if (saved_ < 0 || null < 0)
            return;
        dup2(null, fileno(stream_));
        close(null);
    }
    ~SilencedStream()
    {
        if (saved_ < 0)
            return;
        std::fflush(stream_);
        dup2(saved_, fileno(stream_));
        close(saved_);
    }
    SilencedStream(const SilencedStream&) = delete;
    SilencedStream& operator=(const SilencedStream&) = delete;

  private:
    std::FILE* stream_;
    int saved_ = -1;
};

} // namespace veridem::app
