// Design note: friction history is stored per edge contact and keyed by persistent ids
// (contactor triangle, its edge, target triangle), never by a recycled slot index, so history can
// not leak from one contact to another (BENCHMARKS 1a item (a), 6.3). A couple lives from the
// detection that finds it to the first detection that no longer does; the solver zeroes an edge's
// spring in the step its overlap vanishes (the contact opened), so a couple that survives a gap
// starts again from zero. Rebuilds are a linear merge of two sorted lists (double buffer), in chunks
// of the new list on the thread pool, each chunk starting from a binary search in the old one (each
// couple depends only on its key: the same result on any thread count).
#include "fdem/contact_list.h"

#include "exec/thread_pool.h"

#include <algorithm>

namespace veridem::fdem
{

void ContactList::rebuild(const std::vector<std::pair<std::uint32_t, std::uint32_t>>& candidates)
{
    std::swap(previous_, couples_);
    const std::size_t count = candidates.size();
    couples_.resize(count);
    const auto before = [](const Couple& c, std::uint32_t a, std::uint32_t b)
    { return c.first < a || (c.first == a && c.second < b); };
    constexpr std::size_t kChunk = 8192;
    exec::run(static_cast<int>((count + kChunk - 1) / kChunk),
              [&](int chunk)
              {
                  const std::size_t begin = static_cast<std::size_t>(chunk) * kChunk;
                  const std::size_t end = std::min(count, begin + kChunk);
                  std::size_t old = static_cast<std::size_t>(
                      std::lower_bound(previous_.begin(), previous_.end(), candidates[begin],
                                       [&](const Couple& c, const auto& key)
                                       { return before(c, key.first, key.second); }) -
                      previous_.begin());
                  for (std::size_t i = begin; i < end; ++i)
                  {
                      const auto [a, b] = candidates[i];
                      while (old < previous_.size() && before(previous_[old], a, b))
                          ++old;
                      Couple c{a, b, {}, {}};
                      if (old < previous_.size() && previous_[old].first == a && previous_[old].second == b)
                      {
                          c.spring = previous_[old].spring;
                          c.depth = previous_[old].depth;
                      }
                      couples_[i] = c;
                  }
              });
}

} // namespace veridem::fdem
