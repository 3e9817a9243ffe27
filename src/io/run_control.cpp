#include "io/run_control.h"

#include <csignal>

namespace veridem::io
{

namespace
{

volatile std::sig_atomic_t stopRequest = 0;

extern "C" void recordStopSignal(int signal)
{
    stopRequest = signal;
}

} // namespace

void stopOnSignals()
{
    struct sigaction action = {};
    action.sa_handler = recordStopSignal;
    sigemptyset(&action.sa_mask);
    action.sa_flags = SA_RESETHAND; // a second signal takes the default action (ends the process)
    sigaction(SIGINT, &action, nullptr);
    sigaction(SIGTERM, &action, nullptr);
}

int stopSignal()
{
    return stopRequest;
}

const char* signalName(int signal)
{
    switch (signal)
    {
    case SIGINT:
        return "SIGINT";
    case SIGTERM:
        return "SIGTERM";
    default:
        return "a signal";
    }
}

} // namespace veridem::io
