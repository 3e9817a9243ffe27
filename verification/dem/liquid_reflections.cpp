// Beyond the paper: "Liquid Reflections" (scene in liquid_reflections.h). Seven acrylic balls
// released in a cluster on a turning concave dish collide while they slide, then each climbs to the
// co-rotating height of paper eq. 5; collisions do not change where a ball can co-rotate.
//
// Checks:
//   * every ball's final height (mean of the last 10 s of 90 s) lies in the spec-1c band
//     [h_c* - dh - 5 mm, h_c* + 5 mm], dh = rho_s muR' / sin(theta*) the rolling-resistance band;
//     5 mm (0.3 % of R, as spec 1c's 0.05 m is of its 20 m dish) covers the elastic overlap (5 um)
//     and the residual orbit oscillation;
//   * every ball co-rotates with the dish at the end: its orbital angular velocity about the axis
//     equals Omega to 1 % (inside the band the relative motion has decayed to a slow creep).
// Reported: the number of ball-ball collisions (contacts that form after the pair was apart by more
// than 0.1 % of a) and the largest overlap.
//
// Time step: the recommended tc/50 of dem::estimateTimeStep (pair contact tc = 1.26 ms).
#include "liquid_reflections.h"

#include <algorithm>
#include <cstdio>

namespace veridem::verify
{
namespace
{

template <typename... Args> std::string format(const char* fmt, Args... args)
{
    char buffer[320];
    std::snprintf(buffer, sizeof buffer, fmt, static_cast<double>(args)...);
    return buffer;
}

CaseResult runLiquidReflections(const CaseContext& context)
{
    const LiquidReflectionsScene scene;
    World world = liquidReflectionsWorld(scene);
    const Real dt = dem::estimateTimeStep(world, 1.0).recommended;
    const Real duration = 90, sample = 0.05, finalWindow = 10;
    const std::size_t n = world.particles.size();
    const Real a = scene.ballRadius, rhoS = scene.dishRadius - a;

    std::vector<char> apart(n * n, 1);
    int collisions = 0;
    Real maxOverlap = 0;
    Series paths{"trajectories_lab_first_20s", {"t"}, {}};
    Series dishPaths{"trajectories_dish_frame", {"t"}, {}};
    Series heights{"heights", {"t"}, {}};
    for (std::size_t i = 0; i < n; ++i)
    {
        paths.columns.push_back("x_" + std::to_string(i));
        paths.columns.push_back("y_" + std::to_string(i));
        dishPaths.columns.push_back("x_" + std::to_string(i));
        dishPaths.columns.push_back("y_" + std::to_string(i));
        heights.columns.push_back("h_" + std::to_string(i));
    }
    heights.columns.push_back("h_c_star");
    const Real hStar = rhoS - kG / (scene.omega * scene.omega);
    std::vector<Real> finalHeight(n, 0), finalRate(n, 0);
    int finalSamples = 0;
    const auto sampleSteps = static_cast<std::uint64_t>(std::llround(sample / dt));

    runFor(world, duration, dt, context, "liquid_reflections",
           [&](const World& w)
           {
               const auto& p = w.particles;
               for (std::size_t i = 0; i < n; ++i)
                   for (std::size_t j = i + 1; j < n; ++j)
                   {
                       const Real d = length(p.position[i] - p.position[j]);
                       maxOverlap = std::max(maxOverlap, 2 * a - d);
                       char& state = apart[i * n + j];
                       if (state && d < 2 * a)
                       {
                           ++collisions;
                           state = 0;
                       }
                       else if (!state && d > 2 * a * (1 + 1e-3))
                           state = 1;
                   }
               if (w.stepCount % sampleSteps != 0)
                   return;
               std::vector<Real> row{w.time}, hRow{w.time}, dishRow{w.time};
               const Real turn = scene.omega * w.time, c = std::cos(turn), sn = std::sin(turn);
               const bool last = w.time > duration - finalWindow;
               for (std::size_t i = 0; i < n; ++i)
               {
                   const Vec3& x = p.position[i];
                   row.push_back(x.x);
                   row.push_back(x.y);
                   dishRow.push_back(c * x.x + sn * x.y); // rotated by -Omega t: the dish's frame
                   dishRow.push_back(-sn * x.x + c * x.y);
                   hRow.push_back(x.z - a);
                   if (last)
                   {
                       finalHeight[i] += x.z - a;
                       finalRate[i] +=
                           (x.x * p.velocity[i].y - x.y * p.velocity[i].x) / (x.x * x.x + x.y * x.y);
                   }
               }
               finalSamples += last ? 1 : 0;
               hRow.push_back(hStar);
               if (w.time <= 20 + 1e-9)
                   paths.rows.push_back(std::move(row));
               dishPaths.rows.push_back(std::move(dishRow));
               heights.rows.push_back(std::move(hRow));
           });

    const Real cosTheta = kG / (scene.omega * scene.omega * rhoS);
    const Real band = rhoS * (acrylicBall().rollingFrictionLength / a) / std::sqrt(1 - cosTheta * cosTheta);
    const Real low = hStar - band - 5e-3, high = hStar + 5e-3, middle = 0.5 * (low + high);
    Real worstHeight = 0, worstRate = scene.omega, lowest = 1e9, highest = -1e9;
    for (std::size_t i = 0; i < n; ++i)
    {
        finalHeight[i] /= finalSamples;
        finalRate[i] /= finalSamples;
        lowest = std::min(lowest, finalHeight[i]);
        highest = std::max(highest, finalHeight[i]);
        if (std::fabs(finalHeight[i] - middle) > std::fabs(worstHeight))
            worstHeight = finalHeight[i] - middle;
        if (std::fabs(finalRate[i] - scene.omega) > std::fabs(worstRate - scene.omega))
            worstRate = finalRate[i];
    }
    CaseResult r;
    r.quantities.push_back(absoluteQuantity("worst ball: h_final - (h_c* - dh/2)", "m", 0, worstHeight,
                                            0.5 * (high - low),
                                            format("every ball in [h_c* - dh - 5 mm, h_c* + 5 mm] = [%.4f, "
                                                   "%.4f] m (h_c* = %.4f m, band dh = %.4f m)",
                                                   low, high, hStar, band)));
    r.quantities.push_back(relativeQuantity("worst ball: orbital angular velocity", "rad/s", scene.omega,
                                            worstRate, 0.01,
                                            "co-rotation with the dish at the end (last 10 s)"));
    r.notes.push_back(format(
        "%.0f balls, dt = %.3g s, %.0f s; %.0f ball-ball collisions; largest overlap %.3g mm "
        "(%.2f %% of a); final heights %.4f-%.4f m",
        Real(n), dt, duration, Real(collisions), 1e3 * maxOverlap, 100 * maxOverlap / a, lowest, highest));
    r.series.push_back(std::move(paths));
    r.series.push_back(std::move(dishPaths));
    r.series.push_back(std::move(heights));
    return r;
}

} // namespace

VERIDEM_CASE(
    {.name = "liquid_reflections",
     .summary = "seven acrylic balls on a turning concave dish collide, then each co-rotates at h_c*",
     .reference = "Lijn, Liquid Reflections (1966-68); Xiang et al. eq. 5; BENCHMARKS 1c",
     .labels = {"dem", "paper"},
     .run = runLiquidReflections});

} // namespace veridem::verify
