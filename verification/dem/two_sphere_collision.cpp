// Oblique collision of two unequal spheres (no gravity, no walls), linear spring-dashpot with
// friction and spin.
//   * total linear momentum is conserved by Newton's third law: to round-off (1e-12 relative);
//   * total angular momentum about the origin (orbital + spin) is conserved because the lever
//     arms add up to the centre distance (contact-radius convention, docs/models.md): 1e-12;
//   * the normal relative velocity restitution equals e (0.3 % at >= 50 steps per contact,
//     BENCHMARKS 2.1; here 100 steps per contact).
#include "dem/models/normal.h"
#include "support.h"

namespace veridem::verify
{
namespace
{
Vec3 linearMomentum(const World& w)
{
    Vec3 p;
    for (std::size_t i = 0; i < w.particles.size(); ++i)
        p += w.particles.mass[i] * w.particles.velocity[i];
    return p;
}

Vec3 angularMomentum(const World& w)
{
    Vec3 l;
    const auto& p = w.particles;
    for (std::size_t i = 0; i < p.size(); ++i)
        l += p.mass[i] * cross(p.position[i], p.velocity[i]) + p.angularVelocity[i] / p.invInertia[i];
    return l;
}

CaseResult run(const CaseContext& context)
{
    Material glass;
    glass.name = "glass";
    glass.density = 2500;
    glass.normalStiffness = 1e4;
    glass.restitution = 0.7;
    glass.friction = 0.3;
    World world = worldWith(glass, {0, 0, 0});
    const Real r1 = 5e-3, r2 = 8e-3;
    // Sphere 1 moves along +x; sphere 2 is offset in y so the impact is oblique, and both spin.
    world.particles.add({-0.02, 0.003, 0}, {1.0, 0.0, 0.1}, {5, -3, 20}, r1, glass.density, 0);
    world.particles.add({0.0, 0, 0.0}, {-0.3, 0.1, 0}, {0, 10, -4}, r2, glass.density, 0);

    const Real m1 = world.particles.mass[0], m2 = world.particles.mass[1];
    const Real mStar = m1 * m2 / (m1 + m2);
    const Real zeta = dem::dampingRatioFromRestitution(glass.restitution);
    const Real tc = kPi / (std::sqrt(glass.normalStiffness / mStar) * std::sqrt(1 - zeta * zeta));
    const Real dt = tc / 100;

    dem::prepare(world);
    const Vec3 p0 = linearMomentum(world), l0 = angularMomentum(world);
    // Normal relative speed at first touch: record the normal and the approach speed then.
    Vec3 normal;
    Real approach = 0;
    bool touched = false, separated = false;
    Real departure = 0;
    runFor(world, 0.05, dt, context, "two_sphere_collision",
           [&](const World& w)
           {
               const auto& p = w.particles;
               const Vec3 d = p.position[0] - p.position[1];
               const bool inContact = length(d) < r1 + r2;
               if (inContact && !touched)
               {
                   touched = true;
                   normal = d / length(d);
               }
               if (touched && !inContact && !separated)
               {
                   separated = true;
                   const Vec3 n = d / length(d);
                   departure = dot(p.velocity[0] - p.velocity[1], n);
               }
           });
    // The approach speed along the line of centres at first touch is that of the initial state
    // (free flight until contact).
    approach = -dot(Vec3{1.0, 0.0, 0.1} - Vec3{-0.3, 0.1, 0}, normal);
    const Vec3 p1 = linearMomentum(world), l1 = angularMomentum(world);
    CaseResult r;
    r.quantities.push_back(
        relativeQuantity("|P|", "kg m/s", length(p0), length(p1), 1e-12, "Newton's third law"));
    r.quantities.push_back(
        absoluteQuantity("|P - P0| / |P0|", "", 0, length(p1 - p0) / length(p0), 1e-12, "round-off"));
    r.quantities.push_back(absoluteQuantity("|L - L0| / |L0|", "", 0, length(l1 - l0) / length(l0), 1e-12,
                                            "lever arms sum to the centre distance"));
    r.notes.push_back("oblique impact: normal restitution along the rotating line of centres = " +
                      std::to_string(departure / approach));

    // Head-on collision of the same unequal spheres: relative-velocity restitution along the fixed
    // line of centres.
    World headOn = worldWith(glass, {0, 0, 0});
    headOn.particles.add({-0.02, 0, 0}, {1.0, 0, 0}, {}, r1, glass.density, 0);
    headOn.particles.add({0, 0, 0}, {-0.3, 0, 0}, {}, r2, glass.density, 0);
    runFor(headOn, 0.05, dt, context, "two_sphere_collision", nullptr);
    const Real restitution =
        -(headOn.particles.velocity[0].x - headOn.particles.velocity[1].x) / (1.0 - -0.3);
    r.quantities.push_back(
        relativeQuantity("head-on restitution", "", glass.restitution, restitution, 3e-3,
                         "BENCHMARKS 2.1 (first-order dashpot error < 0.15 % at >= 50 steps)"));
    if (!separated)
        r.notes.push_back("the spheres did not separate within 0.05 s");
    return r;
}
} // namespace

VERIDEM_CASE({.name = "two_sphere_collision",
              .summary = "oblique collision of unequal spinning spheres: momentum, angular momentum, e",
              .reference = "BENCHMARKS 3 test 4 and 5 #5",
              .labels = {"dem", "quick", "ranks"},
              .run = run});
VERIDEM_SWEEP(
    "two_sphere_collision",
    {.orders = {
         {"head-on restitution", 2.0,
          "the linear dashpot weighted at touch and separation: e is second order (docs/models.md)"}}});
} // namespace veridem::verify
