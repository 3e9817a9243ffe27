#include "io/species_output.h"

namespace veridem::io
{

SpeciesTable::SpeciesTable(const std::filesystem::path& file, const std::string& header,
                           std::optional<std::uint64_t> resumeBytes)
{
    if (resumeBytes && csv_.resume(file, *resumeBytes))
        return;
    csv_.open(file);
    csv_.stream() << header << '\n';
    csv_.flush();
}

void SpeciesTable::write(const std::string& rows)
{
    csv_.stream() << rows;
    csv_.flush();
}

namespace
{
void appendVec3(std::string& row, const Vec3& v)
{
    for (const Real c : {v.x, v.y, v.z})
    {
        row += ',';
        appendNumber(row, c);
    }
}
} // namespace

SpeciesRecorder::SpeciesRecorder(const std::filesystem::path& directory, const OutputOptions& options,
                                 std::optional<std::uint64_t> resumeBytes)
    : dt_(options.dt), table_(directory / "species.csv", "t,material,count,mass,x,y,z", resumeBytes)
{
}

void SpeciesRecorder::record(const dem::World& world)
{
    const double time = outputTime(world.stepCount, dt_);
    const std::vector<dem::SpeciesMeasure> species =
        dem::measureSpecies(world.particles, world.materials.size());
    std::string rows;
    for (std::size_t k = 0; k < species.size(); ++k)
    {
        appendNumber(rows, time);
        rows += ',' + world.materials[k].name + ',' + std::to_string(species[k].count) + ',';
        appendNumber(rows, species[k].mass);
        appendVec3(rows, species[k].centre);
        rows += '\n';
    }
    table_.write(rows);
}

ZoneRecorder::ZoneRecorder(const std::filesystem::path& directory, const OutputOptions& options,
                           std::vector<dem::Zone> zones, std::optional<std::uint64_t> resumeBytes)
    : dt_(options.dt), zones_(std::move(zones)),
      table_(directory / "zones.csv", "t,zone,material,count", resumeBytes)
{
}

void ZoneRecorder::record(const dem::World& world)
{
    const double time = outputTime(world.stepCount, dt_);
    std::string rows;
    for (const dem::Zone& zone : zones_)
    {
        const std::vector<std::uint64_t> counts = dem::countInZone(world.particles, zone);
        for (std::size_t k = 0; k < counts.size(); ++k)
        {
            appendNumber(rows, time);
            rows += ',' + zone.name + ',' + world.materials[zone.materials[k]].name + ',' +
                    std::to_string(counts[k]) + '\n';
        }
    }
    table_.write(rows);
}

TrackRecorder::TrackRecorder(const std::filesystem::path& directory, const OutputOptions& options,
                             std::vector<std::uint32_t> ids, std::optional<std::uint64_t> resumeBytes)
    : dt_(options.dt), ids_(std::move(ids)),
      table_(directory / "tracked.csv", "t,id,x,y,z,vx,vy,vz", resumeBytes)
{
}

void TrackRecorder::record(const dem::World& world)
{
    const double time = outputTime(world.stepCount, dt_);
    std::string rows;
    for (const std::uint32_t id : ids_)
        for (std::size_t i = 0; i < world.particles.size(); ++i)
        {
            if (world.particles.id[i] != id || world.particles.retired(i)) // (a slot taken out keeps its id)
                continue;
            appendNumber(rows, time);
            rows += ',' + std::to_string(id);
            appendVec3(rows, world.particles.position[i]);
            appendVec3(rows, world.particles.velocity[i]);
            rows += '\n';
            break;
        }
    table_.write(rows);
}

} // namespace veridem::io
