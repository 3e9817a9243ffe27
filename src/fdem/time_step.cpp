#include "fdem/time_step.h"

#include "fdem/elements/cst.h"
#include "fdem/world.h"

#include <algorithm>
#include <cmath>
#include <sstream>

namespace veridem::fdem
{

Real dampingFactor(Real dampingRatio)
{
    return std::sqrt(1 + dampingRatio * dampingRatio) - dampingRatio;
}

Real elementTimeStep(Real minimumAltitude, Real pWaveSpeed, Real dampingRatio)
{
    return 0.98 * minimumAltitude / pWaveSpeed * dampingFactor(dampingRatio);
}

Real contactTimeStep(Real nodeMass, Real stiffness, Real dampingRatio)
{
    return 2 * std::sqrt(nodeMass / stiffness) * dampingFactor(dampingRatio);
}

std::string TimeStepLimit::describe() const
{
    std::ostringstream s;
    s << "stable time step " << limit << " s (elements " << element << " s, contact " << contact << " s";
    if (std::isfinite(joint))
        s << ", joints " << joint << " s";
    s << ")";
    return s.str();
}

TimeStepLimit stableTimeStep(const World& world)
{
    TimeStepLimit r{INFINITY, INFINITY, INFINITY};
    const NodeStore& nodes = world.nodes();
    const TriangleStore& tris = world.triangles();
    const ContactParameters& cp = world.settings().contact;
    const Real penalty = std::max(cp.normalPenalty, cp.friction > 0 ? cp.tangentialPenalty : 0);
    const Real contactZeta = std::max(cp.normalDampingRatio, cp.friction > 0 ? cp.tangentialDampingRatio : 0);
    for (std::size_t t = 0; t < tris.size(); ++t)
    {
        const auto& ids = tris.nodes[t];
        if (nodes.prescribed[ids[0]] && nodes.prescribed[ids[1]] && nodes.prescribed[ids[2]])
            continue;
        const Material& m = world.materials()[tris.material[t]];
        const Vec2 &a = nodes.referencePosition[ids[0]], &b = nodes.referencePosition[ids[1]],
                   &c = nodes.referencePosition[ids[2]];
        const Real h = minimumAltitude(a, b, c);
        const Real modulus = pWaveModulus(m);
        const Real cP = std::sqrt(modulus / m.density);
        const Real omegaMax = 2 / (0.98 * h / cP);
        const Real xi = m.viscosity * omegaMax / (2 * modulus);
        r.element = std::min(r.element, elementTimeStep(h, cP, xi));
        Real nodeMass = INFINITY;
        for (auto n : ids)
            if (!nodes.prescribed[n])
                nodeMass = std::min(nodeMass, nodes.mass[n]);
        const Real stiffness = 4 * 3 * penalty * longestEdge(a, b, c) / h;
        r.contact = std::min(r.contact, contactTimeStep(nodeMass, stiffness, contactZeta));
    }
    const JointStore& joints = world.joints();
    for (std::size_t j = 0; j < joints.size(); ++j)
    {
        const Real p = world.materials()[joints.material[j]].fracture.penalty;
        for (int k = 0; k < 2; ++k)
        {
            const auto a = joints.nodes[j][k], b = joints.nodes[j][k + 2];
            const Real inverseMass = nodes.inverseMass[a] + nodes.inverseMass[b];
            if (inverseMass == 0)
                continue;
            Real dtElement = INFINITY;
            for (auto t : joints.triangles[j])
            {
                const Material& m = world.materials()[tris.material[t]];
                const auto& ids = tris.nodes[t];
                const Real h =
                    minimumAltitude(nodes.referencePosition[ids[0]], nodes.referencePosition[ids[1]],
                                    nodes.referencePosition[ids[2]]);
                dtElement = std::min(dtElement, 0.98 * h / pWaveSpeed(m));
            }
            const Real omegaElement = 2 / dtElement, omegaJoint2 = p * inverseMass;
            r.joint = std::min(r.joint, 2 / std::sqrt(omegaElement * omegaElement + omegaJoint2));
        }
    }
    r.limit = std::min({r.element, r.contact, r.joint});
    return r;
}

} // namespace veridem::fdem
