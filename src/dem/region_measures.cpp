#include "dem/region_measures.h"

#include "dem/sphere_box_volume.h"

namespace veridem::dem
{

namespace
{
bool inside(const Vec3& x, const Vec3& lo, const Vec3& hi)
{
    return x.x >= lo.x && x.x <= hi.x && x.y >= lo.y && x.y <= hi.y && x.z >= lo.z && x.z <= hi.z;
}

/// Adds f (x_c - x_p)^T to the 3x3 tensor t (row i: force component, column j: arm component).
void addDyad(std::array<Real, 9>& t, const Vec3& f, const Vec3& arm)
{
    const Real fc[3] = {f.x, f.y, f.z}, ac[3] = {arm.x, arm.y, arm.z};
    for (std::size_t i = 0; i < 3; ++i)
        for (std::size_t j = 0; j < 3; ++j)
            t[3 * i + j] += fc[i] * ac[j];
}
} // namespace

RegionMeasures measureRegion(const World& world, const std::vector<ContactRecord>& contacts, const Vec3& lo,
                             const Vec3& hi)
{
    const ParticleStore& p = world.particles;
    RegionMeasures m;
    const Vec3 size = hi - lo;
    const Real volume = size.x * size.y * size.z;
    Real solid = 0, mass = 0;
    Vec3 momentum;
    for (std::size_t i = 0; i < p.size(); ++i)
    {
        solid += sphereBoxVolume(p.position[i], p.radius[i], lo, hi);
        if (inside(p.position[i], lo, hi))
        {
            ++m.particles;
            mass += p.mass[i];
            momentum += p.mass[i] * p.velocity[i];
        }
    }
    // Kinetic part: -sum m v' v'^T over the box's particles, v' = v - the mass-averaged velocity.
    std::array<Real, 9> kinetic{};
    if (mass > 0)
    {
        const Vec3 mean = momentum / mass;
        for (std::size_t i = 0; i < p.size(); ++i)
            if (inside(p.position[i], lo, hi))
            {
                const Vec3 fluctuation = p.velocity[i] - mean;
                addDyad(kinetic, -p.mass[i] * fluctuation, fluctuation);
            }
    }
    std::array<Real, 9> t{};
    for (const ContactRecord& c : contacts)
    {
        const Vec3 force = c.normalForce + c.tangentialForce; // on i
        if (inside(p.position[c.i], lo, hi))
        {
            addDyad(t, force, c.point - p.position[c.i]);
            if (!c.wall)
                ++m.contacts;
        }
        if (!c.wall && inside(p.position[c.partner], lo, hi))
        {
            addDyad(t, -force, c.point - p.position[c.partner]);
            ++m.contacts;
        }
    }
    m.coordination = m.particles ? Real(m.contacts) / Real(m.particles) : 0;
    m.packingFraction = solid / volume;
    const auto symmetric = [&](const std::array<Real, 9>& a) -> std::array<Real, 6>
    {
        return {a[0] / volume,
                a[4] / volume,
                a[8] / volume,
                0.5 * (a[1] + a[3]) / volume,
                0.5 * (a[2] + a[6]) / volume,
                0.5 * (a[5] + a[7]) / volume};
    };
    m.contactStress = symmetric(t);
    m.kineticStress = symmetric(kinetic);
    for (std::size_t k = 0; k < 6; ++k)
        m.stress[k] = m.contactStress[k] + m.kineticStress[k];
    return m;
}

} // namespace veridem::dem
