// Paper Fig. 1 (Xiang, Munjiza, Latham & Guises, section 3; BENCHMARKS 1a): a 0.05 m square block
// (rho 2650 kg/m^3, E 1 GPa, nu 0.25 plane strain, 4 x 4 cells) slides on a fixed base with mu = 0.5
// and stops after L = v^2 / (2 mu g). Swept over v in {0.5, 1, 2, 3, 4, 5, 6} m/s.
//
// Tolerances (BENCHMARKS 1a "Pass"): |L_num - L| / L <= 0.5 % for v >= 1 m/s and 0.2 mm at 0.5 m/s.
// The block's elastic shear and the penalty pre-slip are both < 1e-6 m and the explicit scheme's
// stop-position error is O(v dt) < 1e-5 m, so the tolerance only covers the centroid definition
// and the settling; a larger error is an algorithm fault (dashpot outside the cap, no spring reset,
// stale history), not a time-step effect. Friction work = m v^2 / 2 to 0.1 % (BENCHMARKS 1a).
// Creep after the stop: < 1e-6 m over 0.1 s (BENCHMARKS 1a diagnostics).
#include "case.h"
#include "fdem/scenarios.h"
#include "fdem/time_step.h"

#include <cmath>
#include <cstdio>
#include <sstream>

namespace veridem::verify
{
namespace
{

using fdem::SlidingBlockResult;
using fdem::SlidingBlockSetup;

const std::vector<double> kVelocities{0.5, 1, 2, 3, 4, 5, 6};

/// Runs the sweep over `velocities` at each time step of `dts`, every world a task
/// (CaseContext::forEach), the longest (fastest block, smallest dt) first; results[d][i] is
/// velocities[i] at dts[d].
std::vector<std::vector<SlidingBlockResult>> sweep(const std::vector<double>& velocities,
                                                   const std::vector<double>& dts, const CaseContext& context)
{
    std::vector<std::vector<SlidingBlockResult>> results(dts.size(),
                                                         std::vector<SlidingBlockResult>(velocities.size()));
    context.forEach(dts.size() * velocities.size(),
                    [&](std::size_t k)
                    {
                        const std::size_t d = k / velocities.size();
                        const std::size_t i = velocities.size() - 1 - k % velocities.size();
                        SlidingBlockSetup s;
                        s.velocity = velocities[i];
                        s.timeStep = dts[d];
                        results[d][i] = fdem::runSlidingBlock(s);
                        if (context.showProgress)
                            std::fprintf(
                                stderr, "  sliding block v = %g m/s, dt = %g s: L = %.7f m (%.1f s)\n",
                                velocities[i], dts[d], results[d][i].stopDistance, results[d][i].wallSeconds);
                    });
    return results;
}

double theory(double v)
{
    return v * v / (2 * 0.5 * 9.81);
}

void addQuantities(CaseResult& result, const std::vector<double>& velocities,
                   const std::vector<SlidingBlockResult>& runs, const std::string& tag)
{
    for (std::size_t i = 0; i < velocities.size(); ++i)
    {
        const double v = velocities[i];
        const SlidingBlockResult& r = runs[i];
        std::ostringstream name;
        name << "L(v=" << v << ")" << tag;
        const double measured = r.stopped ? r.stopDistance : NAN;
        if (v >= 1)
            result.quantities.push_back(relativeQuantity(name.str(), "m", theory(v), measured, 5e-3,
                                                         "BENCHMARKS 1a: 0.5 % for v >= 1 m/s"));
        else
            result.quantities.push_back(absoluteQuantity(name.str(), "m", theory(v), measured, 2e-4,
                                                         "BENCHMARKS 1a: 0.2 mm at 0.5 m/s"));
        result.quantities.push_back(
            relativeQuantity("friction work/KE(v=" + std::to_string(v).substr(0, 3) + ")" + tag, "", 1,
                             r.frictionWork / r.kineticEnergy, 1e-3,
                             "energy balance: all of m v^2/2 dissipated by friction, 0.1 %"));
        result.quantities.push_back(absoluteQuantity("creep(v=" + std::to_string(v).substr(0, 3) + ")" + tag,
                                                     "m", 0, r.creep, 1e-6,
                                                     "BENCHMARKS 1a: drift < 1e-6 m over 0.1 s"));
        std::ostringstream note;
        note << tag << " v = " << v << " m/s: L = " << r.stopDistance << " m (theory " << theory(v)
             << ", error " << (r.stopDistance - theory(v)) / theory(v) * 100 << " %), stop time "
             << r.stopTime << " s (theory " << v / (0.5 * 9.81)
             << "), friction work / KE = " << r.frictionWork / r.kineticEnergy << ", normal-dashpot work "
             << r.dampingWork << " J/m, mean sum|Ft|/sum(mu Fn) while sliding " << r.meanCapRatio
             << ", creep " << r.creep << " m, " << r.steps << " steps in " << r.wallSeconds << " s";
        result.notes.push_back(note.str());
    }
}

CaseResult runOne(double dt, const CaseContext& context)
{
    CaseResult result;
    const auto runs = sweep(kVelocities, {dt}, context)[0];
    const std::string tag = dt < 5e-7 ? " dt1e-7" : " dt1e-6";
    addQuantities(result, kVelocities, runs, tag);
    Series s{"sliding_block" + std::string(dt < 5e-7 ? "_dt1e-7" : "_dt1e-6"), {"v", "L_theory", "L"}, {}};
    for (std::size_t i = 0; i < kVelocities.size(); ++i)
        s.rows.push_back({kVelocities[i], theory(kVelocities[i]), runs[i].stopDistance});
    result.series.push_back(s);
    return result;
}

VERIDEM_CASE({.name = "sliding_block_dt1e-6",
              .summary = "paper Fig. 1 sweep v = 0.5..6 m/s at dt = 1e-6 s: L = v^2/(2 mu g)",
              .reference = "Xiang et al. section 3, eq. 4; BENCHMARKS 1a",
              .labels = {"fdem", "paper"},
              .run = [](const CaseContext& c) { return runOne(1e-6, c); }});

VERIDEM_CASE({.name = "sliding_block_dt1e-7",
              .summary = "paper Fig. 1 sweep at dt = 1e-7 s and 1e-6 s (figure series), two finest dt agree",
              .reference = "Xiang et al. section 3, eq. 4; BENCHMARKS 1a",
              .labels = {"fdem", "paper", "slow"},
              .run = [](const CaseContext& c)
              {
                  CaseResult result;
                  const auto runs = sweep(kVelocities, {1e-7, 1e-6}, c); // dt sorted: longest first
                  const auto& fine = runs[0];
                  const auto& coarse = runs[1];
                  addQuantities(result, kVelocities, fine, " dt1e-7");
                  for (std::size_t i = 0; i < kVelocities.size(); ++i)
                      if (kVelocities[i] >= 1)
                          result.quantities.push_back(relativeQuantity(
                              "L dt1e-6 vs dt1e-7 (v=" + std::to_string(kVelocities[i]).substr(0, 3) + ")",
                              "m", fine[i].stopDistance, coarse[i].stopDistance, 1e-3,
                              "BENCHMARKS 1a: the two finest dt agree to 0.1 %"));
                  Series s{"sliding_block", {"v", "L_theory", "L_dt1e-6", "L_dt1e-7"}, {}};
                  for (std::size_t i = 0; i < kVelocities.size(); ++i)
                      s.rows.push_back({kVelocities[i], theory(kVelocities[i]), coarse[i].stopDistance,
                                        fine[i].stopDistance});
                  result.series.push_back(s);
                  return result;
              }});

VERIDEM_CASE({.name = "fdem_sliding_block_v1",
              .summary = "sliding block at v = 1 m/s, dt = 1e-6 s (CI subset of Fig. 1)",
              .reference = "Xiang et al. section 3, eq. 4; BENCHMARKS 1a",
              .labels = {"fdem", "quick"},
              .run = [](const CaseContext&)
              {
                  CaseResult result;
                  SlidingBlockSetup s;
                  s.velocity = 1;
                  s.timeStep = 1e-6;
                  const SlidingBlockResult r = fdem::runSlidingBlock(s);
                  addQuantities(result, {1.0}, {r}, " dt1e-6");
                  return result;
              }});

} // namespace
} // namespace veridem::verify

namespace veridem::verify
{
namespace
{

// Mesh independence (BENCHMARKS 1a: n = 4, 8, 16): v = 2 m/s with the block meshed n x n, each at
// 0.4 x its own printed stable time step (the contact limit shrinks with the node mass). Same
// tolerance as the sweep (0.5 %): a mesh effect larger than that would be an algorithm fault.
CaseResult meshConvergence(const CaseContext& context)
{
    CaseResult result;
    Series s{"sliding_block_mesh", {"cells", "dt", "L_theory", "L"}, {}};
    const std::vector<int> cells{4, 8, 16};
    std::vector<fdem::SlidingBlockSetup> setups(cells.size());
    std::vector<SlidingBlockResult> runs(cells.size());
    context.forEach(cells.size(),
                    [&](std::size_t k)
                    {
                        const std::size_t i = cells.size() - 1 - k; // the finest (longest) first
                        const int n = cells[i];
                        fdem::SlidingBlockSetup& setup = setups[i];
                        setup.velocity = 2;
                        setup.cells = n;
                        setup.timeStep = 1; // only to build the world for the limit
                        const fdem::World probe = fdem::makeSlidingBlockWorld(setup);
                        setup.timeStep = 0.4 * fdem::stableTimeStep(probe).limit;
                        runs[i] = fdem::runSlidingBlock(setup);
                        if (context.showProgress)
                            std::fprintf(stderr, "  %d x %d: dt = %.3g s, L = %.7f m (%.1f s)\n", n, n,
                                         setup.timeStep, runs[i].stopDistance, runs[i].wallSeconds);
                    });
    for (std::size_t i = 0; i < cells.size(); ++i)
    {
        const int n = cells[i];
        const fdem::SlidingBlockSetup& setup = setups[i];
        const SlidingBlockResult& r = runs[i];
        result.quantities.push_back(
            relativeQuantity("L(v=2, " + std::to_string(n) + "x" + std::to_string(n) + ")", "m", theory(2),
                             r.stopped ? r.stopDistance : NAN, 5e-3, "BENCHMARKS 1a: 0.5 % for every mesh"));
        std::ostringstream note;
        note << n << " x " << n << ": dt = " << setup.timeStep << " s, L error "
             << r.stopDistance / theory(2) - 1
             << ", friction work / KE = " << r.frictionWork / r.kineticEnergy << ", creep " << r.creep
             << " m, " << r.steps << " steps in " << r.wallSeconds << " s";
        result.notes.push_back(note.str());
        s.rows.push_back({static_cast<double>(n), setup.timeStep, theory(2), r.stopDistance});
    }
    result.series.push_back(s);
    return result;
}

VERIDEM_CASE({.name = "sliding_block_mesh",
              .summary = "sliding block v = 2 m/s with 4x4, 8x8 and 16x16 meshes at 0.4 x their stable dt",
              .reference = "Xiang et al. section 3, eq. 4; BENCHMARKS 1a (n = 4, 8, 16)",
              .labels = {"fdem", "slow"},
              .run = meshConvergence});

} // namespace
} // namespace veridem::verify
