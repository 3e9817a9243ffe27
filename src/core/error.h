// Errors reported to the user. Every message is one line that names what is wrong and what was
// expected; the command-line driver prints it and exits non-zero (no crash, nothing lost).
#pragma once

#include <stdexcept>
#include <string>

namespace veridem
{

/// Invalid input (scene file, parameters, command line).
class InputError : public std::runtime_error
{
  public:
    using std::runtime_error::runtime_error;
};

/// An output file that could not be written completely (disk full, permissions); the run stops.
class OutputError : public std::runtime_error
{
  public:
    using std::runtime_error::runtime_error;
};

/// A simulation that became non-physical (NaN, excessive overlap); names step, particle, cause.
class SimulationError : public std::runtime_error
{
  public:
    using std::runtime_error::runtime_error;
};

} // namespace veridem
