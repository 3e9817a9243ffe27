#include "distributed/exchange_plan.h"

#include "core/error.h"

#include <string>

namespace veridem::distributed
{

ExchangePlan planExchange(const Decomposition& d, int me, std::span<const Vec3> position,
                          std::span<const Real> radius, Real halo)
{
    if (me < 0 || me >= d.parts())
        throw InputError("exchange plan: rank " + std::to_string(me) + " is not one of the decomposition's " +
                         std::to_string(d.parts()) + " parts");
    if (radius.size() != position.size())
        throw InputError("exchange plan: one radius per particle is needed");
    if (!(halo > 0))
        throw InputError("exchange plan: the halo must be positive, got " + std::to_string(halo) + " m");
    ExchangePlan plan;
    plan.migrate.resize(d.parts());
    plan.ghost.resize(d.parts());
    for (std::size_t i = 0; i < position.size(); ++i)
    {
        const auto index = static_cast<std::uint32_t>(i);
        const int owner = d.owner(position[i]);
        if (owner != me)
        {
            plan.migrate[owner].push_back(index);
            continue; // (its new owner sends its ghosts)
        }
        d.forEachPartNear(position[i], radius[i] + halo,
                          [&](int part)
                          {
                              if (part != me)
                                  plan.ghost[part].push_back(index);
                          });
    }
    return plan;
}

} // namespace veridem::distributed
