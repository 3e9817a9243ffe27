#include "dem/neighbor_list.h"

#include "core/grow_only.h"
#include "dem/pair_search.h"

#include <algorithm>

namespace veridem::dem
{

bool NeighborList::needsRebuild(const ParticleStore& particles) const
{
    if (positionAtBuild_.size() != particles.size())
        return true;
    // (A check outside the step, serial: the step measures the motion in kickDrift.)
    Real largest2 = 0;
    for (std::size_t i = 0; i < particles.size(); ++i)
        largest2 = std::max(largest2, lengthSquared(particles.position[i] - positionAtBuild_[i]));
    return largest2 > 0.25 * skin * skin;
}

NeighborList::MotionReference NeighborList::motionReference(std::size_t particleCount) const
{
    if (positionAtBuild_.size() != particleCount)
        return {};
    const Vec3* const built = positionAtBuild_.data();
    return {built, positionAtActiveBuild_.size() == particleCount ? positionAtActiveBuild_.data() : built};
}

bool NeighborList::checkMotion(std::size_t particleCount, Real largestMotion2, Real largestActiveMotion2)
{
    if (positionAtBuild_.size() != particleCount)
        return true;
    if (largestActiveMotion2 > 0.25 * innerSkin * innerSkin)
        activeStale_ = true;
    return largestMotion2 > 0.25 * skin * skin;
}

namespace
{

std::uint64_t pairKey(std::uint32_t i, std::uint32_t j)
{
    return (std::uint64_t(i) << 32) | j;
}

} // namespace

void NeighborList::refreshActiveSlots(const ParticleStore& particles, ContactHistoryStore& history)
{
    ++activeAge_;
    const bool mayShrink = activeAge_ > 128 && innerSkin > skin / 64; // long-lived: try a tighter one
    if (!activeStale_ && !mayShrink)
        return;
    // Adapt the inner skin to the lifetime of the sub-list just ended.
    if (innerSkin <= 0 || innerSkin > skin)
        innerSkin = skin / 16; // first guess (doubled within a few steps if too tight)
    else if (activeAge_ < 8)
        innerSkin = std::min(2 * innerSkin, skin);
    else if (activeAge_ > 128)
        innerSkin = std::max(0.5 * innerSkin, skin / 64);
    activeAge_ = 0;
    activeStale_ = false;
    ++activeRebuilds_;
    positionAtActiveBuild_.assign(particles.position.begin(), particles.position.end());

    selectCandidates(particles, history);
    history.carry(source_.data(), activeSlots.size());

    // The rest of each candidate's record, from its slot.
    const std::size_t count = activeSlots.size();
    resizeGrowOnly(activeFirst, count);
    resizeGrowOnly(activeSecond, count);
    resizeGrowOnly(activeMass, count);
    resizeGrowOnly(activeDeferred, count);
    const Real* const mass = particles.mass.data();
    for (std::size_t a = 0; a < count; ++a)
    {
        const std::uint32_t k = activeSlots[a], i = first[k], j = second[k];
        activeFirst[a] = i;
        activeSecond[a] = j;
        activeMass[a] = effectivePairMass(mass[i], mass[j]);
        activeDeferred[a] = deferredIndex[k];
    }
    if (anyFixed) [[unlikely]] // a frozen particle's mass is infinite: m* is the other's
    {
        const std::uint8_t* const fixed = particles.fixed.data();
        for (std::size_t a = 0; a < count; ++a)
        {
            const std::uint32_t i = activeFirst[a], j = activeSecond[a];
            if (fixed[i] || fixed[j])
                activeMass[a] = fixed[i] ? mass[j] : mass[i];
        }
    }
    slotsRebuilt_ = false;
}

void NeighborList::selectCandidates(const ParticleStore& particles, const ContactHistoryStore& history)
{
    // Which slots are within the inner skin, and how many: the new sub-list's arrays are then
    // sized once (resizeGrowOnly: never shrunk, grown with an eighth of headroom).
    const Vec3* const x = particles.position.data();
    const Real* const r = particles.radius.data();
    const Real innerSkinReach = innerSkin + reach; // beyond r_i + r_j [m]
    resizeGrowOnly(within_, first.size());
    std::size_t count = 0;
    for (std::size_t k = 0; k < first.size(); ++k)
    {
        const std::uint32_t i = first[k], j = second[k];
        const Real within = r[i] + r[j] + innerSkinReach;
        within_[k] = lengthSquared(x[i] - x[j]) < within * within;
        count += within_[k];
    }
    // The old sub-list's slots move to oldSlots_ (slot-to-slot matching reads them).
    oldSlots_.swap(activeSlots);
    resizeGrowOnly(activeSlots, count);
    resizeGrowOnly(source_, count);
    const std::size_t oldCount = activeFirst.size();
    std::size_t a = 0, old = 0; // old: the first old candidate not yet matched or passed
    for (std::size_t k = 0; k < first.size(); ++k)
    {
        std::uint32_t from = kNoSource;
        if (slotsRebuilt_) // the old candidates name old slots: match by (i, j)
        {
            const std::uint64_t wanted = pairKey(first[k], second[k]);
            while (old < oldCount && pairKey(activeFirst[old], activeSecond[old]) < wanted)
                ++old; // no longer a slot (the deferred entries are new: nothing to zero)
            if (old < oldCount && pairKey(activeFirst[old], activeSecond[old]) == wanted)
                from = static_cast<std::uint32_t>(old++);
        }
        else if (old < oldCount && oldSlots_[old] == k) // every old candidate's slot is visited
            from = static_cast<std::uint32_t>(old++);
        if (within_[k])
        {
            activeSlots[a] = static_cast<std::uint32_t>(k);
            source_[a++] = from;
        }
        else if (from != kNoSource && !slotsRebuilt_ && history.formed[from])
            zeroDeferred(activeDeferred[from]); // left out, so not touching: the contact opened
    }
}

void NeighborList::forgetCandidates(ContactHistoryStore& history)
{
    for (auto* v : {&activeSlots, &activeFirst, &activeSecond, &activeDeferred})
        v->clear();
    activeMass.clear();
    history.clear();
}

void NeighborList::renameParticles(const std::vector<std::uint32_t>& newIndex, ContactHistoryStore& history)
{
    // Each kept candidate with its new key and its old entry, sorted by the new key.
    struct Renamed
    {
        std::uint64_t key;
        std::uint32_t from;
        bool flipped;
    };
    std::vector<Renamed> kept;
    kept.reserve(activeFirst.size());
    for (std::size_t a = 0; a < activeFirst.size(); ++a)
    {
        const std::uint32_t i = newIndex[activeFirst[a]], j = newIndex[activeSecond[a]];
        if (i == kGone || j == kGone)
            continue;
        kept.push_back({i < j ? pairKey(i, j) : pairKey(j, i), static_cast<std::uint32_t>(a), i > j});
    }
    std::sort(kept.begin(), kept.end(), [](const Renamed& a, const Renamed& b) { return a.key < b.key; });
    ContactHistoryStore renamed(history.keepFormed);
    renamed.keepRolling = history.keepRolling;
    renamed.scalarCount = history.scalarCount;
    const bool rolling = history.keepRolling && history.rolling.size() == history.spring.size();
    const bool formed = history.keepFormed && history.formed.size() == history.spring.size();
    std::vector<std::uint32_t> newFirst(kept.size()), newSecond(kept.size());
    renamed.spring.resize(kept.size());
    if (history.keepRolling)
        renamed.rolling.resize(kept.size());
    if (history.keepFormed)
        renamed.formed.resize(kept.size());
    renamed.resizeScalars(kept.size());
    for (std::size_t a = 0; a < kept.size(); ++a)
    {
        const Renamed& k = kept[a];
        newFirst[a] = static_cast<std::uint32_t>(k.key >> 32);
        newSecond[a] = static_cast<std::uint32_t>(k.key);
        // (j, i) instead of (i, j): the relative motion, and so each spring, changes sign.
        const Real sign = k.flipped ? -1.0 : 1.0;
        renamed.spring[a] = sign * history.spring[k.from];
        if (rolling)
            renamed.rolling[a] = sign * history.rolling[k.from];
        if (formed)
            renamed.formed[a] = history.formed[k.from];
        renamed.copyScalars(a, history, k.from); // (scalars do not change sign)
    }
    adoptCandidates(std::move(newFirst), std::move(newSecond), history, std::move(renamed));
}

void NeighborList::adoptCandidates(std::vector<std::uint32_t> newFirst, std::vector<std::uint32_t> newSecond,
                                   ContactHistoryStore& history, ContactHistoryStore&& adopted)
{
    activeFirst = std::move(newFirst);
    activeSecond = std::move(newSecond);
    history = std::move(adopted);
    // The slots name old particles: the rebuild that follows matches the candidates by (i, j).
    first.clear();
    second.clear();
    positionAtBuild_.clear();
    positionAtActiveBuild_.clear();
}

std::size_t NeighborList::candidateOfSlot(std::size_t k) const
{
    const std::uint64_t wanted = pairKey(first[k], second[k]);
    std::size_t lo = 0, hi = activeFirst.size(); // the candidates are sorted by (i, j)
    while (lo < hi)
    {
        const std::size_t mid = (lo + hi) / 2;
        if (pairKey(activeFirst[mid], activeSecond[mid]) < wanted)
            lo = mid + 1;
        else
            hi = mid;
    }
    if (lo < activeFirst.size() && pairKey(activeFirst[lo], activeSecond[lo]) == wanted)
        return lo;
    return kNotCandidate;
}

std::size_t NeighborList::memoryBytes() const
{
    auto bytes = [](const auto& v) { return v.capacity() * sizeof(v[0]); };
    return bytes(first) + bytes(second) + bytes(activeMass) + bytes(activeDeferred) + bytes(oldSlots_) +
           bytes(source_) + bytes(within_) + bytes(firstStart) + bytes(deferredIndex) + bytes(deferred) +
           bytes(incomingStart) + bytes(incomingEntry) + bytes(activeSlots) + bytes(activeFirst) +
           bytes(activeSecond) + bytes(positionAtBuild_) + bytes(positionAtActiveBuild_);
}

void NeighborList::rebuild(const ParticleStore& particles, ContactHistoryStore& history)
{
    ++rebuilds_;
    // The candidates keep their history and (i, j), which the next sub-list merges by key; the
    // rest of their record refers to the old slots and is freed before the new slots are
    // allocated, which lowers the peak memory of a rebuild.
    slotsRebuilt_ = true;
    for (auto* v : {&activeSlots, &activeDeferred, &oldSlots_, &source_})
        std::vector<std::uint32_t>().swap(*v);
    std::vector<Real>().swap(activeMass);
    std::vector<std::uint8_t>().swap(within_);
    activeStale_ = true; // new slots: the sub-list is rebuilt by the next force evaluation
    const std::size_t n = particles.size();
    positionAtBuild_.assign(particles.position.begin(), particles.position.end());
    if (positionAtActiveBuild_.size() != n) // (particles were inserted: the sub-list is stale)
        positionAtActiveBuild_.clear();
    firstStart.assign(n + 1, 0);
    incomingStart.assign(n + 1, 0);
    if (n == 0)
    {
        first.clear();
        second.clear();
        deferredIndex.clear();
        deferred.clear();
        incomingEntry.clear();
        forgetCandidates(history);
        return;
    }

    // Candidate pairs: for each i, every j > i within r_i + r_j + skin + reach, ascending
    // (pair_search.h: O(N) for any mix of sizes).
    std::vector<std::uint32_t> newSecond;
    findPairsWithin(particles, skin + reach, firstStart, newSecond, second.size());
    for (std::size_t i = 0; i < n; ++i)
        firstStart[i + 1] += firstStart[i];
    const std::size_t pairCount = firstStart[n];
    // The new list is built in fresh arrays of exact size and swapped in; the old ones are freed
    // on return, so that only one copy of the list is held between rebuilds.
    std::vector<std::uint32_t> newFirst(pairCount);
    for (std::size_t i = 0; i < n; ++i)
        std::fill(newFirst.begin() + firstStart[i], newFirst.begin() + firstStart[i + 1],
                  static_cast<std::uint32_t>(i));
    first.swap(newFirst);
    second.swap(newSecond);
    if (first.empty())
        // No slots: no force evaluation will rebuild the sub-list, so the old candidates would
        // wait for slots to come back, and hand a pair that was in contact before the pairs
        // separated its old history then.
        forgetCandidates(history);

    // Cross-block slots (the second particle in a later block), numbered in slot order; each
    // particle's incoming entries listed in slot order.
    deferredIndex.resize(pairCount);
    std::uint32_t deferredCount = 0;
    for (std::size_t k = 0; k < pairCount; ++k)
    {
        const bool cross = first[k] / kBlockParticles != second[k] / kBlockParticles;
        deferredIndex[k] = cross ? deferredCount++ : kInBlock;
        incomingStart[second[k] + 1] += cross;
    }
    for (std::size_t i = 0; i < n; ++i)
        incomingStart[i + 1] += incomingStart[i];
    deferred.assign(deferredCount, DeferredShare{});
    std::vector<std::uint32_t>(deferredCount).swap(incomingEntry);
    std::vector<std::uint32_t> fill(incomingStart.begin(), incomingStart.end() - 1);
    for (std::size_t k = 0; k < pairCount; ++k)
        if (deferredIndex[k] != kInBlock)
            incomingEntry[fill[second[k]]++] = deferredIndex[k];
}

void NeighborList::appendParticles(const ParticleStore& particles, std::size_t from)
{
    const std::size_t n = particles.size();
    const bool activeKept = positionAtActiveBuild_.size() == positionAtBuild_.size();
    for (std::size_t i = from; i < n; ++i)
    {
        positionAtBuild_.push_back(particles.position[i]);
        if (activeKept)
            positionAtActiveBuild_.push_back(particles.position[i]);
        // No slots and no incoming cross-block entries: the offsets repeat their last value.
        firstStart.push_back(firstStart.back());
        incomingStart.push_back(incomingStart.back());
    }
}

} // namespace veridem::dem
