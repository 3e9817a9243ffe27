// A bonded cube under unconfined uniaxial compression: a face-centred-cubic packing of equal
// spheres (12 bonds each, nearest neighbours at 2 r (1 + 1e-4)), its bottom layer frozen, pressed
// by a plane platen moving down at constant speed. The diagonal bonds push the spheres apart
// sideways and the bonds across the load break in tension: the cube fails, the stress falls after
// a peak. There is no closed form for the strength of a bonded packing (Potyondy & Cundall 2004
// calibrate it); the case reports the peak stress and the bonds broken and checks only that it
// failed: a peak followed by a drop, and bonds broken.
//
// Stress: the platen's load is measured as the reaction on the frozen bottom layer (their force
// rows hold every bond and contact force on them), over the cube's cross-section. Quasi-static
// loading: the platen moves 1e-3 of the height in ~14 wave transits (speed 0.01 m/s against
// c = sqrt(E/rho) ~ 300 m/s).
#include "core/error.h"
#include "support.h"

#include <algorithm>
#include <cmath>

namespace veridem::verify
{
namespace
{

CaseResult run(const CaseContext& context)
{
    const Real radius = 1e-3, density = 2500, gapRatio = 1e-4;
    const int cells = 4;                                             // conventional FCC cells a side
    const Real pitch = 2 * radius * (1 + gapRatio) * std::sqrt(2.0); // cell side [m]
    Material material;
    material.name = "rock";
    material.density = density;
    material.normalStiffness = 3e5; // contacts (platen, spheres pressed together) [N/m]
    material.friction = 0.5;
    World world = worldWith(material, {0, 0, 0});
    const Vec3 basis[4] = {{0, 0, 0}, {0.5, 0.5, 0}, {0.5, 0, 0.5}, {0, 0.5, 0.5}};
    const Real side = cells * pitch;
    Real top = 0;
    for (int k = 0; k <= cells; ++k)
        for (int j = 0; j <= cells; ++j)
            for (int i = 0; i <= cells; ++i)
                for (const Vec3& b : basis)
                {
                    const Vec3 x = pitch * (Vec3{Real(i), Real(j), Real(k)} + b);
                    if (x.x > side + 1e-9 || x.y > side + 1e-9 || x.z > side + 1e-9)
                        continue;
                    const std::uint32_t id = world.particles.add(x, {}, {}, radius, density, 0);
                    world.particles.fixed[id] = x.z < 0.25 * pitch ? 1 : 0;
                    top = std::max(top, x.z);
                }
    dem::BondSet& bonds = world.bonds;
    bonds.enabled = true;
    bonds.params.normalStiffness = 1e11; // [N/m^3]
    bonds.params.shearStiffness = 4e10;
    bonds.params.tensileStrength = 2e5; // [Pa]
    bonds.params.shearStrength = 4e5;
    bonds.params.dampingRatio = 0.2;
    bonds.gapTolerance = 4 * radius * gapRatio;
    bonds.materialSelected = {1};
    dem::createBonds(bonds, world.particles);
    const std::size_t formed = bonds.bonds.size();

    const Real speed = 0.01; // platen [m/s]
    dem::Wall platen;
    platen.name = "platen";
    platen.shape = dem::PlaneShape{{0, 0, top + radius}, {0, 0, -1}};
    platen.motion.velocity = {0, 0, -speed};
    world.walls.push_back(platen);
    dem::prepare(world);

    const Real dt = 3e-7 * context.dtScale;
    const Real height = top + 2 * radius, area = (side + 2 * radius) * (side + 2 * radius);
    const auto steps = static_cast<std::uint64_t>(std::llround(1.2e-2 * height / speed / dt));
    Series curve{"stress_strain", {"strain", "stress_Pa", "bonds_broken"}, {}};
    Real peak = 0, peakStrain = 0, last = 0;
    const dem::ParticleStore& p = world.particles;
    for (std::uint64_t s = 1; s <= steps; ++s)
    {
        dem::step(world, dt);
        if (s % 100 != 0)
            continue;
        Real reaction = 0;
        for (const std::uint32_t i : world.fixedIndex)
            reaction -= p.force[i].z;
        const Real stress = reaction / area, strain = speed * world.time / height;
        curve.rows.push_back({strain, stress, Real(bonds.broken)});
        if (stress > peak)
        {
            peak = stress;
            peakStrain = strain;
        }
        last = stress;
        if (!world.health.finite)
            throw SimulationError("bonded_cube_compression: the state is not finite");
    }
    CaseResult r;
    r.quantities.push_back(absoluteQuantity("stress after the run / peak stress", "", 0, last / peak, 0.5,
                                            "plausibility: failed (the stress fell to below half its peak)"));
    Quantity broken;
    broken.name = "bonds broken / bonds formed";
    broken.expected = 0.05;
    broken.measured = Real(bonds.broken) / Real(formed);
    broken.relative = false;
    broken.atLeast = true;
    broken.why = "plausibility: failure breaks bonds (at least 5 % of them)";
    r.quantities.push_back(broken);
    char note[240];
    std::snprintf(
        note, sizeof note,
        "%zu spheres, %zu bonds; peak stress %.4g Pa (%.3g x sigma_c) at strain %.3g; %llu bonds broken",
        p.size(), formed, peak, peak / bonds.params.tensileStrength, peakStrain,
        static_cast<unsigned long long>(bonds.broken));
    r.notes.emplace_back(note);
    r.series.push_back(std::move(curve));
    return r;
}

} // namespace

VERIDEM_CASE(
    {.name = "bonded_cube_compression",
     .summary = "bonded FCC cube under unconfined compression fails (plausibility: peak, bonds broken)",
     .reference = "Potyondy & Cundall 2004 (bonded-particle model); no closed form",
     .labels = {"dem", "bonds", "slow"},
     .run = run});
} // namespace veridem::verify
