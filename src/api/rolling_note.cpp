#include "api/rolling_note.h"

#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

namespace veridem::api
{

const char* rollingModelName(dem::RollingModel model)
{
    switch (model)
    {
    case dem::RollingModel::None:
        return "none";
    case dem::RollingModel::ConstantTorque:
        return "constant_torque, type A, w relative to the partner";
    case dem::RollingModel::Epsd:
        return "epsd, type C";
    case dem::RollingModel::Viscous:
        return "viscous, type B";
    case dem::RollingModel::ConstantTorqueAbsolute:
        return "constant_torque_absolute, type A, the particle's own w";
    }
    return "unknown";
}

void printRollingFrictionNote(const dem::World& world)
{
    const std::size_t count = world.materials.size();
    // Per material: the smallest and largest radius of its spheres (0: none), and whether a wall
    // is made of it.
    std::vector<Real> smallest(count, 0), largest(count, 0);
    std::vector<bool> onWall(count, false);
    for (std::size_t i = 0; i < world.particles.size(); ++i)
    {
        const std::uint32_t m = world.particles.material[i];
        const Real r = world.particles.radius[i];
        smallest[m] = smallest[m] == 0 ? r : std::fmin(smallest[m], r);
        largest[m] = std::fmax(largest[m], r);
    }
    for (const dem::Wall& wall : world.walls)
        onWall[wall.material] = true;
    dem::PairTable table = world.pairs; // (with the [[pair]] overrides once the scene is read)
    if (table.count() != count)
        table.build(world.materials);
    for (std::uint32_t a = 0; a < count; ++a)
        for (std::uint32_t b = a; b < count; ++b)
        {
            const dem::PairParams& pair = table(a, b);
            if (pair.rollingModel == dem::RollingModel::None)
                continue;
            // Contacts of this pair: sphere-sphere if both have spheres, sphere-wall if one has
            // spheres and the other a wall. The radii are those of the spheres that meet.
            const bool spheres = largest[a] > 0 && largest[b] > 0;
            const bool walls = (largest[a] > 0 && onWall[b]) || (largest[b] > 0 && onWall[a]);
            if (!spheres && !walls)
                continue;
            Real small = 0, large = 0;
            for (const std::uint32_t m : {a, b})
                if (largest[m] > 0)
                {
                    small = small == 0 ? smallest[m] : std::fmin(small, smallest[m]);
                    large = std::fmax(large, largest[m]);
                }
            const dem::PairParams mixed = dem::mixMaterials(world.materials[a], world.materials[b]);
            const bool overridden = mixed.rollingModel != pair.rollingModel ||
                                    mixed.rollingLength != pair.rollingLength ||
                                    mixed.rollingDimensionless != pair.rollingDimensionless ||
                                    mixed.rollingViscous != pair.rollingViscous;
            const std::string name = "'" + world.materials[a].name + "'-'" + world.materials[b].name + "' (" +
                                     (overridden ? "set by [[pair]]"
                                      : a == b   ? "the material's"
                                                 : "mixed") +
                                     ")";
            const char* model = rollingModelName(pair.rollingModel);
            if (pair.rollingModel == dem::RollingModel::Viscous)
                std::fprintf(stderr,
                             "veridem: pair %s: rolling friction (%s) c_r = %.4g s/m: torque -c_r Fn R_r^2 "
                             "w_rel, R_r = %.4g m (wall) to %.4g m (two spheres of R = %.4g m)\n",
                             name.c_str(), model, pair.rollingViscous, large, small / 2, small);
            else if (pair.rollingLength > 0)
                std::fprintf(stderr,
                             "veridem: pair %s: rolling friction (%s) mu_r = %.4g m = mu_r' * R with mu_r' = "
                             "%.4g (R = %.4g m) to %.4g (R = %.4g m) against a wall\n",
                             name.c_str(), model, pair.rollingLength, pair.rollingLength / large, large,
                             pair.rollingLength / small, small);
            else
                std::fprintf(
                    stderr,
                    "veridem: pair %s: rolling friction (%s) mu_r' = %.4g -> mu_r = mu_r' * R_r = %.4g m "
                    "(R_r = %.4g m, wall) to %.4g m (two spheres of R = %.4g m, R_r = R/2)\n",
                    name.c_str(), model, pair.rollingDimensionless, pair.rollingDimensionless * large, large,
                    pair.rollingDimensionless * small / 2, small);
        }
}

} // namespace veridem::api
