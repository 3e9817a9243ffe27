// The joint (crack) elements of World: insertion when a body that cracks is added, the joint force
// loop of each step, and the contact filter inside such bodies (fracture/joints.h).
//
// Inside a body that cracks every triangle pair may touch (self-contact, also between fragments),
// except two triangles that share a node (the continuum) or that an intact joint ties (the joint
// carries their tension, shear and compression). When a joint breaks the candidate list is rebuilt
// in the same step (the joints come before the detection), so its two free edges meet through the
// potential contact with friction from then on.
#include "core/error.h"
#include "exec/thread_pool.h"
#include "fdem/elements/cst.h"
#include "fdem/world.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <sstream>
#include <string>

namespace veridem::fdem
{

namespace
{

void checkCrackingBody(const BodyDefinition& body, const SplitMesh& split, const Material& m,
                       const CohesiveConstants& law)
{
    const std::string where = "body '" + body.name + "'";
    const FractureParameters& f = m.fracture;
    if (!(f.tensileStrength > 0))
        throw InputError(where + " cracks: its material's tensile_strength must be > 0 Pa (got " +
                         std::to_string(f.tensileStrength) + ")");
    if (!(f.fractureEnergy > 0))
        throw InputError(where + " cracks: its material's fracture_energy must be > 0 J/m^2 (got " +
                         std::to_string(f.fractureEnergy) + ")");
    if (!(f.cohesion > 0) || !(f.shearFractureEnergy > 0) || !(f.penalty > 0))
        throw InputError(where + " cracks: its material's cohesion, shear_fracture_energy and joint_penalty "
                                 "must be > 0");
    if (split.jointNodes.empty())
        throw InputError(where + (body.crackRegion ? ": the crack region selects no interior edge"
                                                   : ": the mesh has no interior edge to crack"));
    // Snap-back: the element beside each joint, of size h = its altitude onto the joint edge.
    Real hMax = 0;
    for (std::size_t j = 0; j < split.jointNodes.size(); ++j)
    {
        const auto& n = split.jointNodes[j];
        const Vec2 p = split.mesh.points[n[0]], q = split.mesh.points[n[1]];
        const Real edge = length(q - p);
        for (auto t : split.jointTriangles[j])
        {
            const auto& tri = split.mesh.triangles[t];
            const Real area =
                signedArea(split.mesh.points[tri[0]], split.mesh.points[tri[1]], split.mesh.points[tri[2]]);
            hMax = std::max(hMax, 2 * area / edge);
        }
    }
    const Real limit = snapBackSize(law, m.youngsModulus);
    if (hMax > limit)
    {
        std::ostringstream s;
        s << where << ": fracture_energy " << f.fractureEnergy
          << " J/m^2 is too small for its elements (size " << hMax
          << " m across a joint): the softening would snap back; use elements of at most " << limit
          << " m, or fracture_energy >= " << f.fractureEnergy * hMax / limit << " J/m^2";
        throw InputError(s.str());
    }
}

} // namespace

SplitMesh World::splitForCracks(const BodyDefinition& body, const TriangleMesh& mesh) const
{
    const auto inRegion = [&](Vec2 p, Vec2 q)
    {
        const Vec2 c = 0.5 * (p + q);
        return !body.crackRegion || (c.x >= body.crackMin.x && c.x <= body.crackMax.x &&
                                     c.y >= body.crackMin.y && c.y <= body.crackMax.y);
    };
    SplitMesh split = splitForJoints(mesh, inRegion);
    checkCrackingBody(body, split, materials_[body.material], laws_[body.material]);
    return split;
}

void World::insertJoints(const BodyDefinition& definition, const SplitMesh& split, std::uint32_t firstNode,
                         std::uint32_t firstTriangle)
{
    const Real nan = std::numeric_limits<Real>::quiet_NaN();
    for (std::size_t j = 0; j < split.jointNodes.size(); ++j)
    {
        const auto& n = split.jointNodes[j];
        const auto id = static_cast<std::uint32_t>(joints_.size());
        joints_.nodes.push_back({firstNode + n[0], firstNode + n[1], firstNode + n[2], firstNode + n[3]});
        const std::array<std::uint32_t, 2> tris{firstTriangle + split.jointTriangles[j][0],
                                                firstTriangle + split.jointTriangles[j][1]};
        joints_.triangles.push_back(tris);
        joints_.length.push_back(length(split.mesh.points[n[1]] - split.mesh.points[n[0]]));
        joints_.material.push_back(definition.material);
        joints_.damage.push_back({0, 0});
        joints_.opening.push_back({0, 0});
        joints_.slip.push_back({0, 0});
        joints_.normalTraction.push_back({0, 0});
        joints_.shearTraction.push_back({0, 0});
        joints_.work.push_back(0);
        joints_.brokenAt.push_back(nan);
        joints_.broken.push_back(0);
        for (auto t : tris)
            for (auto& slot : triangleJoints_[t])
                if (slot == ~0u)
                {
                    slot = id;
                    break;
                }
    }
}

void World::prescribeNode(std::uint32_t node, Vec2 velocity)
{
    if (node >= nodes_.size())
        throw InputError("prescribeNode: node " + std::to_string(node) + " out of range");
    nodes_.prescribed[node] = 1;
    nodes_.inverseMass[node] = 0;
    nodes_.velocity[node] = velocity;
    contactsValid_ = false;
    listsValid_ = false;
}

void World::computeJointForces()
{
    const auto broken = evaluateJoints(joints_, nodes_.position, laws_, time_); // summed in sumNodeForces
    for (auto j : broken)
    {
        ++brokenJoints_;
        energyReleased_ += joints_.work[j];
    }
    if (!broken.empty())
        contactsValid_ = false; // the two free edges join the candidate list in this step's detection
}

bool World::jointedOrAdjacent(std::uint32_t a, std::uint32_t b) const
{
    if (triangles_.body[a] != triangles_.body[b])
        return false;
    for (auto na : triangles_.nodes[a])
        for (auto nb : triangles_.nodes[b])
            if (na == nb)
                return true;
    for (auto j : triangleJoints_[a])
        if (j != ~0u && !joints_.broken[j] && (joints_.triangles[j][0] == b || joints_.triangles[j][1] == b))
            return true;
    return false;
}

void World::removeTiedPairs(std::vector<std::pair<std::uint32_t, std::uint32_t>>& pairs) const
{
    if (joints_.nodes.empty())
        return;
    // Tested on the thread pool (each pair its own flag), compacted serially in order.
    const std::size_t count = pairs.size();
    std::vector<std::uint8_t> tied(count);
    constexpr std::size_t kChunk = 8192;
    exec::run(static_cast<int>((count + kChunk - 1) / kChunk),
              [&](int c)
              {
                  const std::size_t end = std::min(count, (static_cast<std::size_t>(c) + 1) * kChunk);
                  for (std::size_t i = static_cast<std::size_t>(c) * kChunk; i < end; ++i)
                      tied[i] = jointedOrAdjacent(pairs[i].first, pairs[i].second) ? 1 : 0;
              });
    std::size_t kept = 0;
    for (std::size_t i = 0; i < count; ++i)
        if (!tied[i])
            pairs[kept++] = pairs[i];
    pairs.resize(kept);
}

FractureState World::fractureState() const
{
    FractureState s;
    s.joints = joints_.size();
    s.broken = brokenJoints_;
    s.energyReleased = energyReleased_;
    for (Real w : joints_.work)
        s.jointWork += w;
    return s;
}

} // namespace veridem::fdem
