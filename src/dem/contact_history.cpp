#include "dem/contact_history.h"

#include "core/grow_only.h"

#include <algorithm>

namespace veridem::dem
{

void ContactHistoryStore::carry(const std::uint32_t* source, std::size_t count)
{
    const std::size_t oldCount = spring.size();
    if (keepRolling && rolling.size() < oldCount) // (no rolling history was kept: zeros)
        rolling.assign(oldCount, Vec3{});
    if (keepFormed && formed.size() < oldCount)
        formed.assign(oldCount, 0);
    if (scalarCount > 0 && scalars.size() < oldCount * scalarCount)
        scalars.assign(oldCount * scalarCount, 0.0);
    const std::size_t room = std::max(count, oldCount);
    resizeGrowOnly(spring, room);
    if (keepRolling)
        resizeGrowOnly(rolling, room);
    else
        rolling.clear();
    if (keepFormed)
        resizeGrowOnly(formed, room);
    else
        formed.clear();
    if (scalarCount > 0)
        resizeGrowOnly(scalars, room * scalarCount);
    else
        scalars.clear();
    const auto move = [&](std::size_t to, std::size_t from)
    {
        spring[to] = spring[from];
        if (keepRolling)
            rolling[to] = rolling[from];
        if (keepFormed)
            formed[to] = formed[from];
        for (unsigned s = 0; s < scalarCount; ++s)
            scalars[to * scalarCount + s] = scalars[from * scalarCount + s];
    };
    // In place: a contact whose source lies after it is moved in ascending order, one whose source
    // lies before it in descending order; neither move overwrites a source still to be read.
    for (std::size_t a = 0; a < count; ++a)
        if (source[a] != kNoSource && source[a] > a)
            move(a, source[a]);
    for (std::size_t a = count; a-- > 0;)
        if (source[a] != kNoSource && source[a] < a)
            move(a, source[a]);
    for (std::size_t a = 0; a < count; ++a)
        if (source[a] == kNoSource)
        {
            spring[a] = Vec3{};
            if (keepRolling)
                rolling[a] = Vec3{};
            if (keepFormed)
                formed[a] = 0;
            for (unsigned s = 0; s < scalarCount; ++s)
                scalars[a * scalarCount + s] = 0;
        }
    spring.resize(count);
    if (keepRolling)
        rolling.resize(count);
    if (keepFormed)
        formed.resize(count);
    scalars.resize(count * scalarCount);
}

void ContactHistoryStore::clear()
{
    spring.clear();
    rolling.clear();
    formed.clear();
    scalars.clear();
}

std::size_t ContactHistoryStore::memoryBytes() const
{
    return spring.capacity() * sizeof(Vec3) + rolling.capacity() * sizeof(Vec3) + formed.capacity() +
           scalars.capacity() * sizeof(Real);
}

} // namespace veridem::dem
