// Energy over 100 elastic collisions (BENCHMARKS 5.5): a ball bounces between two parallel fixed
// walls, no gravity, no friction, e = 1, 50 steps per contact, once with the linear spring and once
// with Hertz. Velocity Verlet is symplectic: between collisions the energy is that of the free
// flight, and each collision changes it only through the contact switching on and off between
// steps, an error of order (omega_n dt)^2 whose sign depends on where first touch falls. Checks:
//  * |E_n - E_0| / E_0 below 1e-4 after every one of the 100 collisions (BENCHMARKS 5.5);
//  * no drift: the flight between the walls has a fixed length, so first touch moves through the
//    step by a fixed fraction from one collision to the next and the energy error is a bounded,
//    quasi-periodic function of that phase (time-reversible scheme: zero mean), not a growing
//    sum. A systematic gain or loss per collision would give the changes d_n = (E_n - E_(n-1))/E_0
//    a mean; checked as |mean(d)| / (std(d) / sqrt(n)) below 3 (three standard errors).
#include "chung_ooi.h"
#include "support.h"

#include <cstdio>

namespace veridem::verify
{
namespace
{
void runLaw(bool hertz, const CaseContext& context, CaseResult& r)
{
    Material ball = hertz ? chung_ooi::hertzMaterial(chung_ooi::kGlass, 1.0, 0.0) : flatTurntableBall();
    ball.restitution = 1.0;
    ball.friction = 0;
    ball.rollingModel = dem::RollingModel::None;
    const Real radius = kFlatBallRadius, gap = 0.01, speed = 1.0;
    World world = worldWith(ball, {0, 0, 0});
    world.walls.push_back(floorWall());
    dem::Wall ceiling = floorWall();
    ceiling.name = "ceiling";
    ceiling.shape = dem::PlaneShape{{0, 0, 2 * radius + gap}, {0, 0, -1}};
    world.walls.push_back(ceiling);
    // Slightly irrational start so that first touch falls at varied points between steps.
    world.particles.add({0, 0, radius + 0.5 * gap * (std::sqrt(2.0) - 1)}, {0, 0, speed}, {}, radius,
                        ball.density, 0);
    const Real m = world.particles.mass[0];
    const Real tc =
        hertz ? chung_ooi::hertzImpact(m, radius, chung_ooi::effectiveModulus(chung_ooi::kGlass, true), speed)
                    .contactTime
              : kPi * std::sqrt(m / ball.normalStiffness);
    const Real e0 = 0.5 * m * speed * speed;
    std::vector<Real> index, error;
    bool inContact = false;
    runFor(world, 100 * (gap / speed + tc) + 0.5 * gap / speed, tc / 50, context,
           "asmar_energy_100_collisions",
           [&](const World& w)
           {
               const Real z = w.particles.position[0].z;
               const bool touching = z < radius || z > radius + gap;
               if (inContact && !touching)
               {
                   index.push_back(static_cast<Real>(index.size() + 1));
                   error.push_back((0.5 * m * lengthSquared(w.particles.velocity[0]) - e0) / e0);
               }
               inContact = touching;
           });
    const std::string tag = hertz ? " (Hertz)" : " (linear)";
    Real worst = 0;
    Series s{std::string(hertz ? "hertz" : "linear") + "_energy", {"collision", "dE_over_E"}, {}};
    for (std::size_t i = 0; i < error.size(); ++i)
    {
        worst = std::fmax(worst, std::fabs(error[i]));
        s.rows.push_back({index[i], error[i]});
    }
    r.quantities.push_back(absoluteQuantity("collisions" + tag, "", 100, static_cast<Real>(error.size()), 0.5,
                                            "the run spans 100 wall-to-wall flights"));
    r.quantities.push_back(absoluteQuantity("max |E_n - E_0|/E_0 over the collisions" + tag, "", 0, worst,
                                            1e-4, "BENCHMARKS 5.5 at 50 steps per contact"));
    Real mean = 0, variance = 0;
    const Real n = static_cast<Real>(error.size());
    for (std::size_t i = 0; i < error.size(); ++i)
        mean += (error[i] - (i > 0 ? error[i - 1] : 0.0)) / n;
    for (std::size_t i = 0; i < error.size(); ++i)
    {
        const Real d = error[i] - (i > 0 ? error[i - 1] : 0.0) - mean;
        variance += d * d / (n - 1);
    }
    r.quantities.push_back(absoluteQuantity("drift: |mean change per collision| / standard error" + tag, "",
                                            0, std::fabs(mean) / std::sqrt(variance / n), 3.0,
                                            "three standard errors of the per-collision change"));
    char note[160];
    std::snprintf(note, sizeof note, "%s: mean change per collision %.3g, rms step %.3g (of E_0)",
                  hertz ? "Hertz" : "linear", mean, std::sqrt(variance));
    r.notes.push_back(note);
    r.series.push_back(std::move(s));
}

CaseResult run(const CaseContext& context)
{
    CaseResult r;
    runLaw(false, context, r);
    runLaw(true, context, r);
    return r;
}
} // namespace

VERIDEM_CASE({.name = "asmar_energy_100_collisions",
              .summary = "100 elastic collisions at 50 steps per contact: |dE|/E < 1e-4, bounded, no drift",
              .reference = "BENCHMARKS 5.5",
              .labels = {"dem", "quick", "asmar", "ranks"},
              .run = run});
VERIDEM_SWEEP("asmar_energy_100_collisions",
              {.orders = {
                   {"max |E_n - E_0|/E_0", 2.0,
                    "velocity Verlet's energy error per contact is O((omega_n dt)^2) (BENCHMARKS 5.5)"}}});
} // namespace veridem::verify
