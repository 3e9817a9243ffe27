#include "dem/region_measures.h"

#include "core/constants.h"

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
    Real solid = 0;
    for (std::size_t i = 0; i < p.size(); ++i)
        if (inside(p.position[i], lo, hi))
        {
            ++m.particles;
            solid += (4.0 / 3.0) * kPi * p.radius[i] * p.radius[i] * p.radius[i];
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
    m.stress = {t[0] / volume,
                t[4] / volume,
                t[8] / volume,
                0.5 * (t[1] + t[3]) / volume,
                0.5 * (t[2] + t[6]) / volume,
                0.5 * (t[5] + t[7]) / volume};
    return m;
}

} // namespace veridem::dem
