// Freed heap memory handed back to the system after a contact-list rebuild.
#pragma once

#if defined(__GLIBC__)
#include <malloc.h>
#endif

#include <cstddef>

namespace veridem
{

/// Gives the pages of freed heap memory back to the system (glibc: malloc_trim(0), which returns
/// the free top of every arena and madvises away the whole free pages inside them). glibc keeps
/// what a program frees for its next allocations, in each thread's arena separately, so the
/// temporaries of the list rebuilds (the pair search's grids and chunks, the old lists) stay in
/// the resident set for the whole run, at their largest. Called after every rebuild of the
/// contact lists (world.cpp), which happens every few tens to hundreds of steps. Measured on the
/// meshed drum of bench/run_reference.sh (20k spheres, 20,000 steps): peak RSS without the mesh
/// 1066 -> 836 B/particle above the empty process on 2 threads, 958 -> 793 on 1, with the same
/// bits (trimming at every 4th rebuild only: 931 B on 2 threads). The cost is the page faults of
/// re-touching the trimmed pages at the next rebuild: the 20k gas, which rebuilds every ~50 steps,
/// takes 2.6 % more CPU time (three alternated pairs); the drum < 0.5 % (perf). Does nothing on
/// other C libraries.
/// The fewest particles for which a rebuild of the contact lists hands its freed memory back
/// (world.cpp): below, the rebuild's temporaries are under ~1 MB (a few hundred bytes a particle),
/// while each trim walks the whole heap; a one-ball verification case that rebuilt often spent
/// most of its time in malloc_trim, contending with the cases beside it for the arena locks.
inline constexpr std::size_t kTrimAfterRebuildParticles = 4096;

inline void releaseFreeMemory()
{
#if defined(__GLIBC__)
    malloc_trim(0);
#endif
}

} // namespace veridem
