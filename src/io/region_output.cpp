#include "io/region_output.h"

namespace veridem::io
{

RegionRecorder::RegionRecorder(const std::filesystem::path& directory, const OutputOptions& options,
                               const Vec3& lo, const Vec3& hi, std::optional<std::uint64_t> resumeBytes)
    : dt_(options.dt), lo_(lo), hi_(hi),
      table_(directory,
             {"t", "particles", "contacts", "coordination", "packing_fraction", "sxx", "syy", "szz", "sxy",
              "sxz", "syz", "kinetic_sxx", "kinetic_syy", "kinetic_szz", "kinetic_sxy", "kinetic_sxz",
              "kinetic_syz"},
             resumeBytes, "region.csv")
{
}

void RegionRecorder::record(const dem::World& world, const std::vector<dem::ContactRecord>& contacts)
{
    const dem::RegionMeasures m = dem::measureRegion(world, contacts, lo_, hi_);
    std::vector<ThermoValue> row = {outputTime(world.stepCount, dt_), m.particles, m.contacts, m.coordination,
                                    m.packingFraction};
    for (const std::array<Real, 6>* stress : {&m.stress, &m.kineticStress})
        for (const Real v : *stress)
            row.emplace_back(v);
    table_.row(row);
}

} // namespace veridem::io
