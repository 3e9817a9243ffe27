#include "fdem/fracture/joints.h"

#include "core/error.h"
#include "exec/thread_pool.h"
#include "fdem/union_find.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>
#include <numeric>
#include <utility>

namespace veridem::fdem
{

SplitMesh splitForJoints(const TriangleMesh& mesh, const std::function<bool(Vec2, Vec2)>& selected)
{
    // Edges by their sorted end points: (triangle, local edge e from corner e to corner e + 1).
    std::map<std::pair<std::uint32_t, std::uint32_t>, std::vector<std::pair<std::uint32_t, int>>> edges;
    for (std::uint32_t t = 0; t < mesh.triangles.size(); ++t)
        for (int e = 0; e < 3; ++e)
        {
            const std::uint32_t p = mesh.triangles[t][e], q = mesh.triangles[t][(e + 1) % 3];
            edges[{std::min(p, q), std::max(p, q)}].push_back({t, e});
        }
    // Union of triangle corners (3 t + corner) across the interior edges that are not split.
    std::vector<std::uint32_t> parent(3 * mesh.triangles.size());
    std::iota(parent.begin(), parent.end(), 0u);
    const auto corner = [&](std::uint32_t t, std::uint32_t node)
    {
        const auto& tri = mesh.triangles[t];
        const int k = tri[0] == node ? 0 : tri[1] == node ? 1 : 2;
        return 3 * t + static_cast<std::uint32_t>(k);
    };
    // Corners of the same node in triangles that share no interior edge (a fan around a node) are
    // united through the chain of edges between them; a boundary node with two fans separated by
    // the boundary cannot occur in a valid (manifold) mesh region.
    std::vector<std::pair<std::uint32_t, int>> jointEdges;
    std::vector<std::uint32_t> jointOther;
    for (const auto& [key, list] : edges)
    {
        if (list.size() != 2)
            continue;
        const auto [a, ea] = list[0];
        const auto [b, eb] = list[1];
        const std::uint32_t p = mesh.triangles[a][ea], q = mesh.triangles[a][(ea + 1) % 3];
        if (selected(mesh.points[p], mesh.points[q]))
        {
            jointEdges.push_back({a, ea});
            jointOther.push_back(b);
            continue;
        }
        unionJoin(parent, corner(a, p), corner(b, p));
        unionJoin(parent, corner(a, q), corner(b, q));
    }
    SplitMesh out;
    std::vector<std::uint32_t> newId(parent.size(), std::numeric_limits<std::uint32_t>::max());
    out.mesh.triangles.resize(mesh.triangles.size());
    for (std::uint32_t c = 0; c < parent.size(); ++c)
    {
        const std::uint32_t root = unionRoot(parent, c);
        if (newId[root] == std::numeric_limits<std::uint32_t>::max())
        {
            newId[root] = static_cast<std::uint32_t>(out.mesh.points.size());
            out.mesh.points.push_back(mesh.points[mesh.triangles[c / 3][c % 3]]);
        }
        out.mesh.triangles[c / 3][c % 3] = newId[root];
    }
    for (std::size_t j = 0; j < jointEdges.size(); ++j)
    {
        const auto [a, ea] = jointEdges[j];
        const std::uint32_t b = jointOther[j];
        const std::uint32_t p = mesh.triangles[a][ea], q = mesh.triangles[a][(ea + 1) % 3];
        out.jointNodes.push_back(
            {newId[unionRoot(parent, corner(a, p))], newId[unionRoot(parent, corner(a, q))],
             newId[unionRoot(parent, corner(b, p))], newId[unionRoot(parent, corner(b, q))]});
        out.jointTriangles.push_back({a, b});
    }
    return out;
}

namespace
{

/// Updates joint j's state from the positions and returns its end forces on a0 and a1 [N/m] (the
/// b nodes get the opposite); sets its broken flag when an end reaches D = 1. Touches joint j only.
std::array<Vec2, 2> evaluateJoint(JointStore& joints, std::uint32_t j, const std::vector<Vec2>& position,
                                  const std::vector<CohesiveConstants>& laws, Real time)
{
    const auto& id = joints.nodes[j];
    const Vec2 xa0 = position[id[0]], xa1 = position[id[1]], xb0 = position[id[2]], xb1 = position[id[3]];
    const Vec2 axis = 0.5 * (xa1 + xb1 - xa0 - xb0);
    const Vec2 t = axis / length(axis);
    const Vec2 n{t.y, -t.x};
    const CohesiveConstants& law = laws[joints.material[j]];
    const Real h = joints.length[j];
    bool broken = false;
    Real work = 0;
    std::array<Vec2, 2> f{};
    for (int k = 0; k < 2; ++k)
    {
        const Vec2 jump = k == 0 ? xb0 - xa0 : xb1 - xa1;
        const Real o = dot(jump, n), s = dot(jump, t);
        const CohesiveResult r = cohesiveTraction(o, s, h, joints.damage[j][k], law);
        work += 0.5 * h * 0.5 *
                ((r.normal + joints.normalTraction[j][k]) * (o - joints.opening[j][k]) +
                 (r.tangential + joints.shearTraction[j][k]) * (s - joints.slip[j][k]));
        joints.damage[j][k] = r.damage;
        joints.opening[j][k] = o;
        joints.slip[j][k] = s;
        joints.normalTraction[j][k] = r.normal;
        joints.shearTraction[j][k] = r.tangential;
        f[k] = 0.5 * h * (r.normal * n + r.tangential * t);
        broken = broken || r.damage >= 1;
    }
    joints.work[j] += work;
    if (broken)
    {
        joints.broken[j] = 1;
        joints.brokenAt[j] = time;
    }
    return f;
}

} // namespace

std::vector<std::uint32_t> evaluateJoints(JointStore& joints, const std::vector<Vec2>& position,
                                          const std::vector<CohesiveConstants>& laws, Real time)
{
    // On the thread pool: each joint's state and end forces (no joint touches another's data). The
    // caller scatters the forces in a fixed order (World::sumNodeForces), so the bits are the same on
    // any thread count.
    const std::size_t count = joints.size();
    joints.endForce.resize(count);
    joints.event.assign(count, 0);
    constexpr std::size_t kChunk = 1024;
    const int chunks = static_cast<int>((count + kChunk - 1) / kChunk);
    exec::run(chunks,
              [&](int c)
              {
                  const std::size_t end = std::min(count, (static_cast<std::size_t>(c) + 1) * kChunk);
                  for (std::size_t j = static_cast<std::size_t>(c) * kChunk; j < end; ++j)
                  {
                      if (joints.broken[j])
                          continue;
                      joints.endForce[j] =
                          evaluateJoint(joints, static_cast<std::uint32_t>(j), position, laws, time);
                      joints.event[j] = joints.broken[j] ? 2 : 1; // 2: broke in this step
                  }
              });
    std::vector<std::uint32_t> newlyBroken; // a broken joint carries nothing (its last tractions are ~0)
    for (std::uint32_t j = 0; j < count; ++j)
        if (joints.event[j] == 2)
            newlyBroken.push_back(j);
    return newlyBroken;
}

CohesiveConstants checkedCohesiveConstants(const FractureParameters& f, const std::string& where)
{
    if (!std::isfinite(f.tensileStrength) || !std::isfinite(f.fractureEnergy) || !std::isfinite(f.cohesion) ||
        !std::isfinite(f.shearFractureEnergy) || !std::isfinite(f.penalty) || !(f.frictionAngle >= 0) ||
        !(f.frictionAngle < 1.5707963267948966))
        throw InputError(where +
                         ": fracture parameters must be finite and internal_friction_degrees in [0, 90)");
    const bool complete = f.tensileStrength > 0 && f.fractureEnergy > 0 && f.cohesion > 0 &&
                          f.shearFractureEnergy > 0 && f.penalty > 0;
    return complete ? cohesiveConstants(f) : CohesiveConstants{};
}

Real snapBackSize(const CohesiveConstants& law, Real youngsModulus)
{
    const FractureParameters& p = law.p;
    return youngsModulus * p.fractureEnergy /
           (p.tensileStrength * p.tensileStrength * law.area * softeningMaxSlope(p.curve));
}

} // namespace veridem::fdem
