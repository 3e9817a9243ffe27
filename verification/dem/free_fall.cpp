// Free fall of one sphere: z(t) = z0 + vz0 t - g t^2 / 2, vz(t) = vz0 - g t.
// Velocity Verlet integrates a constant acceleration exactly, so the only error is round-off:
// tolerance 1e-12 relative (1000 steps of double round-off, ~1e-13).
#include "support.h"

namespace veridem::verify
{
namespace
{
CaseResult run(const CaseContext& context)
{
    const Real z0 = 10.0, vz0 = 3.0, duration = 1.0, dt = 1e-3, radius = 0.01;
    World world = worldWith(flatTurntableBall(), {0, 0, -kG});
    world.particles.add({0, 0, z0}, {0, 0, vz0}, {}, radius, 7800, 0);
    runFor(world, duration, dt, context, "free_fall", nullptr);
    const Real t = world.time;
    CaseResult r;
    const char* why = "Verlet is exact for constant acceleration; round-off only";
    r.quantities.push_back(relativeQuantity("z(1 s)", "m", z0 + vz0 * t - 0.5 * kG * t * t,
                                            world.particles.position[0].z, 1e-12, why));
    r.quantities.push_back(
        relativeQuantity("vz(1 s)", "m/s", vz0 - kG * t, world.particles.velocity[0].z, 1e-12, why));
    return r;
}
} // namespace

VERIDEM_CASE({.name = "free_fall",
              .summary = "ballistic flight under gravity, exact for velocity Verlet",
              .reference = "Newton; BENCHMARKS 3 test 1",
              .labels = {"dem", "quick"},
              .run = run});
} // namespace veridem::verify
