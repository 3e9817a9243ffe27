#include "io/scene_limits.h"

#include "core/error.h"

#include <cmath>
#include <iomanip>
#include <sstream>
#include <unistd.h>

namespace veridem::io
{

double physicalMemoryBytes()
{
    const long pages = sysconf(_SC_PHYS_PAGES), pageSize = sysconf(_SC_PAGE_SIZE);
    return pages > 0 && pageSize > 0 ? double(pages) * double(pageSize) : 0.0;
}

namespace
{
double sphereLimit = kMaxSpheres;
}

void limitSpheres(double count)
{
    sphereLimit = std::fmin(sphereLimit, count);
}

double maxSphereCount()
{
    const double memory = physicalMemoryBytes();
    return memory > 0 ? std::fmin(sphereLimit, std::floor(memory / kBytesPerSphere)) : sphereLimit;
}

void checkSphereCount(double count, const std::string& what, const std::string& file)
{
    const double memory = physicalMemoryBytes();
    const double needed = count * kBytesPerSphere;
    if (!(count <= maxSphereCount()))
    {
        std::ostringstream s;
        s << std::setprecision(3) << file << ": " << what << " make " << count << " spheres, needing about "
          << needed / 1e9 << " GB (" << kBytesPerSphere << " B per sphere); the limit is " << maxSphereCount()
          << " spheres";
        if (memory > 0)
            s << " and this machine's " << memory / 1e9 << " GB";
        throw InputError(s.str());
    }
}

void checkSphereRanges(const dem::World& world, Real dt, const std::string& file)
{
    const auto& p = world.particles;
    for (std::size_t i = 0; i < p.size(); ++i)
    {
        const Real r = p.radius[i], m = p.mass[i];
        const Real inertia = 1 / p.invInertia[i]; // the store's I = (2/5) m r^2
        const Vec3 &x = p.position[i], &v = p.velocity[i], &w = p.angularVelocity[i];
        const Real kinetic = 0.5 * m * dot(v, v) + 0.5 * inertia * dot(w, w);
        std::ostringstream s;
        s << std::setprecision(4) << file << ": sphere " << i << " (radius " << r << " m): ";
        if (!(m > 0 && std::isfinite(m) && p.invMass[i] > 0 && std::isfinite(p.invMass[i])))
            s << "mass " << m << " kg is out of range (zero or not finite)";
        else if (!(inertia > 0 && std::isfinite(inertia) && std::isfinite(p.invInertia[i])))
            s << "moment of inertia " << inertia << " kg m^2 is out of range (zero or not finite)";
        else if (!std::isfinite(kinetic))
            s << "kinetic energy is not finite (velocity (" << v.x << ", " << v.y << ", " << v.z
              << ") m/s, angular velocity (" << w.x << ", " << w.y << ", " << w.z << ") rad/s)";
        else if (!(std::fmax(std::fabs(x.x), std::fmax(std::fabs(x.y), std::fabs(x.z))) <=
                   kMaxDistanceInRadii * r))
            s << "position (" << x.x << ", " << x.y << ", " << x.z << ") m is more than "
              << kMaxDistanceInRadii << " radii from the origin: a double cannot resolve its overlaps";
        else if (!(length(v) * dt <= r))
            s << "speed " << length(v) << " m/s moves it " << length(v) * dt
              << " m per step, more than its radius: it would pass through a contact within one step "
                 "(lower dt or the speed)";
        else
            continue;
        throw InputError(s.str());
    }
}

} // namespace veridem::io
