// Loop helpers for the force and integration loops (OpenMP when built with VERIDEM_OPENMP).
//
// Determinism (STYLE 3.4). Every loop run through these helpers writes only to its own index (or
// its own chunk), and reductions combine per-chunk results in chunk order, so that results are
// bit-identical for any thread count. Small loops (a single ball on a turntable) run serially
// without entering a parallel region: a region costs about a microsecond, ten steps of one ball.
#pragma once

#include <algorithm>
#include <cstddef>

#ifdef _OPENMP
#include <omp.h>
#endif

namespace veridem::dem
{

/// Below this many items a loop runs on the calling thread only.
inline constexpr std::size_t kParallelThreshold = 2048;

/// Number of threads a loop of `count` items will use.
inline int loopThreads(std::size_t count)
{
#ifdef _OPENMP
    return count >= kParallelThreshold ? omp_get_max_threads() : 1;
#else
    (void)count;
    return 1;
#endif
}

/// Splits [0, count) into `chunks` contiguous ranges in order; chunk c is [begin, end).
inline std::size_t chunkBegin(std::size_t count, int chunks, int c)
{
    return count * static_cast<std::size_t>(c) / static_cast<std::size_t>(chunks);
}

/// body(chunk, begin, end) for `chunks` contiguous ranges of [0, count), one per thread. The
/// caller combines per-chunk results in chunk order.
template <class Body> inline void parallelChunks(std::size_t count, int chunks, Body&& body)
{
#ifdef _OPENMP
    if (chunks > 1)
    {
#pragma omp parallel for schedule(static, 1) num_threads(chunks)
        for (int c = 0; c < chunks; ++c)
            body(c, chunkBegin(count, chunks, c), chunkBegin(count, chunks, c + 1));
        return;
    }
#endif
    for (int c = 0; c < chunks; ++c)
        body(c, chunkBegin(count, chunks, c), chunkBegin(count, chunks, c + 1));
}

} // namespace veridem::dem
