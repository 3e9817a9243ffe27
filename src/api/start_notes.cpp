// The notes a run prints as it starts: the time step against the stability limit, and the
// rolling friction of each material in both conventions.
#include "api/start_notes.h"

#include "core/error.h"
#include "dem/time_step.h"
#include "io/particle_flow_keys.h"

#include <cmath>
#include <cstdio>
#include <sstream>
#include <string>

namespace veridem::api
{

void checkTimeStep(const io::DemScene& scene, const std::string& sceneName, bool allowUnstable, bool speak)
{
    const dem::TimeStepEstimate estimate =
        scene.flow.inserters.empty()
            ? dem::estimateTimeStep(scene.world, scene.characteristicSpeed)
            : dem::estimateTimeStep(io::timeStepProbe(scene.world, scene.flow), scene.characteristicSpeed);
    if (speak)
        std::fprintf(stderr,
                     "veridem: dt = %.4g s; stability limit %.4g s (%s); shortest contact time %.4g s, "
                     "recommended dt <= tc/50 = %.4g s\n",
                     scene.dt, estimate.critical, estimate.limitedBy.c_str(), estimate.contactTime,
                     estimate.recommended);
    if (scene.dt > estimate.critical)
    {
        std::ostringstream s;
        s << sceneName << ": [simulation] dt = " << scene.dt << " s exceeds the stability limit "
          << estimate.critical << " s (" << estimate.limitedBy << "); use dt <= " << estimate.recommended
          << " s (tc/50)";
        if (!allowUnstable)
            throw InputError(s.str() + ", or --force-dt to run anyway");
        if (speak)
            std::fprintf(stderr, "veridem: warning: %s; running anyway (--force-dt)\n", s.str().c_str());
    }
    else if (speak && scene.dt > estimate.contactTime / 20)
        std::fprintf(
            stderr,
            "veridem: warning: dt is more than tc/20: contacts are resolved by fewer than 20 steps\n");
}

namespace
{

/// The scene-file name of a rolling model (`rolling_model`) and its class in Ai et al. (2011).
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

} // namespace

/// Prints each material's rolling model and its friction in both conventions (length and
/// dimensionless) for the radii present, so the two are never confused; for the viscous model
/// its coefficient c_r.
void printRollingFrictionConversion(const dem::World& world)
{
    for (std::uint32_t m = 0; m < world.materials.size(); ++m)
    {
        const dem::Material& material = world.materials[m];
        if (material.rollingModel == dem::RollingModel::None)
            continue;
        Real smallest = 0, largest = 0;
        for (std::size_t i = 0; i < world.particles.size(); ++i)
            if (world.particles.material[i] == m)
            {
                const Real r = world.particles.radius[i];
                smallest = smallest == 0 ? r : std::fmin(smallest, r);
                largest = std::fmax(largest, r);
            }
        if (largest == 0)
            continue;
        const char* model = rollingModelName(material.rollingModel);
        if (material.rollingModel == dem::RollingModel::Viscous)
            std::fprintf(stderr,
                         "veridem: material '%s': rolling friction (%s) c_r = %.4g s/m: torque -c_r Fn R_r^2 "
                         "w_rel, R_r = %.4g m (wall) to %.4g m (two spheres of R = %.4g m)\n",
                         material.name.c_str(), model, material.rollingViscousCoefficient, largest,
                         smallest / 2, smallest);
        else if (material.rollingFrictionLength > 0)
            std::fprintf(
                stderr,
                "veridem: material '%s': rolling friction (%s) mu_r = %.4g m = mu_r' * R with mu_r' = "
                "%.4g (R = %.4g m) to %.4g (R = %.4g m) against a wall\n",
                material.name.c_str(), model, material.rollingFrictionLength,
                material.rollingFrictionLength / largest, largest, material.rollingFrictionLength / smallest,
                smallest);
        else
            std::fprintf(
                stderr,
                "veridem: material '%s': rolling friction (%s) mu_r' = %.4g -> mu_r = mu_r' * R_r = %.4g m "
                "(R_r = %.4g m, wall) to %.4g m (two spheres of R = %.4g m, R_r = R/2)\n",
                material.name.c_str(), model, material.rollingFrictionDimensionless,
                material.rollingFrictionDimensionless * largest, largest,
                material.rollingFrictionDimensionless * smallest / 2, smallest);
    }
}

} // namespace veridem::api
