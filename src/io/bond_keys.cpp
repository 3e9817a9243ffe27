#include "io/bond_keys.h"

#include "core/constants.h"
#include "core/error.h"

#include <cmath>
#include <sstream>

namespace veridem::io
{

namespace
{

/// The largest angular frequency of two equal bonded spheres of radius r and density rho, each
/// mode's stiffness summed (an upper bound of the pair's highest mode) [rad/s].
Real pairFrequencyBound(const dem::BondParams& p, Real r, Real rho)
{
    const dem::BondSection s = dem::bondSection(p, r, r);
    const Real m = rho * (4.0 / 3.0) * kPi * r * r * r;
    const Real reducedMass = 0.5 * m, reducedInertia = 0.5 * 0.4 * m * r * r;
    const Real axial = std::fmax(p.normalStiffness, p.shearStiffness) * s.area / reducedMass;
    const Real turning =
        (p.normalStiffness * s.bend + p.shearStiffness * s.twist + p.shearStiffness * s.area * r * r) /
        reducedInertia;
    return std::sqrt(axial + turning);
}

} // namespace

void readBonds(TableReader& top, dem::World& world, Real dt, bool laterParticles, bool energyLedger)
{
    auto t = top.table("bonds");
    if (!t)
        return;
    // A bond reads its partners' positions as they are: not through a periodic face, whose
    // partner's image it would need; and the energy ledger has no bond term.
    if (world.domain.any())
        top.fail("bonds", "cannot be combined with periodic boundaries ([domain]) yet");
    if (energyLedger)
        top.fail("bonds",
                 "cannot be combined with [output] energy = true yet (the ledger has no bond energy)");
    dem::BondSet& set = world.bonds;
    set = dem::BondSet{};
    set.enabled = true;
    dem::BondParams& p = set.params;
    p.normalStiffness = t->requiredNumber("kn");
    t->requirePositive("kn", p.normalStiffness, "N/m^3");
    p.shearStiffness = t->requiredNumber("ks");
    t->requireNonNegative("ks", p.shearStiffness, "N/m^3");
    if (auto v = t->optionalNumber("tensile_strength"))
    {
        t->requirePositive("tensile_strength", *v, "Pa");
        p.tensileStrength = *v;
    }
    if (auto v = t->optionalNumber("shear_strength"))
    {
        t->requirePositive("shear_strength", *v, "Pa");
        p.shearStrength = *v;
    }
    p.radiusMultiplier = t->number("radius_multiplier", 1.0);
    t->requirePositive("radius_multiplier", p.radiusMultiplier, "");
    p.dampingRatio = t->number("damping_ratio", 0.0);
    t->requireNonNegative("damping_ratio", p.dampingRatio, "");
    set.createAt = t->number("create_at", 0.0);
    t->requireNonNegative("create_at", set.createAt, "s");
    set.gapTolerance = t->number("gap", 0.0);
    t->requireNonNegative("gap", set.gapTolerance, "m");
    const std::vector<std::string> names = t->strings("materials");
    set.materialSelected.assign(world.materials.size(), names.empty() ? 1 : 0);
    for (const std::string& name : names)
    {
        std::uint32_t id = 0;
        try
        {
            id = world.materialId(name);
        }
        catch (const InputError& e)
        {
            t->fail("materials", e.what());
        }
        set.materialSelected[id] = 1;
    }
    t->finish();

    // The particles it selects, and the pairs it would bond now.
    Real smallest = 0, density = 0;
    std::size_t selected = 0;
    for (std::size_t i = 0; i < world.particles.size(); ++i)
        if (set.materialSelected[world.particles.material[i]])
        {
            ++selected;
            if (smallest == 0 || world.particles.radius[i] < smallest)
            {
                smallest = world.particles.radius[i];
                density = world.materials[world.particles.material[i]].density;
            }
        }
    if (selected == 0 && !laterParticles)
        t->fail(names.empty() ? "kn" : "materials", "selects no particles: no particle of the scene has "
                                                    "a bonded material");
    if (set.createAt == 0 && !laterParticles)
    {
        dem::BondSet trial = set;
        if (dem::createBonds(trial, world.particles) == 0)
        {
            std::ostringstream s;
            s << "selects no pair of particles within gap = " << set.gapTolerance
              << " m of touching (raise `gap` or check the packing)";
            t->fail("gap", s.str());
        }
    }
    if (smallest > 0)
    {
        const Real limit = 2 / pairFrequencyBound(p, smallest, density);
        if (dt > limit)
        {
            std::ostringstream s;
            s << "with dt = " << dt << " s the bonds are unstable: two bonded spheres of radius " << smallest
              << " m need dt < " << limit << " s (2 / omega_max; take ~0.2 of it in a packing)";
            t->fail("kn", s.str());
        }
    }
}

} // namespace veridem::io
