#include "dem/wall_contacts.h"

#include "core/error.h"
#include "dem/parallel.h"

#include <algorithm>
#include <string>
#include <utility>

namespace veridem::dem
{

bool WallContactList::needsRebuild(const std::vector<Wall>& walls, Real skin) const
{
    if (wallDisplacementAtBuild_.size() != walls.size() || wallActiveAtBuild_.size() != walls.size())
        return true;
    for (std::size_t w = 0; w < walls.size(); ++w)
    {
        if (wallActive(walls[w]) != bool(wallActiveAtBuild_[w]))
            return true;
        if (const auto* mesh = std::get_if<MeshShape>(&walls[w].shape))
        {
            if (wallTurnAtBuild_.size() != walls.size() ||
                length(walls[w].displacement - wallDisplacementAtBuild_[w]) +
                        (mesh->turned - wallTurnAtBuild_[w]) * mesh->farthestVertex >
                    0.5 * skin)
                return true;
        }
        else if (lengthSquared(walls[w].displacement - wallDisplacementAtBuild_[w]) > 0.25 * skin * skin)
            return true;
    }
    return false;
}

void WallContactList::markActivity(const std::vector<Wall>& walls)
{
    wallActiveAtBuild_.resize(walls.size());
    for (std::size_t w = 0; w < walls.size(); ++w)
        wallActiveAtBuild_[w] = wallActive(walls[w]);
}

void WallContactList::setRecordLoads(bool on)
{
    recordLoads = on;
    loadForce.assign(on ? particle.size() : 0, Vec3{});
    loadMoment.assign(on ? particle.size() : 0, Vec3{});
}

WallLoad wallLoad(const WallContactList& list, std::uint32_t w, const Vec3& reference)
{
    Vec3 force, moment;
    for (std::size_t k = 0; k < list.loadForce.size() && k < list.size(); ++k)
        if (list.wall[k] == w)
        {
            force += list.loadForce[k];
            moment += list.loadMoment[k];
        }
    // On the particles about the reference: moment - reference x force; the wall takes minus that.
    return {-force, cross(reference, force) - moment};
}

namespace
{

/// Candidate slots, sorted by (particle, wall): per slot its particle and wall and, when some wall
/// is a mesh, its triangles' count (a mesh group's first slot: its triangles within r + reach; a
/// flat candidate's one slot: 1, its plane's triangle; 0 otherwise) and its flat mark (the plane's
/// triangle, or WallContactList::kNotFlat).
struct CandidateSlots
{
    std::vector<std::uint32_t> particle, wall, triangleCount, triangles, flat;
};

/// Appends particle i's candidates with `walls` within `reach` [m] (wallNear; for a mesh,
/// meshTrianglesNear and meshPatchFlat) to `out`; `anyMesh`: some wall is a mesh.
void appendCandidates(const ParticleStore& particles, std::size_t i, const std::vector<Wall>& walls,
                      Real reach, bool anyMesh, CandidateSlots& out)
{
    const Vec3& x = particles.position[i];
    const Real r = particles.radius[i];
    const auto slot = [&](std::size_t w, std::uint32_t triangleCount, std::uint32_t flat)
    {
        out.particle.push_back(static_cast<std::uint32_t>(i));
        out.wall.push_back(static_cast<std::uint32_t>(w));
        if (anyMesh)
        {
            out.triangleCount.push_back(triangleCount);
            out.flat.push_back(flat);
        }
    };
    for (std::size_t w = 0; w < walls.size(); ++w)
    {
        const Wall& candidate = walls[w];
        const auto* mesh = std::get_if<MeshShape>(&candidate.shape);
        if (mesh && wallActive(candidate))
        {
            const std::size_t near =
                meshTrianglesNear(*mesh, candidate.displacement, x, r, reach, out.triangles);
            if (near == 0)
                continue;
            const std::size_t listed = out.triangles.size() - near;
            if (meshPatchFlat(*mesh, candidate.displacement, x, r, reach, out.triangles.data() + listed,
                              near))
            {
                out.triangles.resize(listed + 1);
                slot(w, 1, out.triangles[listed]);
                continue;
            }
            for (int q = 0; q < kMeshSlots; ++q)
                slot(w, q == 0 ? static_cast<std::uint32_t>(near) : 0, WallContactList::kNotFlat);
        }
        else if (!mesh && wallNear(candidate, x, r, reach))
            slot(w, 0, WallContactList::kNotFlat);
    }
}

} // namespace

void WallContactList::rebuild(const ParticleStore& particles, const std::vector<Wall>& walls, Real skin,
                              ContactHistoryStore& history)
{
    const std::size_t n = particles.size();
    wallDisplacementAtBuild_.resize(walls.size());
    bool anyMesh = false;
    for (std::size_t w = 0; w < walls.size(); ++w)
    {
        wallDisplacementAtBuild_[w] = walls[w].displacement;
        anyMesh = anyMesh || std::holds_alternative<MeshShape>(walls[w].shape);
    }
    wallTurnAtBuild_.clear();
    if (anyMesh)
        for (const Wall& w : walls)
        {
            const auto* mesh = std::get_if<MeshShape>(&w.shape);
            wallTurnAtBuild_.push_back(mesh ? mesh->turned : 0);
        }
    markActivity(walls);

    // Candidates per chunk of particles, concatenated in order (sorted by (particle, wall)).
    // (A mesh candidate's slots: its triangles' count on the first, 0 on the others; a flat one's
    // one slot: 1, its plane's triangle.)
    const int chunks = std::min(loopThreads(n), 64);
    std::vector<CandidateSlots> chunkSlots(static_cast<std::size_t>(chunks));
    if (chunks > 1) // (reserved here: a worker thread's malloc arena would keep what it frees)
        for (CandidateSlots& part : chunkSlots)
        {
            const auto share = [&](std::size_t total)
            { return (total + total / 8) / static_cast<std::size_t>(chunks) + 16; };
            part.particle.reserve(share(particle.size()));
            part.wall.reserve(share(particle.size()));
            if (anyMesh)
            {
                part.triangleCount.reserve(share(particle.size()));
                part.flat.reserve(share(particle.size()));
                part.triangles.reserve(share(meshTriangles.size()));
            }
        }
    parallelChunks(n, chunks,
                   [&](int c, std::size_t begin, std::size_t end)
                   {
                       for (std::size_t i = begin; i < end; ++i)
                           appendCandidates(particles, i, walls, skin, anyMesh,
                                            chunkSlots[static_cast<std::size_t>(c)]);
                   });
    std::vector<std::uint32_t> newParticle, newWall, triangleStart, triangles, newFlat;
    for (const CandidateSlots& part : chunkSlots)
    {
        newParticle.insert(newParticle.end(), part.particle.begin(), part.particle.end());
        newWall.insert(newWall.end(), part.wall.begin(), part.wall.end());
        triangleStart.insert(triangleStart.end(), part.triangleCount.begin(), part.triangleCount.end());
        triangles.insert(triangles.end(), part.triangles.begin(), part.triangles.end());
        newFlat.insert(newFlat.end(), part.flat.begin(), part.flat.end());
    }
    const std::size_t count = newParticle.size();
    if (anyMesh) // counts to offsets
    {
        triangleStart.push_back(0);
        std::uint32_t offset = 0;
        for (std::size_t k = 0; k <= count; ++k)
            offset += std::exchange(triangleStart[k], offset);
    }
    meshTriangleStart.swap(triangleStart);
    meshTriangles.swap(triangles);

    // Re-key the history: each slot's source is the old slot with the same (particle, wall), a
    // mesh group's slots in order, and across a flat/general change as the header says.
    std::vector<std::uint32_t> source(count, ContactHistoryStore::kNoSource);
    const auto key = [](std::uint32_t a, std::uint32_t b) { return (std::uint64_t(a) << 32) | b; };
    const bool oldFlat = meshFlat.size() == particle.size() && meshNormal.size() == particle.size();
    std::size_t old = 0;
    for (std::size_t k = 0, next = 0; k < count; k = next)
    {
        const std::uint64_t wanted = key(newParticle[k], newWall[k]);
        for (next = k + 1; next < count && key(newParticle[next], newWall[next]) == wanted;)
            ++next;
        while (old < particle.size() && key(particle[old], wall[old]) < wanted)
            ++old;
        std::size_t oldEnd = old;
        while (oldEnd < particle.size() && key(particle[oldEnd], wall[oldEnd]) == wanted)
            ++oldEnd;
        const bool nowFlat = anyMesh && newFlat[k] != kNotFlat;
        const bool wasFlat = oldFlat && old < oldEnd && meshFlat[old] != kNotFlat;
        if (nowFlat && !wasFlat && oldEnd - old > 1 &&
            meshNormal.size() == particle.size()) // general -> flat: the old slot of the plane's normal
        {
            const Wall& meshWall = walls[newWall[k]];
            const MeshShape& shape = std::get<MeshShape>(meshWall.shape);
            const TriangleMesh& m = *shape.mesh;
            const Vec3 p = bodyPoint(shape, meshWall.displacement, particles.position[newParticle[k]]);
            const Vec3& normal = m.normals[newFlat[k]];
            const Vec3 towards =
                dot(p - m.vertices[m.triangles[newFlat[k]][0]], normal) < 0 ? -normal : normal;
            Real bestCos = 0.5; // (as the matching: within 60 degrees)
            for (std::size_t o = old; o < oldEnd; ++o)
                if (dot(meshNormal[o], towards) > bestCos)
                {
                    bestCos = dot(meshNormal[o], towards);
                    source[k] = static_cast<std::uint32_t>(o);
                }
        }
        else // the same kind (q-th to q-th), flat -> general (the first slot) or a plain wall
            for (std::size_t q = 0; q < next - k && old + q < oldEnd; ++q)
                source[k + q] = static_cast<std::uint32_t>(old + q);
        old = oldEnd;
    }
    if (anyMesh)
    {
        std::vector<Vec3> normals(count);
        if (meshNormal.size() == particle.size())
            for (std::size_t k = 0; k < count; ++k)
                if (source[k] != ContactHistoryStore::kNoSource)
                    normals[k] = meshNormal[source[k]];
        meshNormal.swap(normals);
    }
    else
        meshNormal.clear();
    meshFlat.swap(newFlat);
    if (history.size() != particle.size()) // (never built: no history to carry)
        history.clear();
    history.carry(source.data(), count);
    particle.swap(newParticle);
    wall.swap(newWall);
    if (recordLoads)
    {
        loadForce.assign(count, Vec3{});
        loadMoment.assign(count, Vec3{});
    }
    start.assign(n + 1, 0);
    for (std::size_t k = 0; k < count; ++k)
        ++start[particle[k] + 1];
    for (std::size_t i = 0; i < n; ++i)
        start[i + 1] += start[i];
}

void WallContactList::appendParticles(const ParticleStore& particles, std::size_t from,
                                      const std::vector<Wall>& walls, Real reach,
                                      ContactHistoryStore& history)
{
    // The triangle lists only where they are kept: after a restore the step uses the mesh grids
    // until the next rebuild.
    const bool triangleLists = meshTriangleStart.size() == particle.size() + 1;
    const bool anyMesh = !meshNormal.empty() || !wallTurnAtBuild_.empty();
    CandidateSlots added;
    for (std::size_t i = from; i < particles.size(); ++i)
    {
        appendCandidates(particles, i, walls, reach, anyMesh, added);
        start.push_back(static_cast<std::uint32_t>(particle.size() + added.particle.size()));
    }
    particle.insert(particle.end(), added.particle.begin(), added.particle.end());
    wall.insert(wall.end(), added.wall.begin(), added.wall.end());
    const std::size_t count = particle.size();
    if (anyMesh)
    {
        if (triangleLists)
        {
            for (const std::uint32_t c : added.triangleCount)
                meshTriangleStart.push_back(meshTriangleStart.back() + c);
            meshTriangles.insert(meshTriangles.end(), added.triangles.begin(), added.triangles.end());
        }
        meshNormal.resize(count, Vec3{});
        meshFlat.insert(meshFlat.end(), added.flat.begin(), added.flat.end());
    }
    history.spring.resize(count, Vec3{});
    if (history.keepRolling)
        history.rolling.resize(count, Vec3{});
    if (history.keepFormed)
        history.formed.resize(count, 0);
    history.resizeScalars(count);
    if (recordLoads)
    {
        loadForce.resize(count, Vec3{});
        loadMoment.resize(count, Vec3{});
    }
}

void WallContactList::renameParticles(const std::vector<std::uint32_t>& newIndex,
                                      ContactHistoryStore& history)
{
    constexpr std::uint32_t kGone = 0xffffffffu;               // (NeighborList::kGone)
    std::vector<std::pair<std::uint64_t, std::uint32_t>> kept; // new (particle, wall) key, old slot
    kept.reserve(particle.size());
    for (std::size_t k = 0; k < particle.size(); ++k)
        if (const std::uint32_t p = newIndex[particle[k]]; p != kGone)
            kept.push_back({(std::uint64_t(p) << 32) | wall[k], static_cast<std::uint32_t>(k)});
    std::sort(kept.begin(), kept.end());
    ContactHistoryStore renamed(history.keepFormed);
    renamed.keepRolling = history.keepRolling;
    renamed.scalarCount = history.scalarCount;
    const bool rolling = history.keepRolling && history.rolling.size() == history.spring.size();
    std::vector<std::uint32_t> newParticle(kept.size()), newWall(kept.size());
    renamed.spring.resize(kept.size());
    if (rolling)
        renamed.rolling.resize(kept.size());
    renamed.resizeScalars(kept.size());
    for (std::size_t k = 0; k < kept.size(); ++k)
    {
        newParticle[k] = static_cast<std::uint32_t>(kept[k].first >> 32);
        newWall[k] = static_cast<std::uint32_t>(kept[k].first);
        renamed.spring[k] = history.spring[kept[k].second];
        if (rolling)
            renamed.rolling[k] = history.rolling[kept[k].second];
        renamed.copyScalars(k, history, kept[k].second);
    }
    std::vector<Vec3> normals; // (a mesh group's slots stay together and in order: stable keys)
    if (!meshNormal.empty())
    {
        normals.resize(kept.size());
        for (std::size_t k = 0; k < kept.size(); ++k)
            normals[k] = meshNormal[kept[k].second];
    }
    std::vector<std::uint32_t> flat;
    if (!meshFlat.empty())
    {
        flat.resize(kept.size());
        for (std::size_t k = 0; k < kept.size(); ++k)
            flat[k] = meshFlat[kept[k].second];
    }
    adoptSlots(std::move(newParticle), std::move(newWall), std::move(normals), std::move(flat), history,
               std::move(renamed));
}

void WallContactList::adoptSlots(std::vector<std::uint32_t> particles, std::vector<std::uint32_t> walls,
                                 std::vector<Vec3> normals, std::vector<std::uint32_t> flat,
                                 ContactHistoryStore& history, ContactHistoryStore&& adopted)
{
    particle = std::move(particles);
    wall = std::move(walls);
    meshNormal = std::move(normals);
    meshFlat = std::move(flat);
    history = std::move(adopted);
    start.clear();
    meshTriangleStart.clear(); // (the rebuild that follows makes them again)
    meshTriangles.clear();
}

std::size_t WallContactList::meshGroupFirst(std::size_t k) const
{
    if (meshFlat[k] != kNotFlat)
        return k;
    std::size_t first = k;
    while (first > 0 && k - first < kMeshSlots - 1 && particle[first - 1] == particle[k] &&
           wall[first - 1] == wall[k])
        --first;
    return first;
}

void WallContactList::matchMeshGroup(std::size_t first, const Wall& meshWall, const Vec3& x, Real r,
                                     MeshGroup& group, Vec3* next) const
{
    const MeshShape& shape = std::get<MeshShape>(meshWall.shape);
    group.first = first;
    if (meshFlat[first] != kNotFlat)
    {
        bool fresh;
        group.size = 1;
        group.gap[0] = flatSlotGap(first, shape, meshWall.displacement, x, r, next[0], fresh);
        group.touching = group.gap[0].touching ? 1u : 0u;
        group.fresh = fresh ? 1u : 0u;
        return;
    }
    group.size = kMeshSlots;
    MeshContactBuffer buffer;
    const MeshBodyContact* const found = buffer.item;
    const int count = meshTriangleStart.size() == particle.size() + 1
                          ? meshBodyContacts(shape, meshWall.displacement, x, r,
                                             meshTriangles.data() + meshTriangleStart[first],
                                             meshTriangleStart[first + 1] - meshTriangleStart[first], buffer)
                          : meshBodyContacts(shape, meshWall.displacement, x, r, buffer);
    // (next may be the stored normals themselves: a slot's stored normal is read only while it is
    // not taken, and next is written only for taken slots until the end.)
    const Vec3* stored = meshNormal.data() + first;
    std::uint32_t taken = 0, fresh = 0; // bit q: slot first + q
    for (int c = 0; c < count; ++c)     // deepest first
    {
        const Vec3& normal = found[c].bodyNormal;
        int best = -1;
        Real bestCos = 0.5; // a contact keeps its slot while its normal turns by < 60 degrees
        for (int q = 0; q < kMeshSlots; ++q)
            if (!(taken >> q & 1u) && dot(stored[q], normal) > bestCos)
            {
                best = q;
                bestCos = dot(stored[q], normal);
            }
        if (best < 0) // a new contact: an empty slot, else one whose contact has gone (fresh)
        {
            for (int q = 0; q < kMeshSlots && best < 0; ++q)
                if (!(taken >> q & 1u) && lengthSquared(stored[q]) == 0)
                    best = q;
            for (int q = 0; q < kMeshSlots && best < 0; ++q)
                if (!(taken >> q & 1u))
                    best = q;
            if (lengthSquared(stored[best]) > 0)
                fresh |= 1u << best;
        }
        taken |= 1u << best;
        WallGap& gap = group.gap[best];
        gap.touching = true;
        gap.overlap = found[c].overlap;
        gap.normal = worldDirection(shape, normal);
        gap.effectiveRadius = r;
        // (Component by component: a block copy's wide loads would straddle the narrower stores
        // that just wrote the normal and stall store-to-load forwarding.)
        next[best].x = normal.x;
        next[best].y = normal.y;
        next[best].z = normal.z;
    }
    for (int q = 0; q < kMeshSlots; ++q)
        if (!(taken >> q & 1u))
            next[q].x = next[q].y = next[q].z = 0;
    group.touching = taken;
    group.fresh = fresh;
}

WallGap WallContactList::meshSlotGap(std::size_t k, const Wall& meshWall, const Vec3& x, Real r,
                                     MeshGroup& group)
{
    if (group.first == ~std::size_t(0) || k < group.first || k >= group.first + group.size ||
        particle[group.first] != particle[k] || wall[group.first] != wall[k])
    {
        const std::size_t first = meshGroupFirst(k);
        matchMeshGroup(first, meshWall, x, r, group, meshNormal.data() + first);
    }
    return group.gapOf(k - group.first);
}

WallGap WallContactList::meshSlotGapAsStored(std::size_t k, const Wall& meshWall, const Vec3& x, Real r) const
{
    MeshGroup group;
    Vec3 next[kMeshSlots];
    const std::size_t first = meshGroupFirst(k);
    matchMeshGroup(first, meshWall, x, r, group, next);
    return group.gapOf(k - first);
}

std::size_t WallContactList::slotOf(std::uint32_t particleIndex, std::uint32_t wallIndex) const
{
    for (std::size_t k = 0; k < particle.size(); ++k)
        if (particle[k] == particleIndex && wall[k] == wallIndex)
            return k;
    throw InputError("particle " + std::to_string(particleIndex) + " has no contact slot with wall " +
                     std::to_string(wallIndex) + " (it is not within the neighbour skin of it)");
}

std::size_t WallContactList::memoryBytes() const
{
    auto bytes = [](const auto& v) { return v.capacity() * sizeof(v[0]); };
    return bytes(particle) + bytes(wall) + bytes(start) + bytes(wallDisplacementAtBuild_) +
           bytes(wallActiveAtBuild_) + bytes(loadForce) + bytes(loadMoment) + bytes(meshNormal) +
           bytes(wallTurnAtBuild_) + bytes(meshTriangleStart) + bytes(meshTriangles) + bytes(meshFlat);
}

} // namespace veridem::dem
