// The element loop of World::step(): gravity and the CST internal forces (elements/cst.h).
//
// Two phases, so that the forces have the same bits on any thread count: the triangles' forces and
// stresses are computed on the thread pool (each triangle writes only its own slots), then scattered
// to the nodes serially in the order of activeTriangles_, the order of the serial loop this replaced.
#include "core/error.h"
#include "exec/thread_pool.h"
#include "fdem/elements/cst.h"
#include "fdem/world.h"

#include <algorithm>
#include <sstream>

namespace veridem::fdem
{

void World::computeElementForces()
{
    // Every node's force starts from its weight each step, the prescribed ones' too: the elements,
    // joints and contacts next to a node held at rest add to it, and prescribedForce() sums it as the
    // support's load (not integrated: it was once left to accumulate over the steps). Triangles whose
    // nodes are all prescribed are skipped (activeTriangles_).
    const Vec2 g = settings_.gravity;
    for (std::size_t n = 0; n < nodes_.size(); ++n)
        nodes_.force[n] = nodes_.mass[n] * g;
    const std::size_t count = activeTriangles_.size();
    elementForce_.resize(count);
    elementJacobian_.resize(count);
    constexpr std::size_t kChunk = 2048;
    const int chunks = static_cast<int>((count + kChunk - 1) / kChunk);
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
                  }
              });
    for (std::size_t k = 0; k < count; ++k)
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
        const auto& ids = triangles_.nodes[t];
        for (int i = 0; i < 3; ++i)
            nodes_.force[ids[i]] += elementForce_[k][i];
    }
}

} // namespace veridem::fdem
