// Design note: one step of the 2D FEM/DEM solver, read top to bottom in World::step().
//
//  1. computeElementForces  CST internal forces (elements/cst.h), a pure function per triangle of its
//                           reference inverse and current nodes, scattered to the nodes, plus gravity
//                           (world_elements.cpp); then the joints of bodies that crack (world_fracture.cpp).
//  2. detectContacts        only when the Verlet-skin criterion says the candidate list may be stale
//                           (broadphase.h); history is carried by persistent keys (contact_list.h).
//  3. computeContactForces  per couple, both roles: potential contact (contact/potential.h) gives the
//                           elastic normal force of each contactor edge inside the target; the normal
//                           dashpot and the Coulomb law (contact/friction.h) act at the same point.
//  4. integrate             central difference: v_{n+1/2} = v_{n-1/2} + dt f_n / m,
//                           x_{n+1} = x_n + dt v_{n+1/2}.
//
// Contact stiffness and damping per edge contact (L_in: length of the contactor edge inside the
// target, H_t: smallest altitude of the target, rho_c: contactor density):
//   normal (flat-on-flat):  k_n = 3 p_n L_in / H_t   (phi = 3 d / H near an edge)
//   tangential:             k_t = 3 p_t L_in / H_t   (same form, so p_t = p_n gives k_t = k_n)
//   tangential dashpot:     eta_t = 2 zeta_t sqrt(1.5 p_t rho_c) L_in, the critical value for a node of
//                           mass rho h^2 / 2 on a spring 3 p h (square elements of size h), times zeta_t.
//   normal dashpot:         F_d = 2 zeta_n sqrt(m_eff k_n) d(delta)/dt on the mean penetration depth
//                           delta = F_e / k_n, m_eff the reduced mass of the edge's and the target's nodes.
//                           Not on the relative velocity along the edge normal: the leading face of a
//                           sliding block enters the next base element at constant depth while moving at
//                           v along its own normal; damping v braked the block (stop distance 0.4 % short
//                           at 6 m/s). Not on dF_e/dt either: a contact whose overlap grows or shrinks
//                           at constant depth was then damped, and the clipping at F >= 0 of the
//                           shrinking one left a net upward dashpot force that lowered the elastic
//                           normal force and the friction cap (over-travel growing with v: 6e-5 at 6 m/s).
//                           Even on d(delta)/dt the potential's kinks give the dashpot a non-zero mean
//                           while sliding (L short by 1e-5 per m/s), so friction benchmarks switch it off
//                           after settling (docs/fdem.md).
// The Coulomb cap uses the elastic normal force (paper eq. 2: "Fn is normal elastic force").
// Velocities are the half-step values v_{n-1/2}, the ones that carried the nodes to x_n, so the
// tangential spring increment v_t dt is at the positions' time level (BENCHMARKS 1a (b)).
#include "fdem/world.h"

#include "core/error.h"
#include "fdem/broadphase.h"
#include "fdem/contact/friction.h"
#include "fdem/contact/potential.h"
#include "fdem/elements/cst.h"

#include <algorithm>
#include <cmath>
#include <sstream>

namespace veridem::fdem
{

namespace
{

void checkContactParameters(const ContactParameters& c)
{
    if (!(c.normalPenalty > 0) || !std::isfinite(c.normalPenalty))
        throw InputError("contact normal penalty must be > 0 Pa (got " + std::to_string(c.normalPenalty) +
                         ")");
    if (!(c.friction >= 0) || !std::isfinite(c.friction))
        throw InputError("friction coefficient must be >= 0 (got " + std::to_string(c.friction) + ")");
    if (c.friction > 0 && (!(c.tangentialPenalty > 0) || !std::isfinite(c.tangentialPenalty)))
        throw InputError("contact tangential penalty must be > 0 Pa when friction > 0 (got " +
                         std::to_string(c.tangentialPenalty) + ")");
    if (!(c.normalDampingRatio >= 0) || !(c.tangentialDampingRatio >= 0) ||
        !std::isfinite(c.normalDampingRatio) || !std::isfinite(c.tangentialDampingRatio))
        throw InputError("contact damping ratios must be >= 0");
}

} // namespace

World::World(const WorldSettings& settings) : settings_(settings)
{
    if (!(settings.timeStep > 0) || !std::isfinite(settings.timeStep))
        throw InputError("time step must be > 0 s (got " + std::to_string(settings.timeStep) + ")");
    if (!isFinite(settings.gravity))
        throw InputError("gravity must be finite");
    checkContactParameters(settings.contact);
    if (!(settings.buffer >= 0) || !std::isfinite(settings.buffer))
        throw InputError("contact buffer must be >= 0 m (got " + std::to_string(settings.buffer) + ")");
}

void World::setContactParameters(const ContactParameters& contact)
{
    checkContactParameters(contact);
    settings_.contact = contact;
}

std::uint32_t World::addMaterial(const Material& m, const std::string& name)
{
    const auto bad = [&](const std::string& what) { throw InputError("material '" + name + "': " + what); };
    if (!(m.density > 0) || !std::isfinite(m.density))
        bad("density must be > 0 kg/m^3 (got " + std::to_string(m.density) + ")");
    if (!(m.youngsModulus > 0) || !std::isfinite(m.youngsModulus))
        bad("youngs_modulus must be > 0 Pa (got " + std::to_string(m.youngsModulus) + ")");
    if (!(m.poissonRatio >= 0 && m.poissonRatio < 0.5))
        bad("poisson_ratio must be in [0, 0.5) (got " + std::to_string(m.poissonRatio) + ")");
    if (!(m.viscosity >= 0) || !std::isfinite(m.viscosity))
        bad("viscosity must be >= 0 Pa s (got " + std::to_string(m.viscosity) + ")");
    materials_.push_back(m);
    constants_.push_back(elasticConstants(m));
    laws_.push_back(checkedCohesiveConstants(m.fracture, "material '" + name + "'"));
    return static_cast<std::uint32_t>(materials_.size() - 1);
}

std::uint32_t World::addBody(const BodyDefinition& body)
{
    if (body.material >= materials_.size())
        throw InputError("body '" + body.name + "': unknown material index " + std::to_string(body.material));
    TriangleMesh mesh = validatedMesh(body.mesh, "body '" + body.name + "'");
    const SplitMesh split = body.cracks ? splitForCracks(body, mesh) : SplitMesh{}; // world_fracture.cpp
    if (body.cracks)
        mesh = split.mesh;
    const auto id = static_cast<std::uint32_t>(bodyNames_.size());
    bodyNames_.push_back(body.name);
    bodyFixed_.push_back(body.fixed ? 1 : 0);
    bodyCracks_.push_back(body.cracks ? 1 : 0);
    const auto first = static_cast<std::uint32_t>(nodes_.size());
    const auto firstTriangle = static_cast<std::uint32_t>(triangles_.size());
    const Real rho = materials_[body.material].density;
    for (const Vec2& p : mesh.points)
    {
        nodes_.position.push_back(p);
        nodes_.referencePosition.push_back(p);
        nodes_.velocity.push_back(body.velocity);
        nodes_.force.push_back({});
        nodes_.mass.push_back(0);
        nodes_.inverseMass.push_back(0);
        nodes_.prescribed.push_back(body.fixed ? 1 : 0);
        nodes_.body.push_back(id);
    }
    for (const auto& t : mesh.triangles)
    {
        const std::array<std::uint32_t, 3> ids{first + t[0], first + t[1], first + t[2]};
        const std::array<Vec2, 3> x{mesh.points[t[0]], mesh.points[t[1]], mesh.points[t[2]]};
        const Real area = signedArea(x[0], x[1], x[2]);
        triangles_.nodes.push_back(ids);
        triangles_.referenceInverse.push_back(referenceInverse(x));
        triangles_.referenceArea.push_back(area);
        triangles_.material.push_back(body.material);
        triangles_.body.push_back(id);
        triangles_.stress.push_back({});
        triangleMinAltitude_.push_back(minimumAltitude(x[0], x[1], x[2]));
        for (auto n : ids)
            nodes_.mass[n] += rho * area / 3;
    }
    for (std::size_t n = first; n < nodes_.size(); ++n)
        nodes_.inverseMass[n] = nodes_.prescribed[n] ? 0 : 1 / nodes_.mass[n];
    if (nodes_.size() >= (1u << 31) || triangles_.size() >= (1u << 31))
        throw InputError("too many nodes or triangles");
    triangleJoints_.resize(triangles_.size(), {~0u, ~0u, ~0u});
    if (body.cracks)
        insertJoints(body, split, first, firstTriangle);
    contactsValid_ = false;
    listsValid_ = false;
    return id;
}

std::size_t World::prescribeNodes(std::uint32_t body, Vec2 lo, Vec2 hi, Vec2 velocity)
{
    std::size_t count = 0;
    for (std::size_t n = 0; n < nodes_.size(); ++n)
    {
        const Vec2& p = nodes_.position[n];
        if (nodes_.body[n] != body || p.x < lo.x || p.x > hi.x || p.y < lo.y || p.y > hi.y)
            continue;
        nodes_.prescribed[n] = 1;
        nodes_.inverseMass[n] = 0;
        nodes_.velocity[n] = velocity;
        ++count;
    }
    contactsValid_ = false;
    listsValid_ = false;
    return count;
}

void World::setBodyVelocity(std::uint32_t body, Vec2 velocity)
{
    for (std::size_t n = 0; n < nodes_.size(); ++n)
        if (nodes_.body[n] == body && !nodes_.prescribed[n])
            nodes_.velocity[n] = velocity;
    contactsValid_ = false;
    listsValid_ = false;
}

void World::refreshActiveLists()
{
    activeNodes_.clear();
    activeTriangles_.clear();
    for (std::size_t n = 0; n < nodes_.size(); ++n)
        if (!nodes_.prescribed[n] || lengthSquared(nodes_.velocity[n]) > 0)
            activeNodes_.push_back(static_cast<std::uint32_t>(n));
    for (std::size_t t = 0; t < triangles_.size(); ++t)
    {
        const auto& ids = triangles_.nodes[t];
        if (!nodes_.prescribed[ids[0]] || !nodes_.prescribed[ids[1]] || !nodes_.prescribed[ids[2]])
            activeTriangles_.push_back(static_cast<std::uint32_t>(t));
    }
    listsValid_ = true;
}

void World::setNodeVelocity(std::uint32_t node, Vec2 velocity)
{
    if (node < nodes_.size() && !nodes_.prescribed[node])
        nodes_.velocity[node] = velocity;
}

void World::step()
{
    if (!listsValid_)
        refreshActiveLists();
    computeElementForces();
    if (!joints_.nodes.empty())
        computeJointForces();
    if (needsDetection())
        detectContacts();
    computeContactForces();
    integrate();
    time_ += settings_.timeStep;
    ++steps_;
}

bool World::needsDetection() const
{
    if (!contactsValid_)
        return true;
    Real maxSquared = 0;
    for (std::size_t i = 0; i < activeNodes_.size(); ++i)
        maxSquared =
            std::max(maxSquared, lengthSquared(nodes_.position[activeNodes_[i]] - positionAtDetection_[i]));
    return 4 * maxSquared > buffer_ * buffer_; // 2 d_max > buffer
}

void World::detectContacts()
{
    if (buffer_ == 0)
    {
        buffer_ = settings_.buffer;
        if (buffer_ == 0)
        {
            Real hMin = INFINITY;
            for (Real h : triangleMinAltitude_)
                hMin = std::min(hMin, h);
            buffer_ = 0.5 * hMin;
        }
    }
    std::vector<BoundingBox> boxes(triangles_.size());
    for (std::size_t t = 0; t < triangles_.size(); ++t)
    {
        const auto& ids = triangles_.nodes[t];
        BoundingBox& box = boxes[t];
        // Triangles of a body that cracks are each their own group (self-contact); see jointedOrAdjacent.
        const std::uint32_t group =
            bodyCracks_[triangles_.body[t]] ? (1u << 31) | static_cast<std::uint32_t>(t) : triangles_.body[t];
        box = {nodes_.position[ids[0]], nodes_.position[ids[0]], group, false};
        for (auto n : ids)
        {
            const Vec2 x = nodes_.position[n];
            box.lo = {std::min(box.lo.x, x.x), std::min(box.lo.y, x.y)};
            box.hi = {std::max(box.hi.x, x.x), std::max(box.hi.y, x.y)};
            box.active = box.active || !nodes_.prescribed[n] || lengthSquared(nodes_.velocity[n]) > 0;
        }
    }
    auto pairs = findCandidatePairs(boxes, buffer_);
    removeTiedPairs(pairs);
    contacts_.rebuild(pairs);
    positionAtDetection_.clear();
    for (const auto n : activeNodes_)
        positionAtDetection_.push_back(nodes_.position[n]);
    contactsValid_ = true;
    ++detections_;
}

void World::computeContactForces()
{
    const ContactParameters& cp = settings_.contact;
    const Real dt = settings_.timeStep;
    diagnostics_ = {};
    for (Couple& couple : contacts_.couples())
    {
        const std::uint32_t tri[2] = {couple.first, couple.second};
        std::array<Vec2, 3> x[2];
        Vec2 lo[2], hi[2];
        for (int k = 0; k < 2; ++k)
        {
            const auto& ids = triangles_.nodes[tri[k]];
            for (int i = 0; i < 3; ++i)
                x[k][i] = nodes_.position[ids[i]];
            lo[k] = {std::min({x[k][0].x, x[k][1].x, x[k][2].x}),
                     std::min({x[k][0].y, x[k][1].y, x[k][2].y})};
            hi[k] = {std::max({x[k][0].x, x[k][1].x, x[k][2].x}),
                     std::max({x[k][0].y, x[k][1].y, x[k][2].y})};
        }
        if (lo[0].x > hi[1].x || lo[1].x > hi[0].x || lo[0].y > hi[1].y || lo[1].y > hi[0].y)
        {
            couple.spring.fill(0); // apart: every edge contact is open
            couple.depth.fill(0);
            continue;
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
                const Vec2 targetVelocity = pen.targetWeight[0] * v[t][0] + pen.targetWeight[1] * v[t][1] +
                                            pen.targetWeight[2] * v[t][2];
                const Vec2 relative = contactorVelocity - targetVelocity;
                const Real slip = dot(relative, tangent);
                const Real insideLength = edgeLength * pen.insideFraction;

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
                        normalDampingWork_ += (normalForce - elasticNormal) * penetrationRate * dt;
                    }
                }
                previousDepth = depth;
                Real tangentialForce = 0;
                if (cp.friction > 0)
                {
                    const Real stiffness = 3 * cp.tangentialPenalty * insideLength / targetAltitude;
                    const Real eta = 2 * cp.tangentialDampingRatio *
                                     std::sqrt(1.5 * cp.tangentialPenalty * rho) * insideLength;
                    const Real cap = cp.friction * elasticNormal;
                    const FrictionResult f = coulombFriction(spring, slip, dt, stiffness, eta, cap);
                    spring = f.spring;
                    tangentialForce = f.force;
                    frictionWork_ -= tangentialForce * slip * dt;
                    diagnostics_.tangentialForce += std::abs(tangentialForce);
                    diagnostics_.cap += cap;
                    diagnostics_.sliding += f.sliding ? 1 : 0;
                }
                diagnostics_.normalForce += elasticNormal;
                ++diagnostics_.contacts;

                const Vec2 force = tangentialForce * tangent - normalForce * normal; // on the contactor
                const Real w1 = pen.firstMoment / pen.integral;
                nodes_.force[contactorNodes[e]] += (1 - w1) * force;
                nodes_.force[contactorNodes[e1]] += w1 * force;
                for (int k = 0; k < 3; ++k)
                    nodes_.force[targetNodes[k]] -= pen.targetWeight[k] * force;
            }
        }
    }
}

void World::integrate()
{
    const Real dt = settings_.timeStep;
    for (const auto n : activeNodes_)
    {
        if (!nodes_.prescribed[n])
            nodes_.velocity[n] += (dt * nodes_.inverseMass[n]) * nodes_.force[n];
        nodes_.position[n] += dt * nodes_.velocity[n];
    }
    if (steps_ % 1024 == 0)
        for (const auto n : activeNodes_)
            if (!isFinite(nodes_.position[n]) || !isFinite(nodes_.velocity[n]))
            {
                std::ostringstream s;
                s << "step " << steps_ << " (t = " << time_ << " s): node " << n << " of body '"
                  << bodyNames_[nodes_.body[n]]
                  << "' has a non-finite position or velocity (time step above the "
                  << "stability limit?)";
                throw SimulationError(s.str());
            }
}

BodyState World::bodyState(std::uint32_t body) const
{
    BodyState s;
    for (std::size_t n = 0; n < nodes_.size(); ++n)
    {
        if (nodes_.body[n] != body)
            continue;
        s.mass += nodes_.mass[n];
        s.centroid += nodes_.mass[n] * nodes_.position[n];
        s.velocity += nodes_.mass[n] * nodes_.velocity[n];
    }
    if (s.mass > 0)
    {
        s.centroid = s.centroid / s.mass;
        s.velocity = s.velocity / s.mass;
    }
    return s;
}

Vec2 World::prescribedForce(std::uint32_t body) const
{
    Vec2 sum{};
    for (std::size_t n = 0; n < nodes_.size(); ++n)
        if (nodes_.body[n] == body && nodes_.prescribed[n])
            sum += nodes_.force[n];
    return sum;
}

Energies World::energies() const
{
    Energies e;
    for (std::size_t n = 0; n < nodes_.size(); ++n)
    {
        if (nodes_.prescribed[n])
            continue;
        e.kinetic += 0.5 * nodes_.mass[n] * lengthSquared(nodes_.velocity[n]);
        e.gravity -= nodes_.mass[n] * dot(settings_.gravity, nodes_.position[n]);
    }
    for (std::size_t t = 0; t < triangles_.size(); ++t)
    {
        const auto& ids = triangles_.nodes[t];
        const std::array<Vec2, 3> x{nodes_.position[ids[0]], nodes_.position[ids[1]],
                                    nodes_.position[ids[2]]};
        e.strain += cstStrainEnergy(x, triangles_.referenceInverse[t], triangles_.referenceArea[t],
                                    constants_[triangles_.material[t]]);
    }
    e.frictionWork = frictionWork_;
    e.normalDampingWork = normalDampingWork_;
    return e;
}

} // namespace veridem::fdem
