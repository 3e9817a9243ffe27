// One parallel bond (dem/bonds/bond_law.h) pulled apart by a force F = F' t ramped on one partner,
// the other frozen: it breaks at the first step whose tensile stress Fn / A reaches the tensile
// strength sigma_c. The bond's tension kn A (d - d0) at that step lies within one step's increment
// of it above sigma_c A (checked at the step it broke from the centre distance, the law's total
// normal form). The applied force then exceeds it by the damper's share, 2 beta sqrt(m kn A) v with
// the quasi-static stretch rate v = F' / (kn A) (beta = 1, so the partner follows the ramp without
// ringing), to about one step's increment (the transient of the ramp's start, decayed).
#include "core/error.h"
#include "support.h"

#include <cmath>

namespace veridem::verify
{
namespace
{

CaseResult run(const CaseContext& context)
{
    const Real radius = 1e-3, gap = 2e-6, density = 2500;
    Material material;
    material.name = "cement";
    material.density = density;
    World world = worldWith(material, {0, 0, 0});
    world.particles.add({0, 0, 0}, {}, {}, radius, density, 0);
    world.particles.add({2 * radius + gap, 0, 0}, {}, {}, radius, density, 0);
    world.particles.fixed[0] = 1;
    world.particles.keepExternalLoads();
    dem::BondSet& bonds = world.bonds;
    bonds.enabled = true;
    bonds.params.normalStiffness = 1e11; // [N/m^3]
    bonds.params.shearStiffness = 4e10;
    bonds.params.tensileStrength = 1e6; // [Pa]
    bonds.params.dampingRatio = 1;
    bonds.gapTolerance = 2 * gap;
    bonds.materialSelected = {1};
    dem::createBonds(bonds, world.particles);
    dem::prepare(world);

    const dem::BondSection sec = dem::bondSection(bonds.params, radius, radius);
    const Real ka = bonds.params.normalStiffness * sec.area;       // [N/m]
    const Real strength = bonds.params.tensileStrength * sec.area; // [N]
    const Real mass = world.particles.mass[1];
    const Real dt = 5e-7 * context.dtScale;
    const Real rampSteps = 20000;                  // to the strength
    const Real rate = strength / (rampSteps * dt); // F' [N/s]
    const Real d0 = bonds.bonds[0].state.restLength;

    Real tension = 0, previousTension = 0, appliedAtBreak = 0;
    bool broke = false;
    for (std::uint64_t s = 0; s < static_cast<std::uint64_t>(2 * rampSteps) && !broke; ++s)
    {
        const Real applied = rate * (world.time + dt); // at the end of the step, as its forces
        world.particles.externalForce[1] = {applied, 0, 0};
        dem::step(world, dt);
        previousTension = tension;
        tension = ka * (length(world.particles.position[1] - world.particles.position[0]) - d0);
        if (bonds.broken > 0)
        {
            broke = true;
            appliedAtBreak = applied;
        }
    }
    CaseResult r;
    if (!broke)
        throw SimulationError("bond_tension_break: the bond did not break by twice the ramp to its strength");
    const Real increment = tension - previousTension; // the last step's tension increment [N]
    Quantity atBreak = absoluteQuantity("bond tension at the breaking step - sigma_c A", "N", 0.5 * increment,
                                        tension - strength, 0.5 * increment,
                                        "in [0, one step's increment]: the first step at or above strength");
    r.quantities.push_back(atBreak);
    const Real lag = 2 * bonds.params.dampingRatio * std::sqrt(mass * ka) * rate / ka;
    r.quantities.push_back(absoluteQuantity(
        "applied force at break - (sigma_c A + damper share)", "N", 0, appliedAtBreak - (strength + lag),
        rate * dt, "one step's load increment (the ramp's start transient decayed)"));
    char note[200];
    std::snprintf(note, sizeof note, "sigma_c A = %.6g N, load increment %.3g N a step, damper share %.3g N",
                  strength, rate * dt, lag);
    r.notes.emplace_back(note);
    return r;
}

} // namespace

VERIDEM_CASE({.name = "bond_tension_break",
              .summary = "a parallel bond pulled by a ramped force breaks at its tensile strength",
              .reference = "Potyondy & Cundall 2004, strength criterion",
              .labels = {"dem", "quick", "bonds"},
              .run = run});
} // namespace veridem::verify
