// Disjoint sets over the indices 0..n-1 (union-find with path halving), for the pieces of a mesh:
// the corners of split edges (fracture/joints.cpp) and the fragments of cracked bodies
// (fragments.cpp). `parent` starts as 0, 1, ..., n-1 (std::iota).
#pragma once

#include <algorithm>
#include <cstdint>
#include <vector>

namespace veridem::fdem
{

/// The representative of a's set (its lowest index: see unionJoin).
inline std::uint32_t unionRoot(std::vector<std::uint32_t>& parent, std::uint32_t a)
{
    while (parent[a] != a)
    {
        parent[a] = parent[parent[a]]; // path halving
        a = parent[a];
    }
    return a;
}

/// Joins the sets of a and b; the lower root becomes the root, so the result does not depend on
/// the order of the joins.
inline void unionJoin(std::vector<std::uint32_t>& parent, std::uint32_t a, std::uint32_t b)
{
    a = unionRoot(parent, a);
    b = unionRoot(parent, b);
    if (a != b)
        parent[std::max(a, b)] = std::min(a, b);
}

} // namespace veridem::fdem
