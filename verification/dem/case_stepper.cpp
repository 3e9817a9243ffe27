#include "case_stepper.h"

#include "dem/particle_changes.h"
#include "distributed/rank_flow.h"
#include "distributed/rank_gather.h"
#include "distributed/rank_step.h"

#include <utility>

namespace veridem::verify
{

CaseStepper::CaseStepper(dem::World& world, const CaseContext& context, dem::ParticleFlow* flow)
    : world_(world), flow_(flow)
{
    if (!context.ranks || context.ranks->size() == 1)
    {
        if (!world.prepared)
            dem::prepare(world);
        return;
    }
    ranks_ = std::make_unique<distributed::RankStep>(*context.ranks);
    ranks_->distribute(world);
    if (flow_) // (every rank holds the same totals: finish)
        distributed::countOnFirstRank(flow_->outlets, *context.ranks);
}

CaseStepper::~CaseStepper() = default;

std::uint64_t CaseStepper::advance(Real dt, std::uint64_t steps, Real maxOverlapFraction)
{
    return dem::advance(world_, dt, steps, maxOverlapFraction);
}

void CaseStepper::applyFlow(Real dt)
{
    if (!flow_ || flow_->empty())
        return;
    if (ranks_)
        distributed::applyFlow(*flow_, world_, *ranks_, dt);
    else
        flow_->apply(world_, dt);
}

void CaseStepper::sample(const std::function<void(const dem::World&)>& sample)
{
    if (!ranks_)
    {
        dem::compactRetiredParticles(world_); // (a sampler reads the particles by slot)
        sample(world_);
        return;
    }
    std::vector<dem::Outlet> own;
    if (flow_)
        own = std::exchange(flow_->outlets, distributed::outletTotals(flow_->outlets, ranks_->comm(), true));
    const dem::World whole = *distributed::gatherWorld(world_, *ranks_, distributed::kEveryRank);
    sample(whole);
    if (flow_)
        flow_->outlets = std::move(own);
}

std::uint32_t CaseStepper::failedParticleId() const
{
    if (ranks_)
        return ranks_->failedParticleId(world_);
    const dem::StepHealth& h = world_.health;
    const std::uint32_t i = h.finite ? h.worstParticle : h.firstNonFinite;
    return i < world_.particles.size() ? world_.particles.id[i] : i;
}

void CaseStepper::finish()
{
    if (!ranks_)
    {
        dem::compactRetiredParticles(world_);
        return;
    }
    if (flow_)
        flow_->outlets = distributed::outletTotals(flow_->outlets, ranks_->comm(), true);
    dem::World whole = *distributed::gatherWorld(world_, *ranks_, distributed::kEveryRank);
    whole.exec = world_.exec;
    whole.observer = world_.observer;
    world_ = std::move(whole);
    ranks_.reset();
}

} // namespace veridem::verify
