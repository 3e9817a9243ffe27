// The stepping of a case's world, in one process or, under `mpirun -np N veridem verify`, over
// the MPI ranks (CaseContext::ranks): the same case code either way. On several ranks each rank
// keeps its region's particles and their ghosts (distributed::RankStep::distribute) while the world
// steps, the scene's particle flow runs as in `veridem run` on ranks (distributed::applyFlow), a sampler
// reads the whole world gathered on every rank (so every rank computes the same observables and
// takes the same branches), and finish() leaves the whole world on every rank, which is what the
// case reads after a run of steps. The cases whose stepping all goes through this (runFor,
// runScene) carry the label "ranks".
//
// The whole world a sampler reads is distributed::gatherWorld's: particles by id, history, lists and
// wall loads as one process holds them, and each outlet's totals over the ranks. A sample costs a
// gather of O(N) on every rank: the cases' worlds are small (<= ~3e4 spheres).
#pragma once

#include "case.h"
#include "dem/particle_flow.h"
#include "dem/world.h"

#include <cstdint>
#include <functional>
#include <limits>
#include <memory>

namespace veridem::distributed
{
class RankStep;
}

namespace veridem::verify
{

class CaseStepper
{
  public:
    /// Starts stepping `world`: prepared here if it is not; on several ranks, each keeps its part
    /// (collective). `flow` (may be null): the scene's inserters and outlets.
    CaseStepper(dem::World& world, const CaseContext& context, dem::ParticleFlow* flow = nullptr);
    ~CaseStepper();
    CaseStepper(const CaseStepper&) = delete;
    CaseStepper& operator=(const CaseStepper&) = delete;

    /// dem::advance: up to `steps` steps of dt [s], stopping after one whose health is bad (on
    /// several ranks, the health of all ranks). Returns the steps done.
    std::uint64_t advance(Real dt, std::uint64_t steps,
                          Real maxOverlapFraction = std::numeric_limits<Real>::infinity());
    /// The flow's inserters and outlets at this step (ParticleFlow::apply, or distributed::applyFlow).
    void applyFlow(Real dt);
    /// Calls sample(whole world): this one (retired particles compacted away first) or, on
    /// several ranks, the world gathered on every rank with the outlets' totals of all ranks.
    void sample(const std::function<void(const dem::World&)>& sample);
    /// The particle a bad health names, by its id (collective on several ranks).
    std::uint32_t failedParticleId() const;
    /// Ends the run: the world is the whole world (on every rank), without retired particles, and
    /// the flow's outlets hold the totals of all ranks. Collective on several ranks.
    void finish();

  private:
    dem::World& world_;
    dem::ParticleFlow* flow_;
    std::unique_ptr<distributed::RankStep> ranks_; // null in one process
};

} // namespace veridem::verify
