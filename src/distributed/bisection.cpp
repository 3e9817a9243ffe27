#include "distributed/bisection.h"

#include "core/error.h"

#include <algorithm>
#include <cmath>
#include <string>

namespace veridem::distributed
{

Real distanceSquared(const Box& box, const Vec3& x)
{
    Real d2 = 0;
    for (int a = 0; a < 3; ++a)
    {
        const Real c = component(x, a);
        const Real below = component(box.lo, a) - c, above = c - component(box.hi, a);
        const Real d = std::max({below, above, Real(0)});
        d2 += d * d;
    }
    return d2;
}

int Decomposition::owner(const Vec3& x) const
{
    if (nodes.empty())
        return 0;
    int child = 0;
    while (child >= 0)
    {
        const Node& n = nodes[child];
        child = component(x, n.axis) < n.cut ? n.below : n.above;
    }
    return -(child + 1);
}

namespace
{

constexpr Real kInfinity = std::numeric_limits<Real>::infinity();

/// A box of the level being cut: its tree slot (the parent's child index to fill), its bounds,
/// parts and weight, and the bisection of its cut.
struct Task
{
    int parent = -1;      // node whose child this box is (-1: the root)
    bool isBelow = false; // which child of it
    Box bounds;
    int parts = 1;
    std::uint64_t weight = 0;
    Box region;
    // the bisection (parts > 1)
    int axis = 0;
    std::uint64_t target = 0; // weight wanted below the cut
    Real lo = 0, hi = 0;      // weight below lo <= target < weight below hi
    std::uint64_t belowLo = 0, belowHi = 0;
    Real tolerance = 0;
    bool done = false;
};

int longestAxis(const Box& b, std::array<bool, 3> cuttable)
{
    int axis = -1;
    for (int a = 0; a < 3; ++a)
        if (cuttable[static_cast<std::size_t>(a)] &&
            (axis < 0 ||
             component(b.hi, a) - component(b.lo, a) > component(b.hi, axis) - component(b.lo, axis)))
            axis = a;
    return axis;
}

/// Renumbers the parts (made level by level) in depth-first order, below before above, so that
/// a depth-first walk meets them ascending and neighbouring parts in the tree have near numbers.
void numberPartsDepthFirst(Decomposition& d)
{
    if (d.nodes.empty())
        return;
    std::vector<int> newNumber(d.region.size(), -1);
    int next = 0;
    int stack[64];
    int top = 0;
    stack[top++] = 0;
    while (top > 0)
    {
        const int child = stack[--top];
        if (child < 0)
        {
            newNumber[-(child + 1)] = next++;
            continue;
        }
        stack[top++] = d.nodes[child].above;
        stack[top++] = d.nodes[child].below;
    }
    std::vector<Box> region(d.region.size());
    std::vector<std::uint64_t> cost(d.cost.size());
    for (std::size_t p = 0; p < d.region.size(); ++p)
    {
        region[newNumber[p]] = d.region[p];
        cost[newNumber[p]] = d.cost[p];
    }
    d.region = std::move(region);
    d.cost = std::move(cost);
    for (Decomposition::Node& n : d.nodes)
    {
        if (n.below < 0)
            n.below = -(newNumber[-(n.below + 1)] + 1);
        if (n.above < 0)
            n.above = -(newNumber[-(n.above + 1)] + 1);
    }
}

} // namespace

std::array<bool, 3> cuttableAxes(const dem::PeriodicDomain& domain)
{
    const std::array<bool, 3>& periodic = domain.periodic;
    if (periodic[0] && periodic[1] && periodic[2])
        return {true, true, true};
    return {!periodic[0], !periodic[1], !periodic[2]};
}

Decomposition bisect(std::span<const Vec3> position, std::span<const std::uint32_t> weight, int parts,
                     const Collective& comm, const dem::PeriodicDomain& domain)
{
    const std::array<bool, 3> cuttable = cuttableAxes(domain);
    if (parts < 1)
        throw InputError("the domain decomposition needs at least one part, got " + std::to_string(parts));
    if (weight.size() != position.size())
        throw InputError("the domain decomposition needs one weight per particle");
    Decomposition out;
    out.domain = domain;

    // The bounds (maxima of x and of -x) and the total weight: exact on any rank count.
    double extremes[6] = {-kInfinity, -kInfinity, -kInfinity, -kInfinity, -kInfinity, -kInfinity};
    std::uint64_t total = 0;
    for (std::size_t i = 0; i < position.size(); ++i)
    {
        for (int a = 0; a < 3; ++a)
        {
            extremes[a] = std::max(extremes[a], component(position[i], a));
            extremes[3 + a] = std::max(extremes[3 + a], -component(position[i], a));
        }
        total += weight[i];
    }
    comm.max(extremes);
    comm.sum(std::span<std::uint64_t>(&total, 1));
    for (int a = 0; a < 3; ++a)
        if (!(extremes[a] >= -extremes[3 + a])) // no particle anywhere: an empty box at the origin
            extremes[a] = extremes[3 + a] = 0;
    out.bounds = {{-extremes[3], -extremes[4], -extremes[5]}, {extremes[0], extremes[1], extremes[2]}};

    std::vector<Task> level{
        Task{-1, false, out.bounds, parts, total,
             Box{{-kInfinity, -kInfinity, -kInfinity}, {kInfinity, kInfinity, kInfinity}}}};
    // This rank's particles: their box in `level`, or kInPart once their box is a part.
    constexpr int kInPart = -1;
    std::vector<int> taskOf(position.size(), 0);
    out.region.resize(parts);
    out.cost.resize(parts);
    int nextPart = 0;
    while (!level.empty())
    {
        // Boxes of one part become parts (in tree order: the level is in tree order).
        for (Task& t : level)
        {
            t.done = t.parts == 1;
            if (t.done)
                continue;
            t.axis = longestAxis(t.bounds, cuttable);
            const int partsBelow = t.parts / 2;
            const std::uint64_t q = t.weight / t.parts, rem = t.weight % t.parts;
            t.target = q * partsBelow + rem * partsBelow / t.parts; // floor(weight * below / parts)
            t.lo = component(t.bounds.lo, t.axis);
            t.hi = std::nextafter(component(t.bounds.hi, t.axis), kInfinity);
            t.belowLo = 0; // nothing lies below the bounds
            t.belowHi = t.weight;
            t.tolerance = std::ldexp(t.hi - t.lo, -40);
            t.done = t.weight == 0; // nothing to balance: cut in the middle
            if (t.done)
                t.lo = t.hi = 0.5 * (t.lo + t.hi);
        }
        // Bisection of every box's cut together: one global sum per step.
        std::vector<Real> trial(level.size());
        std::vector<std::uint64_t> below(level.size());
        for (;;)
        {
            bool any = false;
            for (std::size_t k = 0; k < level.size(); ++k)
            {
                Task& t = level[k];
                if (!t.done && (t.hi - t.lo <= t.tolerance || t.lo + 0.5 * (t.hi - t.lo) <= t.lo ||
                                t.lo + 0.5 * (t.hi - t.lo) >= t.hi))
                    t.done = true;
                trial[k] = t.lo + 0.5 * (t.hi - t.lo);
                any = any || !t.done;
            }
            if (!any) // (the same on every rank: each decision is on the same global values)
                break;
            std::fill(below.begin(), below.end(), 0);
            for (std::size_t i = 0; i < position.size(); ++i)
            {
                if (taskOf[i] < 0)
                    continue;
                const Task& t = level[taskOf[i]];
                if (!t.done && component(position[i], t.axis) < trial[taskOf[i]])
                    below[taskOf[i]] += weight[i];
            }
            comm.sum(below);
            for (std::size_t k = 0; k < level.size(); ++k)
            {
                Task& t = level[k];
                if (t.done)
                    continue;
                if (below[k] <= t.target)
                {
                    t.lo = trial[k];
                    t.belowLo = below[k];
                }
                else
                {
                    t.hi = trial[k];
                    t.belowHi = below[k];
                }
            }
        }
        // The cuts: the next level's boxes, and this rank's particles moved into them.
        std::vector<Task> next;
        std::vector<int> childOf(level.size() * 2, -1), nodeOf(level.size(), -1);
        for (std::size_t k = 0; k < level.size(); ++k)
        {
            const Task& t = level[k];
            int self;
            if (t.parts == 1)
            {
                self = -(nextPart + 1);
                out.region[nextPart] = t.region;
                out.cost[nextPart] = t.weight;
                ++nextPart;
            }
            else
            {
                const bool takeLo = t.weight == 0 || t.target - t.belowLo <= t.belowHi - t.target;
                const Real cut = takeLo ? t.lo : t.hi;
                const std::uint64_t weightBelow = takeLo ? t.belowLo : t.belowHi;
                self = nodeOf[k] = static_cast<int>(out.nodes.size());
                out.nodes.push_back({t.axis, cut, -1, -1});
                Task b{self, true, t.bounds, t.parts / 2, weightBelow, t.region};
                Task a{self, false, t.bounds, t.parts - t.parts / 2, t.weight - weightBelow, t.region};
                component(b.bounds.hi, t.axis) = std::min(cut, component(t.bounds.hi, t.axis));
                component(b.region.hi, t.axis) = cut;
                component(a.bounds.lo, t.axis) = std::max(cut, component(t.bounds.lo, t.axis));
                component(a.region.lo, t.axis) = cut;
                childOf[2 * k] = static_cast<int>(next.size());
                next.push_back(b);
                childOf[2 * k + 1] = static_cast<int>(next.size());
                next.push_back(a);
            }
            if (t.parent >= 0)
                (t.isBelow ? out.nodes[t.parent].below : out.nodes[t.parent].above) = self;
        }
        for (std::size_t i = 0; i < position.size(); ++i)
        {
            const int k = taskOf[i];
            if (k < 0)
                continue;
            if (nodeOf[k] < 0)
            {
                taskOf[i] = kInPart; // its box became a part: not in the next level
                continue;
            }
            const Decomposition::Node& n = out.nodes[nodeOf[k]];
            taskOf[i] = childOf[2 * k + (component(position[i], n.axis) < n.cut ? 0 : 1)];
        }
        level = std::move(next);
    }
    numberPartsDepthFirst(out);
    return out;
}

} // namespace veridem::distributed
