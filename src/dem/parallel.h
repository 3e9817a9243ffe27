// Loop helpers for the force and integration loops, on the thread pool of exec/thread_pool.h.
//
// Determinism (STYLE 3.4). Every loop run through these helpers writes only to its own index (or
// its own chunk), and reductions combine per-chunk results in chunk order, so that results are
// bit-identical for any thread count. Small loops (a single ball on a turntable) run serially
// without touching the pool: a fork-join costs about a microsecond, ten steps of one ball.
#pragma once

#include "exec/thread_pool.h"

#include <algorithm>
#include <cstddef>

namespace veridem::dem
{

/// Below this many items a loop runs on the calling thread only.
inline constexpr std::size_t kParallelThreshold = 2048;

/// Number of threads a loop of `count` items will use (exec::threads() from kParallelThreshold).
inline int loopThreads(std::size_t count)
{
    return count >= kParallelThreshold ? exec::threads() : 1;
}

/// Splits [0, count) into `chunks` contiguous ranges in order; chunk c is [begin, end).
inline std::size_t chunkBegin(std::size_t count, int chunks, int c)
{
    return count * static_cast<std::size_t>(c) / static_cast<std::size_t>(chunks);
}

/// body(chunk, begin, end) for `chunks` contiguous ranges of [0, count), chunk c on thread c of
/// the pool (exec::run). The caller combines per-chunk results in chunk order.
template <class Body> inline void parallelChunks(std::size_t count, int chunks, Body&& body)
{
    exec::run(chunks,
              [&](int c) { body(c, chunkBegin(count, chunks, c), chunkBegin(count, chunks, c + 1)); });
}

} // namespace veridem::dem
