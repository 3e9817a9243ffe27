// Shared pieces of the bulk checks (beverloo_discharge, janssen_silo, angle_of_repose_trend):
// scenes read from TOML text through the scene reader (the path a user's scene file takes), a
// stepping loop that applies the scene's particle flow ([[insert]], [[outlet]]) between runs of
// steps as `veridem run` does, a pour in stages into a vertical cylinder, and least-squares fits.
// docs/bulk-checks.md describes the set-ups.
#pragma once

#include "io/dem_scene.h"
#include "support.h"

#include <functional>
#include <string>
#include <vector>

namespace veridem::verify
{

/// A scene from TOML text (`source` names it in messages).
io::DemScene sceneFromText(const std::string& text, const std::string& source);

/// Refuses a scene whose dt exceeds tc/25 (tc the shortest contact time of the materials and the
/// inserters' radii): the bulk checks keep every contact resolved by at least 25 steps.
void requireResolvedContacts(const io::DemScene& scene, const std::string& label);

/// Steps the scene for `duration` [s] at scene.dt (times context.dtScale), in runs of steps up to
/// the next particle-flow step (where flow.apply runs, as in `veridem run`) or sample; calls
/// sample(world) every `sampleInterval` [s] (rounded to whole steps; 0: never). The particles an
/// outlet retired leave the store before each sample and at the end (compactRetiredParticles). Throws
/// SimulationError if the state becomes non-finite or an overlap exceeds the scene's
/// max_overlap_fraction.
void runScene(io::DemScene& scene, Real duration, Real sampleInterval, const CaseContext& context,
              const std::string& label, const std::function<void(const World&)>& sample);

/// The height [m] of the highest point of the free particles (centre z + radius); -inf if none.
Real topOfParticles(const World& world);

/// A pour into a vertical cylinder (axis z through x = y = 0) in stages: at the start of each stage
/// the scene's first inserter (a cylinder region, count mode) is moved to `gap` [m] above the
/// current top of the particles and owes `perStage` more particles, all inserted at once; the stage
/// then runs for `stageTime` [s], so that each batch falls at most its region's height plus `gap`.
struct StagedPour
{
    int stages = 1;
    std::size_t perStage = 0;
    Real stageTime = 0;  // [s]
    Real gap = 0;        // [m] between the top of the particles and the region's bottom
    Real floor = 0;      // [m] the top when there are no particles yet
    Real sampleInterval; // [s] between calls of sample
};

/// Runs the staged pour; sample(stage, world) every sampleInterval within each stage.
void pourInStages(io::DemScene& scene, const StagedPour& pour, const CaseContext& context,
                  const std::string& label, const std::function<void(int, const World&)>& sample);

/// Least-squares line y = slope x + intercept with its coefficient of determination R^2.
struct LineFit
{
    Real slope = 0;
    Real intercept = 0;
    Real r2 = 0;
};
LineFit fitLine(const std::vector<Real>& x, const std::vector<Real>& y);

/// Weighted least-squares line y = slope x + intercept, each point weighted by 1/sigma^2 (sigma
/// its standard error, > 0), with the parameters' variances and covariance (from the sigmas alone,
/// not rescaled by the misfit) and the misfit chi^2 = sum ((y - line) / sigma)^2.
struct WeightedLineFit
{
    Real slope = 0;
    Real intercept = 0;
    Real slopeVariance = 0;
    Real interceptVariance = 0;
    Real covariance = 0;
    Real chi2 = 0;
};
WeightedLineFit fitLineWeighted(const std::vector<Real>& x, const std::vector<Real>& y,
                                const std::vector<Real>& sigma);

/// Mean of v and its standard error (sample standard deviation / sqrt(n); 0 if n < 2).
struct MeanWithError
{
    Real mean = 0;
    Real standardError = 0;
};
MeanWithError meanWithError(const std::vector<Real>& v);

/// CPU time [s] of the calling thread (a case runs on one thread).
Real threadCpuSeconds();

/// Mean of v[from, to).
Real meanOf(const std::vector<Real>& v, std::size_t from = 0, std::size_t to = SIZE_MAX);

/// printf-style formatting into a std::string (notes).
std::string formatted(const char* format, ...) __attribute__((format(printf, 1, 2)));

} // namespace veridem::verify
