// A scope in which this process's stderr goes nowhere: the MPI ranks other than the first read the
// scene too, and its warnings are the first rank's to print (app/run_dem.cpp).
#pragma once

#include <cstdio>
#include <fcntl.h>  // open
#include <unistd.h> // dup, dup2, close

namespace veridem::app
{

/// Silences this process's stderr while it lives, if `quiet` (an error still reaches the user: it
/// is printed after the scope, by main).
class QuietStderr
{
  public:
    explicit QuietStderr(bool quiet)
    {
        if (!quiet)
            return;
        std::fflush(stderr);
        saved_ = dup(STDERR_FILENO);
        const int null = open("/dev/null", O_WRONLY);
        if (saved_ < 0 || null < 0)
            return;
        dup2(null, STDERR_FILENO);
        close(null);
    }
    ~QuietStderr()
    {
        if (saved_ < 0)
            return;
        std::fflush(stderr);
        dup2(saved_, STDERR_FILENO);
        close(saved_);
    }
    QuietStderr(const QuietStderr&) = delete;
    QuietStderr& operator=(const QuietStderr&) = delete;

  private:
    int saved_ = -1;
};

} // namespace veridem::app
