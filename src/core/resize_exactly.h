// Grow-only sizing of the arrays that are resized every few hundred steps (the contact lists).
#pragma once

#include <cstddef>

namespace veridem
{

/// v.resize(count), with the capacity grown to exactly count and never shrunk: re-allocating
/// arrays of changing sizes every few hundred steps fragmented the heap (peak RSS +80 B/particle
/// over 1000 bed steps), and push_back-style growth would over-allocate up to twice over.
template <class V> void resizeExactly(V& v, std::size_t count)
{
    if (v.capacity() < count)
        v.reserve(count);
    v.resize(count);
}

} // namespace veridem
