// Design note: friction history is stored per edge contact and keyed by persistent ids
// (contactor triangle, its edge, target triangle), never by a recycled slot index, so history can
// not leak from one contact to another (BENCHMARKS 1a item (a), 6.3). A couple lives from the
// detection that finds it to the first detection that no longer does; the solver zeroes an edge's
// spring in the step its overlap vanishes (the contact opened), so a couple that survives a gap
// starts again from zero. Rebuilds are a linear merge of two sorted lists (double buffer).
#include "fdem/contact_list.h"

namespace veridem::fdem
{

void ContactList::rebuild(const std::vector<std::pair<std::uint32_t, std::uint32_t>>& candidates)
{
    std::swap(previous_, couples_);
    couples_.clear();
    couples_.reserve(candidates.size());
    std::size_t old = 0;
    for (const auto& [a, b] : candidates)
    {
        while (old < previous_.size() &&
               (previous_[old].first < a || (previous_[old].first == a && previous_[old].second < b)))
            ++old;
        Couple c{a, b, {}, {}};
        if (old < previous_.size() && previous_[old].first == a && previous_[old].second == b)
        {
            c.spring = previous_[old].spring;
            c.depth = previous_[old].depth;
        }
        couples_.push_back(c);
    }
}

} // namespace veridem::fdem
