// Design note: one step of the 2D FEM/DEM solver, read top to bottom in World::step().
//
//  1. computeElementForces  CST internal forces (elements/cst.h), a pure function per triangle of its
//                           reference inverse and current nodes (world_elements.cpp); then the joints
//                           of bodies that crack (world_fracture.cpp); then sumNodeForces adds gravity,
//                           element and joint forces per node in a fixed order.
//  2. detectContacts        only when the Verlet-skin criterion says the candidate list may be stale
//                           (broadphase.h); history is carried by persistent keys (contact_list.h).
//  3. computeContactForces  per couple, both roles (world_contacts.cpp): potential contact
//                           (contact/potential.h) gives the elastic normal force of each contactor
//                           edge inside the target; the normal dashpot and the Coulomb law
//                           (contact/friction.h) act at the same point.
//  4. integrate             central difference: v_{n+1/2} = v_{n-1/2} + dt f_n / m,
//                           x_{n+1} = x_n + dt v_{n+1/2}.
//
// Every loop runs on the thread pool (src/exec/) in chunks whose results are combined in a fixed
// order, so every value has the same bits on any thread count.
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
#include "exec/thread_pool.h"
#include "fdem/broadphase.h"
#include "fdem/contact/friction.h"
#include "fdem/contact/potential.h"
#include "fdem/elements/cst.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <sstream>

namespace veridem::fdem
{

namespace
{

constexpr std::size_t kNodeChunk = 4096; // nodes or triangles per chunk of the per-item loops

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
    nodeSlotsValid_ = false;
}

void World::setNodeVelocity(std::uint32_t node, Vec2 velocity)
{
    if (node < nodes_.size() && !nodes_.prescribed[node])
        nodes_.velocity[node] = velocity;
}

void World::step()
{
    using Clock = std::chrono::steady_clock;
    const auto since = [](Clock::time_point& start)
    {
        const auto now = Clock::now();
        const double elapsed = std::chrono::duration<double>(now - start).count();
        start = now;
        return elapsed;
    };
    if (!listsValid_)
        refreshActiveLists();
    if (!nodeSlotsValid_)
        buildNodeSlots(); // world_elements.cpp
    auto start = Clock::now();
    computeElementForces();
    stepTimes_.elements += since(start);
    if (!joints_.nodes.empty())
        computeJointForces();
    stepTimes_.joints += since(start);
    sumNodeForces();
    stepTimes_.nodeForces += since(start);
    if (needsDetection())
        detectContacts();
    stepTimes_.detection += since(start);
    computeContactForces(); // world_contacts.cpp
    stepTimes_.contacts += since(start);
    integrate();
    stepTimes_.integration += since(start);
    time_ += settings_.timeStep;
    ++steps_;
}

bool World::needsDetection() const
{
    if (!contactsValid_)
        return true;
    // The largest displacement since the detection, per chunk on the thread pool (a maximum is exact
    // in any order; a NaN displacement is skipped by std::max in any chunk as it was serially).
    const std::size_t count = activeNodes_.size();
    const int chunks = static_cast<int>((count + kNodeChunk - 1) / kNodeChunk);
    std::vector<Real> chunkMax(static_cast<std::size_t>(chunks), 0);
    exec::run(chunks,
              [&](int c)
              {
                  Real m = 0;
                  const std::size_t end = std::min(count, (static_cast<std::size_t>(c) + 1) * kNodeChunk);
                  for (std::size_t i = static_cast<std::size_t>(c) * kNodeChunk; i < end; ++i)
                      m = std::max(m,
                                   lengthSquared(nodes_.position[activeNodes_[i]] - positionAtDetection_[i]));
                  chunkMax[static_cast<std::size_t>(c)] = m;
              });
    Real maxSquared = 0;
    for (const Real m : chunkMax)
        maxSquared = std::max(maxSquared, m);
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
    const std::size_t count = triangles_.size();
    const int chunks = static_cast<int>((count + kNodeChunk - 1) / kNodeChunk);
    exec::run(chunks,
              [&](int c)
              {
                  const std::size_t end = std::min(count, (static_cast<std::size_t>(c) + 1) * kNodeChunk);
                  for (std::size_t t = static_cast<std::size_t>(c) * kNodeChunk; t < end; ++t)
                  {
                      const auto& ids = triangles_.nodes[t];
                      BoundingBox& box = boxes[t];
                      // Triangles of a body that cracks are each their own group (self-contact); see
                      // jointedOrAdjacent.
                      const std::uint32_t group = bodyCracks_[triangles_.body[t]]
                                                      ? (1u << 31) | static_cast<std::uint32_t>(t)
                                                      : triangles_.body[t];
                      box = {nodes_.position[ids[0]], nodes_.position[ids[0]], group, false};
                      for (auto n : ids)
                      {
                          const Vec2 x = nodes_.position[n];
                          box.lo = {std::min(box.lo.x, x.x), std::min(box.lo.y, x.y)};
                          box.hi = {std::max(box.hi.x, x.x), std::max(box.hi.y, x.y)};
                          box.active =
                              box.active || !nodes_.prescribed[n] || lengthSquared(nodes_.velocity[n]) > 0;
                      }
                  }
              });
    auto pairs = findCandidatePairs(boxes, buffer_);
    removeTiedPairs(pairs);
    contacts_.rebuild(pairs);
    positionAtDetection_.clear();
    for (const auto n : activeNodes_)
        positionAtDetection_.push_back(nodes_.position[n]);
    contactsValid_ = true;
    ++detections_;
}

void World::integrate()
{
    const Real dt = settings_.timeStep;
    const std::size_t count = activeNodes_.size();
    const int chunks = static_cast<int>((count + kNodeChunk - 1) / kNodeChunk);
    exec::run(chunks,
              [&](int c)
              {
                  const std::size_t end = std::min(count, (static_cast<std::size_t>(c) + 1) * kNodeChunk);
                  for (std::size_t i = static_cast<std::size_t>(c) * kNodeChunk; i < end; ++i)
                  {
                      const auto n = activeNodes_[i];
                      if (!nodes_.prescribed[n])
                          nodes_.velocity[n] += (dt * nodes_.inverseMass[n]) * nodes_.force[n];
                      nodes_.position[n] += dt * nodes_.velocity[n];
                  }
              });
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
