// Grow-only sizing of the arrays that are resized every few hundred steps (the contact lists).
#pragma once

#include <cstddef>

namespace veridem
{

/// v.resize(count) without ever shrinking the capacity; when it must grow, it grows to count plus
/// an eighth. Re-allocating arrays of changing sizes every few hundred steps fragments the heap:
/// each slightly larger array leaves a hole the next one does not fit. Growing to the exact size
/// did that at every small rise of the contact count (the meshed drum of bench/run_reference.sh:
/// peak RSS 1145 B/particle above the empty process after 8000 steps); an eighth of headroom makes
/// the growths rare (992 B/particle), while push_back-style doubling would over-allocate up to
/// twice over.
template <class V> void resizeGrowOnly(V& v, std::size_t count)
{
    if (v.capacity() < count)
        v.reserve(count + count / 8);
    v.resize(count);
}

} // namespace veridem
