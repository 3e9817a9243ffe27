// Candidate triangle pairs ("couples") and their friction history.
#pragma once

#include "fdem/vec2.h"

#include <array>
#include <cstdint>
#include <utility>
#include <vector>

namespace veridem::fdem
{

/// A candidate pair of triangles (first < second, persistent triangle ids) and the tangential
/// springs of its 6 edge contacts: spring[3 * role + edge], role 0 = edges of `first` inside
/// `second`, role 1 = edges of `second` inside `first` [m]. `depth` holds the mean penetration depth
/// of each edge contact in the previous step (0: not touching) [m], for the normal dashpot.
struct Couple
{
    std::uint32_t first = 0;
    std::uint32_t second = 0;
    std::array<Real, 6> spring{};
    std::array<Real, 6> depth{};
};
static_assert(sizeof(Couple) == 104);

class ContactList
{
  public:
    /// Replaces the couples by `candidates` (sorted, unique), carrying each surviving couple's
    /// history (springs, previous depths) over by key (first, second); new couples start with zero
    /// springs.
    void rebuild(const std::vector<std::pair<std::uint32_t, std::uint32_t>>& candidates);

    std::vector<Couple>& couples() { return couples_; }
    const std::vector<Couple>& couples() const { return couples_; }

  private:
    std::vector<Couple> couples_;  // sorted by (first, second)
    std::vector<Couple> previous_; // reused buffer
};

} // namespace veridem::fdem
