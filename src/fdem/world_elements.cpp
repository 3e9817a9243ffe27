// The element loop of World::step() (the CST internal forces of elements/cst.h) and the sum of the
// nodal forces: weight, elements and joints.
//
// The same bits on any thread count: the triangles' (and the joints', fracture/joints.cpp) forces are
// computed on the thread pool, each into its own slots; then each node sums, on the thread pool, its
// weight and the slots that act on it in the order of the serial loops this replaced (triangles in
// the order of activeTriangles_, then joints in joint order). A node's force is therefore the same
// sequence of additions as before, whatever thread sums it. Which slots act on a node is a CSR
// (compressed rows: one start offset per node into one array of slot ids), built when the active
// lists change.
#include "core/error.h"
#include "exec/thread_pool.h"
#include "fdem/elements/cst.h"
#include "fdem/world.h"

#include <algorithm>
#include <sstream>

namespace veridem::fdem
{

namespace
{

/// Rows of a CSR from (row, slot) entries given in slot order: start has rows + 1 offsets, and each
/// row lists its slots in the order they were given (counting sort, stable).
template <class EachEntry>
void buildRows(std::size_t rows, std::vector<std::uint32_t>& start, std::vector<std::uint32_t>& slots,
               EachEntry&& eachEntry)
{
    start.assign(rows + 1, 0);
    eachEntry([&](std::uint32_t row, std::uint32_t) { ++start[row + 1]; });
    for (std::size_t r = 0; r < rows; ++r)
        start[r + 1] += start[r];
    slots.resize(start[rows]);
    std::vector<std::uint32_t> fill(start.begin(), start.end() - 1);
    eachEntry([&](std::uint32_t row, std::uint32_t slot) { slots[fill[row]++] = slot; });
}

} // namespace

void World::buildNodeSlots()
{
    const std::size_t n = nodes_.size();
    buildRows(n, elementSlotStart_, elementSlots_,
              [&](auto&& add)
              {
                  for (std::size_t k = 0; k < activeTriangles_.size(); ++k)
                      for (std::uint32_t i = 0; i < 3; ++i)
                          add(triangles_.nodes[activeTriangles_[k]][i],
                              static_cast<std::uint32_t>(3 * k + i));
              });
    buildRows(n, jointSlotStart_, jointSlots_,
              [&](auto&& add)
              {
                  for (std::size_t j = 0; j < joints_.size(); ++j)
                      for (std::uint32_t e = 0; e < 4; ++e)
                          add(joints_.nodes[j][e], static_cast<std::uint32_t>(4 * j + e));
              });
    nodeSlotsValid_ = true;
}

void World::computeElementForces()
{
    const std::size_t count = activeTriangles_.size();
    elementForce_.resize(count);
    elementJacobian_.resize(count);
    constexpr std::size_t kChunk = 2048;
    const int chunks = static_cast<int>((count + kChunk - 1) / kChunk);
    std::vector<std::uint8_t> inverted(static_cast<std::size_t>(chunks), 0);
    exec::run(chunks,
              [&](int c)
              {
                  const std::size_t end = std::min(count, (static_cast<std::size_t>(c) + 1) * kChunk);
                  for (std::size_t k = static_cast<std::size_t>(c) * kChunk; k < end; ++k)
                  {
                      const auto t = activeTriangles_[k];
                      const auto& ids = triangles_.nodes[t];
                      const std::array<Vec2, 3> x{nodes_.position[ids[0]], nodes_.position[ids[1]],
                                                  nodes_.position[ids[2]]};
                      const std::array<Vec2, 3> v{nodes_.velocity[ids[0]], nodes_.velocity[ids[1]],
                                                  nodes_.velocity[ids[2]]};
                      const CstResult r = cstInternalForces(x, v, triangles_.referenceInverse[t],
                                                            constants_[triangles_.material[t]]);
                      elementForce_[k] = r.force;
                      elementJacobian_[k] = r.jacobian;
                      triangles_.stress[t] = r.stress;
                      if (!(r.jacobian > 0))
                          inverted[static_cast<std::size_t>(c)] = 1;
                  }
              });
    if (std::find(inverted.begin(), inverted.end(), 1) == inverted.end())
        return;
    for (std::size_t k = 0; k < count; ++k) // the first inverted triangle, whatever the thread count
    {
        const auto t = activeTriangles_[k];
        if (!(elementJacobian_[k] > 0))
        {
            std::ostringstream s;
            s << "step " << steps_ << " (t = " << time_ << " s): triangle " << t << " of body '"
              << bodyNames_[triangles_.body[t]] << "' is inverted (J = " << elementJacobian_[k]
              << "); reduce the time step or raise the contact penalty";
            throw SimulationError(s.str());
        }
    }
}

void World::sumNodeForces()
{
    // Every node's force starts from its weight each step, the prescribed ones' too: the elements,
    // joints and contacts next to a node held at rest add to it, and prescribedForce() sums it as the
    // support's load (not integrated: it was once left to accumulate over the steps). Triangles whose
    // nodes are all prescribed are skipped (activeTriangles_). A joint adds its end forces to the a
    // nodes and subtracts them from the b nodes unless it is broken (event 1: evaluated, intact).
    const Vec2 g = settings_.gravity;
    const std::size_t count = nodes_.size();
    const bool joints = !joints_.nodes.empty();
    constexpr std::size_t kChunk = 4096;
    const int chunks = static_cast<int>((count + kChunk - 1) / kChunk);
    exec::run(chunks,
              [&](int c)
              {
                  const std::size_t end = std::min(count, (static_cast<std::size_t>(c) + 1) * kChunk);
                  for (std::size_t n = static_cast<std::size_t>(c) * kChunk; n < end; ++n)
                  {
                      Vec2 f = nodes_.mass[n] * g;
                      for (std::uint32_t s = elementSlotStart_[n]; s < elementSlotStart_[n + 1]; ++s)
                      {
                          const std::uint32_t slot = elementSlots_[s];
                          f += elementForce_[slot / 3][slot % 3];
                      }
                      if (joints)
                          for (std::uint32_t s = jointSlotStart_[n]; s < jointSlotStart_[n + 1]; ++s)
                          {
                              const std::uint32_t j = jointSlots_[s] / 4, corner = jointSlots_[s] % 4;
                              if (joints_.event[j] != 1)
                                  continue;
                              const Vec2 jf = joints_.endForce[j][corner % 2];
                              if (corner < 2)
                                  f += jf;
                              else
                                  f -= jf;
                          }
                      nodes_.force[n] = f;
                  }
              });
}

} // namespace veridem::fdem
