// The contact loop of World::step(): potential contact with the normal dashpot and Coulomb friction
// per couple (the formulas and their reasons are in world.cpp's design note).
//
// The same bits on any thread count: the couples are evaluated on the thread pool in chunks of
// consecutive couples; a couple updates only its own history (springs, depths), and each touching
// edge contact leaves a record (its five nodal forces, dissipated works and diagnostics) in its
// chunk's list. The records are then applied serially, chunk after chunk: the same additions in the
// same order as the serial loop this replaced. Only touching edge contacts leave a record, so the
// serial part is proportional to the contacts that carry force, not to the couples tested.
#include "exec/thread_pool.h"
#include "fdem/contact/friction.h"
#include "fdem/contact/potential.h"
#include "fdem/world.h"

#include <algorithm>
#include <cmath>

namespace veridem::fdem
{

void World::computeContactForces()
{
    std::vector<Couple>& couples = contacts_.couples();
    const std::size_t count = couples.size();
    constexpr std::size_t kChunk = 2048;
    const std::size_t chunks = (count + kChunk - 1) / kChunk;
    if (contactRecords_.size() < chunks)
        contactRecords_.resize(chunks);
    exec::run(static_cast<int>(chunks),
              [&](int c)
              {
                  std::vector<EdgeContactRecord>& records = contactRecords_[static_cast<std::size_t>(c)];
                  records.clear();
                  const std::size_t end = std::min(count, (static_cast<std::size_t>(c) + 1) * kChunk);
                  for (std::size_t i = static_cast<std::size_t>(c) * kChunk; i < end; ++i)
                      evaluateCouple(couples[i], records);
              });
    diagnostics_ = {};
    for (std::size_t c = 0; c < chunks; ++c)
        for (const EdgeContactRecord& r : contactRecords_[c])
        {
            if (r.damped)
                normalDampingWork_ += r.dampingWork;
            if (r.friction)
            {
                frictionWork_ -= r.frictionWork;
                diagnostics_.tangentialForce += r.tangential;
                diagnostics_.cap += r.cap;
                diagnostics_.sliding += r.sliding;
            }
            diagnostics_.normalForce += r.normal;
            ++diagnostics_.contacts;
            nodes_.force[r.node[0]] += r.force[0];
            nodes_.force[r.node[1]] += r.force[1];
            for (int k = 2; k < 5; ++k)
                nodes_.force[r.node[k]] -= r.force[k];
        }
}

void World::evaluateCouple(Couple& couple, std::vector<EdgeContactRecord>& records) const
{
    const ContactParameters& cp = settings_.contact;
    const Real dt = settings_.timeStep;
    const std::uint32_t tri[2] = {couple.first, couple.second};
    std::array<Vec2, 3> x[2];
    Vec2 lo[2], hi[2];
    for (int k = 0; k < 2; ++k)
    {
        const auto& ids = triangles_.nodes[tri[k]];
        for (int i = 0; i < 3; ++i)
            x[k][i] = nodes_.position[ids[i]];
        lo[k] = {std::min({x[k][0].x, x[k][1].x, x[k][2].x}), std::min({x[k][0].y, x[k][1].y, x[k][2].y})};
        hi[k] = {std::max({x[k][0].x, x[k][1].x, x[k][2].x}), std::max({x[k][0].y, x[k][1].y, x[k][2].y})};
    }
    if (lo[0].x > hi[1].x || lo[1].x > hi[0].x || lo[0].y > hi[1].y || lo[1].y > hi[0].y)
    {
        couple.spring.fill(0); // apart: every edge contact is open
        couple.depth.fill(0);
        return;
    }
    std::array<Vec2, 3> v[2];
    for (int k = 0; k < 2; ++k)
        for (int i = 0; i < 3; ++i)
            v[k][i] = nodes_.velocity[triangles_.nodes[tri[k]][i]];
    for (int role = 0; role < 2; ++role)
    {
        const int c = role, t = 1 - role;
        const Real rho = materials_[triangles_.material[tri[c]]].density;
        const Real targetAltitude = triangleMinAltitude_[tri[t]];
        const auto& contactorNodes = triangles_.nodes[tri[c]];
        const auto& targetNodes = triangles_.nodes[tri[t]];
        // Barycentric coordinates of the contactor's nodes in the target, shared by its edges. If
        // all three lie outside one target edge (lambda_k < 0), no contactor edge can enter.
        const std::array<std::array<Real, 3>, 3> lambda{
            barycentric(x[c][0], x[t]), barycentric(x[c][1], x[t]), barycentric(x[c][2], x[t])};
        bool separated = false;
        for (int k = 0; k < 3; ++k)
            separated = separated || (lambda[0][k] < 0 && lambda[1][k] < 0 && lambda[2][k] < 0);
        if (separated)
        {
            for (int e = 0; e < 3; ++e)
                couple.spring[3 * role + e] = couple.depth[3 * role + e] = 0;
            continue;
        }
        for (int e = 0; e < 3; ++e)
        {
            Real& spring = couple.spring[3 * role + e];
            Real& previousDepth = couple.depth[3 * role + e];
            const int e1 = (e + 1) % 3;
            const EdgePenetration pen = edgeInTriangle(lambda[e], lambda[e1]);
            if (!pen.touching())
            {
                spring = 0;
                previousDepth = 0;
                continue;
            }
            const Vec2 edge = x[c][e1] - x[c][e];
            const Real edgeLength = length(edge);
            const Vec2 tangent = edge / edgeLength;
            const Vec2 normal{tangent.y, -tangent.x}; // outward for counter-clockwise triangles
            const Real s = pen.centre();
            const Vec2 contactorVelocity = (1 - s) * v[c][e] + s * v[c][e1];
            const Vec2 targetVelocity =
                pen.targetWeight[0] * v[t][0] + pen.targetWeight[1] * v[t][1] + pen.targetWeight[2] * v[t][2];
            const Vec2 relative = contactorVelocity - targetVelocity;
            const Real slip = dot(relative, tangent);
            const Real insideLength = edgeLength * pen.insideFraction;

            EdgeContactRecord record{};
            const Real elasticNormal = cp.normalPenalty * edgeLength * pen.integral;
            // Normal dashpot on the rate of the mean penetration depth delta = F_e / k_n (the depth a
            // flat contact of stiffness k_n would need): an edge that slides at constant depth while
            // its overlap grows or shrinks (entering or leaving a base element) is not damped.
            const Real normalStiffness = 3 * cp.normalPenalty * insideLength / targetAltitude;
            const Real depth = elasticNormal / normalStiffness;
            Real normalForce = elasticNormal;
            if (cp.normalDampingRatio > 0 && previousDepth > 0)
            {
                const Real contactorMass =
                    0.5 * (nodes_.mass[contactorNodes[e]] + nodes_.mass[contactorNodes[e1]]);
                Real targetMass = 0;
                for (int k = 0; k < 3; ++k)
                    targetMass += pen.targetWeight[k] * nodes_.mass[targetNodes[k]];
                const bool contactorFree =
                    !nodes_.prescribed[contactorNodes[e]] || !nodes_.prescribed[contactorNodes[e1]];
                const bool targetFree = !nodes_.prescribed[targetNodes[0]] ||
                                        !nodes_.prescribed[targetNodes[1]] ||
                                        !nodes_.prescribed[targetNodes[2]];
                const Real inverseMass =
                    (contactorFree ? 1 / contactorMass : 0) + (targetFree ? 1 / targetMass : 0);
                if (inverseMass > 0)
                {
                    const Real penetrationRate = (depth - previousDepth) / dt; // [m/s]
                    const Real eta = 2 * cp.normalDampingRatio * std::sqrt(normalStiffness / inverseMass);
                    normalForce = std::max(Real(0), elasticNormal + eta * penetrationRate);
                    record.dampingWork = (normalForce - elasticNormal) * penetrationRate * dt;
                    record.damped = 1;
                }
            }
            previousDepth = depth;
            Real tangentialForce = 0;
            if (cp.friction > 0)
            {
                const Real stiffness = 3 * cp.tangentialPenalty * insideLength / targetAltitude;
                const Real eta = 2 * cp.tangentialDampingRatio * std::sqrt(1.5 * cp.tangentialPenalty * rho) *
                                 insideLength;
                const Real cap = cp.friction * elasticNormal;
                const FrictionResult f = coulombFriction(spring, slip, dt, stiffness, eta, cap);
                spring = f.spring;
                tangentialForce = f.force;
                record.frictionWork = tangentialForce * slip * dt;
                record.tangential = std::abs(tangentialForce);
                record.cap = cap;
                record.friction = 1;
                record.sliding = f.sliding ? 1 : 0;
            }
            record.normal = elasticNormal;

            const Vec2 force = tangentialForce * tangent - normalForce * normal; // on the contactor
            const Real w1 = pen.firstMoment / pen.integral;
            record.node = {contactorNodes[e], contactorNodes[e1], targetNodes[0], targetNodes[1],
                           targetNodes[2]};
            record.force[0] = (1 - w1) * force;
            record.force[1] = w1 * force;
            for (int k = 0; k < 3; ++k)
                record.force[2 + k] = pen.targetWeight[k] * force;
            records.push_back(record);
        }
    }
}

} // namespace veridem::fdem
