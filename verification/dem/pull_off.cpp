// Two-sphere pull-off with adhesion (JKR and DMT), under displacement control: two equal spheres
// are driven together at a constant speed until they overlap by delta_max, then apart until they
// separate. The spheres are made so heavy that their contact force changes their prescribed
// velocity by less than 1e-12 of it, so the overlap is the prescribed one and the measured force
// is the contact law's force-overlap curve, loading and unloading.
//
// Expected, with w the work of adhesion (= 2 gamma), E* and R* = R/2 (models/cohesion.h cites the
// sources):
//   JKR, parametric in the contact radius a:
//       F = 4 E* a^3 / (3 R*) - sqrt(8 pi w E* a^3),   delta = a^2 / R* - sqrt(2 pi w a / E*);
//     no force while approaching before touch (delta < 0); the contact forms at touch and holds on
//     unloading to delta_c = -(3/4) (pi^2 w^2 R* / E*^2)^(1/3); the force minimum on the way is the
//     pull-off force -(3/2) pi w R*.
//   DMT: F = (4/3) E* sqrt(R*) delta^(3/2) - 2 pi w R* while delta > 0, none otherwise; pull-off
//     force 2 pi w R*, separation at delta = 0.
// The case computes a(delta) by bisection on the closed form (independently of the engine's Newton
// iteration). Tolerances: the curve to 1e-3 of the pull-off force and the pull-off force to 1 %
// (the acceptance of the cohesion models); the measured minimum lies within half a sampling step
// of the true one, where F is flat, so its sampling error is ~(u dt / delta_c)^2 ~ 1e-5. The
// breaking overlap is found between two samples: tolerance one step of travel, u dt.
#include "core/error.h"
#include "dem/models/cohesion.h"
#include "support.h"

#include <algorithm>
#include <limits>

namespace veridem::verify
{
namespace
{

struct Protocol
{
    Real radius = 1e-3;       // R [m] of each sphere (R* = R/2)
    Real speed = 1e-3;        // approach and retraction speed of the pair [m/s]
    Real dt = 5e-6;           // [s]: u dt = 5 nm of travel a step
    Real startGap = 2e-6;     // surface gap at the start [m]
    Real maxOverlap = 5e-6;   // delta_max [m]
    Real endGap = 3e-6;       // retraction continues to this gap [m]
    Real youngsModulus = 1e7; // E [Pa] (a soft solid, so that adhesion matters at this scale)
    Real poissonRatio = 0.3;  // [-]
    Real surfaceEnergy = 0.1; // gamma [J/m^2]: w = 0.2 J/m^2
};

struct Sample
{
    Real overlap; // [m]
    Real force;   // repulsive > 0 [N]
    bool loading;
};

/// Runs the protocol with the given normal model; returns (overlap, force) after every step.
std::vector<Sample> drive(dem::NormalModel model, const Protocol& pr)
{
    Material m;
    m.name = "adhesive";
    m.normalModel = model;
    m.youngsModulus = pr.youngsModulus;
    m.poissonRatio = pr.poissonRatio;
    m.surfaceEnergy = pr.surfaceEnergy;
    m.restitution = 1.0; // no dashpot: the elastic curve alone
    m.friction = 0.0;
    m.density = 1e18; // [kg/m^3]: ~4e9 kg spheres, so the contact force moves them by nothing
    World world = worldWith(m, {0, 0, 0});
    const Real r = pr.radius;
    const Real half = r + 0.5 * pr.startGap;
    world.particles.add({-half, 0, 0}, {}, {}, r, m.density, 0);
    world.particles.add({half, 0, 0}, {}, {}, r, m.density, 0);
    dem::prepare(world);

    std::vector<Sample> samples;
    const Real u = 0.5 * pr.speed; // each sphere's speed
    bool loading = true;
    const auto steps = static_cast<std::size_t>(
        std::ceil((pr.startGap + 2 * pr.maxOverlap + pr.endGap) / (pr.speed * pr.dt)) + 10);
    for (std::size_t s = 0; s < steps; ++s)
    {
        const Real sign = loading ? 1.0 : -1.0;
        world.particles.velocity[0] = {sign * u, 0, 0};
        world.particles.velocity[1] = {-sign * u, 0, 0};
        dem::step(world, pr.dt);
        if (!world.health.finite)
            throw SimulationError("pull_off: state is not finite at step " + std::to_string(world.stepCount));
        const Real distance = length(world.particles.position[1] - world.particles.position[0]);
        const Real overlap = 2 * r - distance;
        // Force on sphere 0 (at -x): repulsive pushes it along -x.
        samples.push_back({overlap, -world.particles.force[0].x, loading});
        if (loading && overlap >= pr.maxOverlap)
            loading = false;
        if (!loading && -overlap > pr.endGap)
            break;
    }
    return samples;
}

/// JKR contact radius a at overlap delta >= delta_c on the stable branch, by bisection on the
/// closed form delta(a) (increasing for a > a_c).
Real jkrRadiusByBisection(Real modulus, Real rStar, Real w, Real overlap)
{
    const Real ac = std::cbrt(kPi * w * rStar * rStar / (8 * modulus));
    Real lo = ac, hi = ac;
    while (dem::jkrOverlap(modulus, rStar, w, hi) < overlap)
        hi *= 2;
    for (int k = 0; k < 200 && hi - lo > 1e-15 * hi; ++k)
    {
        const Real mid = 0.5 * (lo + hi);
        (dem::jkrOverlap(modulus, rStar, w, mid) < overlap ? lo : hi) = mid;
    }
    return 0.5 * (lo + hi);
}

CaseResult run(dem::NormalModel model)
{
    const Protocol pr;
    const std::vector<Sample> samples = drive(model, pr);
    const Real eStar = pr.youngsModulus / (2 * (1 - pr.poissonRatio * pr.poissonRatio));
    const Real rStar = 0.5 * pr.radius;
    const Real w = 2 * pr.surfaceEnergy;
    const bool jkr = model == dem::NormalModel::Jkr;
    const Real pullOff = jkr ? 1.5 * kPi * w * rStar : 2 * kPi * w * rStar;
    const Real breaking = jkr ? -0.75 * std::cbrt(kPi * kPi * w * w * rStar / (eStar * eStar)) : 0.0;
    const Real travel = pr.speed * pr.dt;

    Real approachForce = 0, worstCurve = 0, minForce = std::numeric_limits<Real>::infinity();
    Real lastFormed = std::numeric_limits<Real>::quiet_NaN(), firstBroken = lastFormed;
    Series curve{jkr ? "jkr_force_overlap" : "dmt_force_overlap",
                 {"overlap_over_delta_c_or_m", "force_over_pulloff", "theory_over_pulloff", "loading"},
                 {}};
    bool touched = false;
    for (const Sample& s : samples)
    {
        touched = touched || s.overlap >= 0;
        // The theory's state: formed if touched and (loading, or unloading above the break).
        bool formed;
        if (s.loading)
            formed = jkr ? touched : s.overlap > 0;
        else
            formed = jkr ? s.overlap > breaking : s.overlap > 0;
        Real theory = 0;
        if (formed && jkr)
            theory = dem::jkrForce<Real>(eStar, rStar, w, jkrRadiusByBisection(eStar, rStar, w, s.overlap));
        else if (formed)
            theory = (4.0 / 3.0) * eStar * std::sqrt(rStar) * std::pow(s.overlap, 1.5) - pullOff;
        if (s.loading && !touched)
            approachForce = std::max(approachForce, std::fabs(s.force));
        // Skip the one sample at each transition whose state the sampling cannot decide.
        const bool nearBreak = !s.loading && std::fabs(s.overlap - breaking) < travel;
        if (!nearBreak)
            worstCurve = std::max(worstCurve, std::fabs(s.force - theory) / pullOff);
        minForce = std::min(minForce, s.force);
        if (!s.loading && s.force != 0)
            lastFormed = s.overlap;
        if (!s.loading && s.force == 0 && std::isnan(firstBroken) && s.overlap < 0)
            firstBroken = s.overlap;
        curve.rows.push_back({jkr ? s.overlap / -breaking : s.overlap, s.force / pullOff, theory / pullOff,
                              s.loading ? 1.0 : 0.0});
    }
    CaseResult r;
    r.quantities.push_back(absoluteQuantity("|F| before touch (approach)", "N", 0, approachForce, 0,
                                            "no force before the surfaces touch: exactly zero"));
    r.quantities.push_back(
        absoluteQuantity("max |F - F_theory| / F_pulloff", "", 0, worstCurve, 1e-3,
                         "acceptance of the cohesion models; the law evaluates the closed form"));
    r.quantities.push_back(relativeQuantity("pull-off force", "N", -pullOff, minForce, 1e-2,
                                            "acceptance: 1 %; sampling error ~(u dt / delta_c)^2 ~ 1e-5"));
    const Real breakAt = 0.5 * (lastFormed + firstBroken);
    r.quantities.push_back(absoluteQuantity("breaking overlap", "m", breaking, breakAt, travel,
                                            "found between two samples u dt = 5 nm apart"));
    r.notes.push_back("w = " + std::to_string(w) + " J/m^2, E* = " + std::to_string(eStar) +
                      " Pa, R* = " + std::to_string(rStar) + " m; " + std::to_string(samples.size()) +
                      " samples of the loading and unloading curve");
    r.series.push_back(std::move(curve));
    return r;
}

} // namespace

VERIDEM_CASE({.name = "jkr_pull_off",
              .summary = "two spheres with JKR adhesion loaded and pulled apart: force-overlap curve, "
                         "pull-off force (3/2) pi w R*, break at delta_c",
              .reference = "Johnson, Kendall & Roberts 1971; Johnson, Contact Mechanics 5.5",
              .labels = {"dem", "quick", "asmar", "cohesion"},
              .run = [](const CaseContext&) { return run(dem::NormalModel::Jkr); }});
VERIDEM_CASE({.name = "dmt_pull_off",
              .summary = "two spheres with DMT adhesion loaded and pulled apart: Hertz minus 2 pi w R*, "
                         "pull-off force 2 pi w R*",
              .reference = "Derjaguin, Muller & Toporov 1975; Maugis 2000",
              .labels = {"dem", "quick", "asmar", "cohesion"},
              .run = [](const CaseContext&) { return run(dem::NormalModel::Dmt); }});

} // namespace veridem::verify
