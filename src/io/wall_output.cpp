#include "io/wall_output.h"

#include <string>

namespace veridem::io
{

WallLoadRecorder::WallLoadRecorder(const std::filesystem::path& directory, const OutputOptions& options,
                                   std::optional<std::uint64_t> resumeBytes)
    : dt_(options.dt)
{
    const std::filesystem::path path = directory / "walls.csv";
    if (resumeBytes && csv_.resume(path, *resumeBytes))
        return;
    csv_.open(path);
    csv_.stream() << "t,wall,fx,fy,fz,tx,ty,tz\n";
    csv_.flush();
}

void WallLoadRecorder::record(const dem::World& world)
{
    std::string text;
    std::string time;
    appendNumber(time, outputTime(world.stepCount, dt_));
    for (std::size_t w = 0; w < world.walls.size(); ++w)
    {
        const dem::Wall& wall = world.walls[w];
        const dem::WallLoad load = dem::wallLoad(world.wallContacts, static_cast<std::uint32_t>(w),
                                                 wall.loadPoint + wall.displacement);
        text += time;
        text += ',';
        text += wall.name.empty() ? std::to_string(w) : wall.name;
        for (const Real v :
             {load.force.x, load.force.y, load.force.z, load.torque.x, load.torque.y, load.torque.z})
        {
            text += ',';
            appendNumber(text, v);
        }
        text += '\n';
    }
    csv_.stream() << text;
    csv_.flush();
}

} // namespace veridem::io
