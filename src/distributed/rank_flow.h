// Particles in and out of a run on several MPI ranks (dem/particle_flow.h's outlets and inserters),
// at the same steps as in one process:
//   - outlets: each rank retires the particles it owns whose centre an outlet holds (they leave
//     its store at the next exchange of particles) and counts them into its own totals;
//     outletTotals sums the ranks' totals for the output and the checkpoint (counts exactly,
//     masses in rank order);
//   - inserters: rank 0 alone draws the new particles, from its inserters' generators, against
//     the particles near the insertion regions gathered from every rank (gatherParticlesIn) and
//     the walls, exactly as one process would test them; the new rows go to every rank, and each
//     takes the ones its region holds with an exchange of particles and a rebuild of the lists
//     (RankStep::admit). So the particles inserted are the same bits as in one process when the
//     particles near the regions are (the same seed and draws), and an insertion event costs a
//     rebuild here, where one process appends without one.
#pragma once

#include "dem/particle_flow.h"
#include "dem/world.h"
#include "distributed/rank_step.h"

#include <vector>

namespace veridem::distributed
{

/// ParticleFlow::apply on several ranks (file comment). Returns true if particles changed on some
/// rank. Collective.
bool applyFlow(dem::ParticleFlow& flow, dem::World& world, RankStep& ranks, Real dt);

/// Totals every rank holds alike (read from one checkpoint, or a case's whole world) made ready to
/// be summed over the ranks again: the first rank keeps the outlets' counts and masses, the others
/// start from zero. Not collective.
void countOnFirstRank(std::vector<dem::Outlet>& outlets, const Collective& comm);

/// The outlets with their counts and masses summed over the ranks (masses added in rank order), on
/// rank 0, or on every rank with `everyRank`; elsewhere this rank's own. Collective.
std::vector<dem::Outlet> outletTotals(const std::vector<dem::Outlet>& outlets, const Collective& comm,
                                      bool everyRank = false);

} // namespace veridem::distributed
