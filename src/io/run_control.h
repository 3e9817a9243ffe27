// Stopping a run cleanly on SIGINT or SIGTERM: the handler only records the signal (an
// async-signal-safe store); the run loop sees it between steps, writes a checkpoint, closes its
// output and exits with kInterruptedBase + the signal number (130 for SIGINT, 143 for SIGTERM,
// the shell's convention; statuses below 128 are the program's own: 2 bad input, 3 blow-up, 4
// failed output). The handlers reset themselves, so a second signal ends the process at once.
#pragma once

namespace veridem::io
{

inline constexpr int kInterruptedBase = 128;

/// Installs the SIGINT and SIGTERM handlers (once per process).
void stopOnSignals();

/// The signal that asked the run to stop, or 0.
int stopSignal();

/// "SIGINT", "SIGTERM" or "a signal".
const char* signalName(int signal);

} // namespace veridem::io
