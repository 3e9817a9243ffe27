#include "io/outlet_output.h"

#include <string>

namespace veridem::io
{

OutletRecorder::OutletRecorder(const std::filesystem::path& directory, const OutputOptions& options,
                               std::optional<std::uint64_t> resumeBytes)
    : dt_(options.dt)
{
    if (resumeBytes && csv_.resume(directory / "outlets.csv", *resumeBytes))
        return;
    csv_.open(directory / "outlets.csv");
    csv_.stream() << "t,outlet,count,mass\n";
    csv_.flush();
}

void OutletRecorder::record(const dem::World& world, const std::vector<dem::Outlet>& outlets)
{
    const double time = outputTime(world.stepCount, dt_);
    std::string rows;
    for (const dem::Outlet& o : outlets)
    {
        appendNumber(rows, time);
        rows += ',' + o.name + ',' + std::to_string(o.count) + ',';
        appendNumber(rows, o.mass);
        rows += '\n';
    }
    csv_.stream() << rows;
    csv_.flush();
}

} // namespace veridem::io
