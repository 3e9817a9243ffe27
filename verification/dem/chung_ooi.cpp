#include "chung_ooi.h"

#include "core/error.h"

#include <algorithm>
#include <cmath>

namespace veridem::verify::chung_ooi
{

Material hertzMaterial(const Solid& s, Real restitution, Real friction)
{
    Material m;
    m.name = s.name;
    m.density = s.density;
    m.normalModel = dem::NormalModel::Hertz;
    m.youngsModulus = s.youngsModulus;
    m.poissonRatio = s.poissonRatio;
    m.restitution = restitution;
    m.friction = friction;
    m.rollingModel = dem::RollingModel::None;
    return m;
}

Real effectiveModulus(const Solid& s, bool rigidPartner)
{
    const Real single = s.youngsModulus / (1 - s.poissonRatio * s.poissonRatio);
    return rigidPartner ? single : single / 2;
}

Real effectiveShearModulus(const Solid& s, bool rigidPartner)
{
    const Real single = s.youngsModulus / (2 * (1 + s.poissonRatio)) / (2 - s.poissonRatio);
    return rigidPartner ? single : single / 2;
}

HertzImpact hertzImpact(Real effectiveMass, Real effectiveRadius, Real effectiveModulus, Real speed)
{
    HertzImpact h;
    h.maxOverlap = std::pow(
        15 * effectiveMass * speed * speed / (16 * effectiveModulus * std::sqrt(effectiveRadius)), 0.4);
    h.maxForce = 4.0 / 3.0 * effectiveModulus * std::sqrt(effectiveRadius) * std::pow(h.maxOverlap, 1.5);
    h.contactTime = 2.868 * std::pow(effectiveMass * effectiveMass /
                                         (effectiveRadius * effectiveModulus * effectiveModulus * speed),
                                     0.2);
    return h;
}

namespace
{
// The rigid plane of the wall tests: the ball's material with E and G scaled by 1e9, so that the
// pair's E* and G* equal the rigid-plane values E/(1 - nu^2), G/(2 - nu) to 1e-9.
constexpr Real kRigidScale = 1e9;

// Steps until the contact has opened again after having closed (gap(world) <= 0, then > 0).
Outcome runUntilSeparated(World& world, Real dt, Real friction, const std::function<Real(const World&)>& gap,
                          const std::function<Vec3(const World&)>& normal, bool keepHistory)
{
    Outcome o;
    o.dt = dt;
    dem::prepare(world);
    Real previousGap = gap(world), previousT = world.time, tIn = -1, impulse = 0, stickingImpulse = 0;
    const std::uint64_t limit = 200000;
    for (std::uint64_t s = 0; s < limit; ++s)
    {
        dem::step(world, dt);
        if (!world.health.finite)
            throw SimulationError("chung_ooi impact: state is not finite");
        const Real g = gap(world);
        if (tIn < 0 && g <= 0)
            tIn = crossingTime(previousT, previousGap, world.time, g);
        if (g <= 0)
        {
            const Vec3 n = normal(world);
            const Vec3 f = world.particles.force[0];
            const Real fn = dot(f, n);
            const Real ft = length(f - fn * n);
            o.maxOverlap = std::fmax(o.maxOverlap, -g);
            o.maxNormalForce = std::fmax(o.maxNormalForce, fn);
            // Sliding: the tangential force sits on the Coulomb cap (to rounding).
            impulse += std::fmax(fn, 0.0);
            o.normalImpulse += fn * dt;
            if (ft < friction * std::fmax(fn, 0.0) * (1 - 1e-9))
                stickingImpulse += std::fmax(fn, 0.0);
            if (keepHistory)
                o.history.push_back({world.time, -g, fn});
        }
        if (tIn >= 0 && g > 0)
        {
            o.contactTime = crossingTime(previousT, previousGap, world.time, g) - tIn;
            o.stickingImpulseFraction = impulse > 0 ? stickingImpulse / impulse : 0;
            o.compressiveImpulse = impulse * dt;
            o.slidThroughout = o.stickingImpulseFraction <= 1e-3;
            const auto& p = world.particles;
            o.velocity = p.velocity[0];
            o.angularVelocity = p.angularVelocity[0];
            if (p.size() > 1)
            {
                o.partnerVelocity = p.velocity[1];
                o.partnerAngularVelocity = p.angularVelocity[1];
            }
            return o;
        }
        previousGap = g;
        previousT = world.time;
    }
    throw SimulationError("chung_ooi impact: no separation within 200000 steps");
}
} // namespace

Outcome wallImpact(const Solid& ball, Real restitution, Real friction, Real radius, Vec3 v0, Vec3 w0,
                   Real stepsPerContact, const CaseContext& context, bool keepHistory, Real startSteps)
{
    World world = worldWith(hertzMaterial(ball, restitution, friction), {0, 0, 0});
    Solid rigid = ball;
    rigid.name = "rigid_" + ball.name;
    rigid.youngsModulus *= kRigidScale;
    world.addMaterial(hertzMaterial(rigid, restitution, friction));
    dem::Wall wall = floorWall();
    wall.material = 1;
    world.walls.push_back(wall);
    const Real mass = sphereMass(ball.density, radius);
    const Real vn = std::fabs(v0.z);
    const Real tc = hertzImpact(mass, radius, effectiveModulus(ball, true), vn).contactTime;
    const Real dt = tc / stepsPerContact * context.dtScale; // (a dt sweep: sweep.h)
    world.particles.add({0, 0, radius + startSteps * vn * dt}, v0, w0, radius, ball.density, 0);
    return runUntilSeparated(
        world, dt, friction, [radius](const World& w) { return w.particles.position[0].z - radius; },
        [](const World&) {
            return Vec3{0, 0, 1};
        },
        keepHistory);
}

Outcome sphereImpact(const Solid& solid, Real restitution, Real friction, Real r1, Vec3 v1, Vec3 w1, Real r2,
                     Vec3 v2, Vec3 w2, Real densityFactor2, Real stepsPerContact, const CaseContext& context,
                     bool keepHistory)
{
    World world = worldWith(hertzMaterial(solid, restitution, friction), {0, 0, 0});
    Solid heavy = solid;
    heavy.name = solid.name + "_target";
    heavy.density *= densityFactor2;
    world.addMaterial(hertzMaterial(heavy, restitution, friction));
    const Real m1 = sphereMass(solid.density, r1), m2 = sphereMass(heavy.density, r2);
    const Real mStar = m1 * m2 / (m1 + m2), rStar = r1 * r2 / (r1 + r2);
    const Real vn = std::fabs(v1.z - v2.z);
    const Real dt = hertzImpact(mStar, rStar, effectiveModulus(solid, false), vn).contactTime /
                    stepsPerContact * context.dtScale;
    const Real gap0 = 2.5 * vn * dt;
    // Split the initial gap so that the centre of mass stays at the origin for equal spheres.
    world.particles.add({0, 0, r1 + 0.5 * gap0}, v1, w1, r1, solid.density, 0);
    world.particles.add({0, 0, -r2 - 0.5 * gap0}, v2, w2, r2, heavy.density, 1);
    const Real contact = r1 + r2;
    return runUntilSeparated(
        world, dt, friction,
        [contact](const World& w)
        { return length(w.particles.position[0] - w.particles.position[1]) - contact; },
        [](const World& w)
        {
            const Vec3 d = w.particles.position[0] - w.particles.position[1];
            return d / length(d);
        },
        keepHistory);
}

Real noSlipReversal(Real shearToNormalModulus)
{
    // State (delta, delta', xi, xi') in units where m = 1, (4/3) E* sqrt(R*) = 1 and the impact
    // speed is 1; first touch at delta = 0, delta' = 1, xi = 0, xi' = 1 (V_t = 1).
    const Real c = 21 * shearToNormalModulus;
    using State = std::array<Real, 4>;
    auto rate = [c](const State& s)
    {
        const Real d = std::fmax(s[0], 0.0);
        return State{s[1], -d * std::sqrt(d), s[3], -c * std::sqrt(d) * s[2]};
    };
    State s{0, 1, 0, 1};
    const Real h = 1e-5;
    for (int k = 0; k < 10000000; ++k)
    {
        const State k1 = rate(s);
        State t;
        for (int i = 0; i < 4; ++i)
            t[i] = s[i] + 0.5 * h * k1[i];
        const State k2 = rate(t);
        for (int i = 0; i < 4; ++i)
            t[i] = s[i] + 0.5 * h * k2[i];
        const State k3 = rate(t);
        for (int i = 0; i < 4; ++i)
            t[i] = s[i] + h * k3[i];
        const State k4 = rate(t);
        State next;
        for (int i = 0; i < 4; ++i)
            next[i] = s[i] + h / 6 * (k1[i] + 2 * k2[i] + 2 * k3[i] + k4[i]);
        if (next[0] < 0 && k > 10)
        {
            // Interpolate xi' to delta = 0 within the last step.
            const Real f = s[0] / (s[0] - next[0]);
            return s[3] + f * (next[3] - s[3]);
        }
        s = next;
    }
    throw SimulationError("noSlipReversal: the reference contact did not end");
}

Real worstRelative(const std::vector<Real>& measured, const std::vector<Real>& expected,
                   const std::vector<std::size_t>& indices)
{
    Real worst = 0;
    for (const std::size_t i : indices)
        worst = std::fmax(worst, std::fabs(measured[i] - expected[i]) / std::fabs(expected[i]));
    return worst;
}

} // namespace veridem::verify::chung_ooi
