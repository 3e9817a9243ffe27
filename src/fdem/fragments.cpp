#include "fdem/fragments.h"

#include "core/constants.h"
#include "fdem/union_find.h"

#include <algorithm>
#include <cmath>
#include <numeric>

namespace veridem::fdem
{

std::vector<Fragment> findFragments(const World& world)
{
    const TriangleStore& tris = world.triangles();
    const NodeStore& nodes = world.nodes();
    const auto count = static_cast<std::uint32_t>(tris.size());
    std::vector<std::uint32_t> parent(count);
    std::iota(parent.begin(), parent.end(), 0u);
    // Triangles sharing a node: join each triangle to the first triangle seen at each of its nodes.
    std::vector<std::uint32_t> firstAtNode(nodes.size(), ~0u);
    for (std::uint32_t t = 0; t < count; ++t)
        for (auto n : tris.nodes[t])
        {
            if (firstAtNode[n] == ~0u)
                firstAtNode[n] = t;
            else
                unionJoin(parent, firstAtNode[n], t);
        }
    const JointStore& joints = world.joints();
    for (std::size_t j = 0; j < joints.size(); ++j)
        if (!joints.broken[j])
            unionJoin(parent, joints.triangles[j][0], joints.triangles[j][1]);
    // One fragment per root, numbered in order of the roots (their lowest triangle id).
    std::vector<std::uint32_t> index(count, ~0u);
    std::vector<Fragment> fragments;
    for (std::uint32_t t = 0; t < count; ++t)
    {
        const auto r = unionRoot(parent, t);
        if (index[r] == ~0u)
        {
            index[r] = static_cast<std::uint32_t>(fragments.size());
            fragments.push_back({});
            fragments.back().body = tris.body[t];
        }
        Fragment& f = fragments[index[r]];
        ++f.triangles;
        f.area += tris.referenceArea[t];
        const Real rho = world.materials()[tris.material[t]].density;
        const Real m = rho * tris.referenceArea[t];
        Vec2 c{};
        for (auto n : tris.nodes[t])
            c += nodes.position[n] / 3;
        f.mass += m;
        f.centroid += m * c;
    }
    for (Fragment& f : fragments)
    {
        f.centroid = f.centroid / f.mass;
        f.equivalentDiameter = std::sqrt(4 * f.area / kPi);
    }
    // Bodies are added in order and their triangles are contiguous, so the fragments are already
    // ordered by body, then by lowest triangle id.
    return fragments;
}

} // namespace veridem::fdem
