#include "dem/species_measures.h"

namespace veridem::dem
{

std::vector<SpeciesMeasure> measureSpecies(const ParticleStore& particles, std::size_t materialCount)
{
    std::vector<SpeciesMeasure> species(materialCount);
    std::vector<Vec3> moment(materialCount); // sum of m x [kg m]
    for (std::size_t i = 0; i < particles.size(); ++i)
    {
        const std::uint32_t k = particles.material[i];
        if (k >= materialCount || particles.retired(i)) // (taken out by an outlet: not in the scene)
            continue;
        ++species[k].count;
        species[k].mass += particles.mass[i];
        moment[k] += particles.mass[i] * particles.position[i];
    }
    for (std::size_t k = 0; k < materialCount; ++k)
        if (species[k].mass > 0)
            species[k].centre = moment[k] / species[k].mass;
    return species;
}

std::vector<std::uint64_t> countInZone(const ParticleStore& particles, const Zone& zone)
{
    std::vector<std::uint64_t> counts(zone.materials.size());
    for (std::size_t i = 0; i < particles.size(); ++i)
    {
        if (particles.retired(i)) // (taken out by an outlet, leaving the store at the next rebuild)
            continue;
        const Vec3& x = particles.position[i];
        if (!(x.x >= zone.lo.x && x.y >= zone.lo.y && x.z >= zone.lo.z && x.x <= zone.hi.x &&
              x.y <= zone.hi.y && x.z <= zone.hi.z))
            continue;
        for (std::size_t k = 0; k < zone.materials.size(); ++k)
            if (particles.material[i] == zone.materials[k])
                ++counts[k];
    }
    return counts;
}

} // namespace veridem::dem
