// Paper section 4.2 (Figs. 10-12): a ball released at rest at r = 1 m in the spherically concave
// dish rotating at Omega climbs to the co-rotating height h_c* = (R - a) - g/Omega^2 (Omega > Omega_c)
// or ends near the bottom (Omega < Omega_c). BENCHMARKS 1c, spec 1c: 600 s per Omega, the final
// height is the mean over the last 20 s.
//
// Pass criteria (spec 1c):
//   Omega > Omega_c: h_final in [h_c* - dh_band - 0.05 m, h_c* + 0.05 m]. The type-A torque brings
//     the ball into the rolling-resistance band dh_band = rho_s muR' / sin(theta*) from below and
//     then lets it creep toward h_c*; 0.05 m covers the elastic overlap (<= 1.7 mm at 10 rad/s) and
//     the orbit's residual oscillation. Written as a symmetric check about the band's centre.
//   Omega < Omega_c: r_final <= r_band = rho_s muR' / (1 - Omega^2 rho_s / g) and h_final <= 0.02 m.
// Release inside the bottom's band: above Omega_c the bottom is unstable, but within
//   r_b = rho_s muR' / (Omega^2 rho_s / g - 1)
// the outward drive per unit normal force is below muR' (same small-angle band as below Omega_c).
// At 0.8 rad/s r_b = 1.094 m > r0 = 1 m: the ball cannot climb (the reference integrator agrees),
// so that case checks r_final <= r_b instead, and a second 0.8 rad/s case releases at 2 m.
// Twist regression: with the rolling torque restricted to its rolling part (no twist resistance)
// the ball must lock far below h_c* at 0.9 rad/s (BENCHMARKS: 5.39 m), where the reference
// integrator with the same torque locks too; this documents why the default resists twist.
//
// Time step: dt = 5e-5 s = t_c / 58 (t_c = 2.90 ms for k = 1e3 N/m, m = 8.48e-4 kg; spec: <= t_c/50).
// The reference integrator (dish.h) starts from the DEM state at the end of the initial slide
// (when the contact-point slip falls below 1 mm/s) and runs with RK4, h = 1e-3 s.
#include "dish.h"

#include <algorithm>
#include <cstdio>
#include <limits>

namespace veridem::verify
{
namespace
{

constexpr Real kDishStep = 5e-5;    // [s]
constexpr Real kDishDuration = 600; // [s]
constexpr Real kDishSample = 0.1;   // [s]
constexpr Real kFinalWindow = 20;   // [s]
constexpr Real kTheoryStep = 1e-3;  // [s]

template <typename... Args> std::string format(const char* fmt, Args... args)
{
    char buffer[320];
    std::snprintf(buffer, sizeof buffer, fmt, static_cast<double>(args)...);
    return buffer;
}

struct DishRun
{
    std::vector<Real> time, x, y, h, hTheory, xTheory, yTheory, spin, spinTheory;
    Real slideEnd = -1;       // [s]
    Real theorySlipTime = -1; // first time the rolling reference needs more friction than mu N [s]
    Real maxOverlapRatio = 0; // overlap / a
    Real hFinal = 0, rFinal = 0, hTheoryFinal = 0, spinFinal = 0, spinTheoryFinal = 0;
};

DishRun runDish(const DishSetup& s, const CaseContext& context, const std::string& label)
{
    World world = dishWorld(s);
    const Real a = kDishBallRadius;
    const Vec3 centre{0, 0, kDishRadius};
    DishTheory theory{.omega = s.omega, .twist = s.twist};
    DishState theoryState;
    bool theoryStarted = false;
    const auto sampleSteps = static_cast<std::uint64_t>(std::llround(kDishSample / kDishStep));
    const int substeps = static_cast<int>(std::lround(kDishSample / kTheoryStep));

    DishRun run;
    const auto record = [&](const World& w)
    {
        const Vec3& p = w.particles.position[0];
        const Vec3 n = (p - centre) / length(p - centre);
        run.time.push_back(w.time);
        run.x.push_back(p.x);
        run.y.push_back(p.y);
        run.h.push_back(p.z - a);
        run.spin.push_back(dot(w.particles.angularVelocity[0], n));
        const Real nan = std::numeric_limits<Real>::quiet_NaN();
        if (theoryStarted)
        {
            const Vec3 q = centre + theoryState.x;
            run.hTheory.push_back(q.z - a);
            run.xTheory.push_back(q.x);
            run.yTheory.push_back(q.y);
            run.spinTheory.push_back(theoryState.spin);
        }
        else
        {
            run.hTheory.push_back(nan);
            run.xTheory.push_back(nan);
            run.yTheory.push_back(nan);
            run.spinTheory.push_back(nan);
        }
    };
    record(world);
    Real theoryTime = 0;
    runFor(world, kDishDuration, kDishStep, context, label,
           [&](const World& w)
           {
               run.maxOverlapRatio = std::max(run.maxOverlapRatio, w.health.maxOverlapRatio);
               if (!theoryStarted)
               {
                   const Vec3& p = w.particles.position[0];
                   const Vec3 n = (p - centre) / length(p - centre);
                   const Vec3 contact = p + a * n; // the engine's contact point (undeformed radius)
                   const Vec3 slip = w.particles.velocity[0] + cross(w.particles.angularVelocity[0], a * n) -
                                     dem::wallSurfaceVelocity(w.walls[0], contact);
                   // The engine takes the wall velocity at the half-step contact point, so a rolling
                   // ball shows an apparent slip of up to Omega |v| dt / 2 here.
                   if (length(slip) < 1e-3 + s.omega * length(w.particles.velocity[0]) * kDishStep)
                   {
                       theoryStarted = true;
                       run.slideEnd = w.time;
                       const Vec3 v = w.particles.velocity[0];
                       theoryState = {theory.rhoS * n, v - dot(v, n) * n,
                                      dot(w.particles.angularVelocity[0], n)};
                       theoryTime = w.time;
                   }
               }
               if (w.stepCount % sampleSteps != 0)
                   return;
               if (theoryStarted)
               {
                   // Advance the reference to this sample time.
                   const int steps = static_cast<int>(std::lround((w.time - theoryTime) / kTheoryStep));
                   const Real h = steps > 0 ? (w.time - theoryTime) / steps : 0;
                   for (int i = 0; i < steps; ++i)
                   {
                       theoryState = theory.step(theoryState, h);
                       // Friction demand of rigid rolling, F_t = m (dv/dt - g)_t against mu N.
                       const DishState rate = theory.rate(theoryState);
                       const Vec3 n = theoryState.x / length(theoryState.x);
                       Vec3 demand = rate.v - w.gravity;
                       demand -= dot(demand, n) * n;
                       const Real normal = dot(theoryState.v, theoryState.v) / theory.rhoS - kG * n.z;
                       if (run.theorySlipTime < 0 && length(demand) > dishBall().friction * normal)
                           run.theorySlipTime = theoryTime + (i + 1) * h;
                   }
                   theoryTime = w.time;
                   (void)substeps;
               }
               record(w);
           });

    std::size_t count = 0;
    for (std::size_t i = 0; i < run.time.size(); ++i)
        if (run.time[i] > kDishDuration - kFinalWindow + 1e-9)
        {
            run.hFinal += run.h[i];
            run.rFinal += std::hypot(run.x[i], run.y[i]);
            run.hTheoryFinal += run.hTheory[i];
            ++count;
        }
    run.hFinal /= Real(count);
    run.rFinal /= Real(count);
    run.hTheoryFinal /= Real(count);
    run.spinFinal = run.spin.back();
    run.spinTheoryFinal = run.spinTheory.back();
    return run;
}

Series trajectorySeries(const DishRun& run)
{
    Series s{
        "trajectory", {"t", "x", "y", "h", "x_theory", "y_theory", "h_theory", "spin", "spin_theory"}, {}};
    for (std::size_t i = 0; i < run.time.size(); i += 2)
        s.rows.push_back({run.time[i], run.x[i], run.y[i], run.h[i], run.xTheory[i], run.yTheory[i],
                          run.hTheory[i], run.spin[i], run.spinTheory[i]});
    return s;
}

CaseResult runDishCase(Real omega, Real releaseRadius, const CaseContext& context, const std::string& label,
                       Real meshEdge = 0)
{
    const Real a = kDishBallRadius, rhoS = kDishRadius - a;
    const Real muRPrime = dishBall().rollingFrictionLength / a;
    const Real omegaCritical = std::sqrt(kG / rhoS);
    const DishRun run =
        runDish({.omega = omega, .releaseRadius = releaseRadius, .meshEdge = meshEdge}, context, label);
    // Rolling-resistance band about the bottom (small angles): there the in-plane effective force
    // per unit normal force, |1 - Omega^2 rho_s / g| r / rho_s, is below muR'. Above Omega_c the
    // bottom is unstable, but a ball released inside this band is not driven out of it (the
    // rolling resistance exceeds the outward drive); spec 1c assumes a release outside it.
    const Real bandRadius = rhoS * muRPrime / std::fabs(1 - omega * omega * rhoS / kG);
    const Real hStar = dishEquilibriumHeight(omega);
    const Real hPaper = omega * omega * kDishRadius > kG ? kDishRadius - kG / (omega * omega) : 0.0;

    CaseResult r;
    r.notes.push_back(format("dt = %.0e s (t_c/%.0f), %.0f s; slide ends at %.3f s; max overlap/a = %.3f",
                             kDishStep, 2.90e-3 / kDishStep, kDishDuration, run.slideEnd,
                             run.maxOverlapRatio));
    if (run.theorySlipTime >= 0)
        r.notes.push_back(
            format("from t = %.1f s rigid rolling would need more friction than mu N: the DEM ball slides "
                   "again there, which the rolling reference cannot do, so the two paths part in time "
                   "(the end heights are compared with h_c*, not with the reference)",
                   run.theorySlipTime));
    if (omega > omegaCritical && releaseRadius <= bandRadius)
    {
        r.quantities.push_back(absoluteQuantity(
            "r_final", "m", 0, run.rFinal, bandRadius,
            format(
                "released at r0 = %.2f m inside the bottom's rolling-resistance band r_b = rho_s muR' / "
                "(Omega^2 rho_s / g - 1) = %.3f m: the outward drive never exceeds the rolling resistance, "
                "so the ball stays within r_b (spec 1c's climb to h_c* assumes r0 > r_b)",
                releaseRadius, bandRadius)));
        r.notes.push_back(
            format("r_final = %.4f m, h_final = %.4f m (h_c* = %.4f m is not reached); reference "
                   "integrator h(600 s) = %.4f m",
                   run.rFinal, run.hFinal, hStar, run.hTheoryFinal));
    }
    else if (omega > omegaCritical)
    {
        const Real cosTheta = kG / (omega * omega * rhoS);
        const Real band = rhoS * muRPrime / std::sqrt(1 - cosTheta * cosTheta);
        const Real low = hStar - band - 0.05, high = hStar + 0.05;
        Real enter = -1;
        for (std::size_t i = 0; i < run.time.size(); ++i)
            if (std::fabs(run.h[i] - hStar) <= band)
            {
                enter = run.time[i];
                break;
            }
        r.quantities.push_back(absoluteQuantity("h_final - (h_c* - dh/2)", "m", 0,
                                                run.hFinal - 0.5 * (low + high), 0.5 * (high - low),
                                                format("spec 1c: h_final in [h_c* - dh - 0.05, h_c* + 0.05] "
                                                       "= [%.3f, %.3f] m, with h_c* = %.4f m and the "
                                                       "rolling-resistance band dh = %.3f m",
                                                       low, high, hStar, band)));
        r.notes.push_back(
            format("h_final = %.4f m vs h_c* = %.4f m (error %.4f m = %.2f %%); paper eq. 5 h* = %.4f m",
                   run.hFinal, hStar, run.hFinal - hStar, 100 * (run.hFinal - hStar) / hStar, hPaper));
        r.notes.push_back(
            format("enters the band |h - h_c*| <= %.3f m at %.1f s; reference integrator h(600 s) = %.4f m",
                   band, enter, run.hTheoryFinal));
    }
    else
    {
        r.quantities.push_back(
            absoluteQuantity("r_final", "m", 0, run.rFinal, bandRadius,
                             "spec 1c: below Omega_c the ball ends inside r_band = rho_s muR' / "
                             "(1 - Omega^2 rho_s / g)"));
        r.quantities.push_back(
            absoluteQuantity("h_final", "m", 0, run.hFinal, 0.02, "spec 1c: h_final <= 0.02 m"));
        r.notes.push_back(format("r_final = %.4f m (r_band = %.3f m); reference integrator h(600 s) = %.4f m",
                                 run.rFinal, bandRadius, run.hTheoryFinal));
    }
    r.series.push_back(trajectorySeries(run));
    r.series.push_back(
        Series{"dish_final",
               {"omega", "h_final", "h_c_star", "h_paper", "r_final", "h_theory_final", "r_release"},
               {{omega, run.hFinal, hStar, hPaper, run.rFinal, run.hTheoryFinal, releaseRadius}}});
    return r;
}

// dish_mesh: the dish at 2 rad/s as a triangle mesh (meshedSphericalCap, edge 0.25 m, ~87,000
// triangles up to 86 deg) instead of the analytic sphere, with the same pass band. The facet error
// is the angle between a facet's normal and the sphere's at its points, at most ~ circumradius / R
// = 0.25 / (sqrt 3 * 20) = 7.2e-3 rad; it acts as a local slope error, and the type-A torque holds
// a ball wherever the in-plane drive per unit normal force is below muR' = muR / a = 1.67e-2, so a
// facet error below muR' shifts where the ball can be held by less than the band dh. The case
// measures the largest tilt on the mesh (1.0e-2 rad: the zipped rings' triangles are not all
// equilateral) and checks it is below muR', then the spec 1c band. The facets also make the
// orbit bumpy: a ball crossing an edge at speed v meets the next facet at a normal speed of about
// v times the dihedral angle (edge / R), 0.5 m/s at 40 m/s, so the largest overlap is ~5x the
// analytic dish's (printed in the first note).
constexpr Real kDishMeshEdge = 0.25; // [m]

CaseResult runDishMesh(const CaseContext& context)
{
    const Real omega = 2.0, muRPrime = dishBall().rollingFrictionLength / kDishBallRadius;
    const Vec3 centre{0, 0, kDishRadius};
    const dem::Wall cap = meshedSphericalCap(centre, kDishRadius, kMeshedDishPolar, kDishMeshEdge);
    CaseResult r = runDishCase(omega, 1.0, context, "dish_mesh", kDishMeshEdge);
    const Real tilt = largestFacetTilt(cap, centre);
    r.quantities.insert(r.quantities.begin(),
                        absoluteQuantity("largest facet tilt", "rad", 0, tilt, muRPrime,
                                         "below muR' = muR / a, the in-plane force per unit normal "
                                         "force that the rolling resistance holds (BENCHMARKS 1c band)"));
    const DishRun plane = runDish({.omega = omega, .releaseRadius = 1.0}, context, "dish_mesh (analytic)");
    r.notes.push_back(format("%.0f triangles of edge %.2f m up to %.0f deg; h_final on the analytic dish "
                             "%.4f m (mesh - analytic: %.4f m)",
                             Real(std::get<dem::MeshShape>(cap.shape).mesh->triangles.size()), kDishMeshEdge,
                             kMeshedDishPolar * 180 / kPi, plane.hFinal,
                             r.series.back().rows[0][1] - plane.hFinal));
    r.series.pop_back(); // its dish_final row: Fig. 12 is the analytic dish's sweep
    return r;
}

CaseResult runTwistRegression(const CaseContext& context)
{
    const Real omega = 0.9, a = kDishBallRadius, rhoS = kDishRadius - a;
    const Real muRPrime = dishBall().rollingFrictionLength / a;
    const DishRun run = runDish({.omega = omega, .twist = false}, context, "dish_twist_regression");
    const Real hStar = dishEquilibriumHeight(omega);
    const Real cosTheta = kG / (omega * omega * rhoS);
    const Real band = rhoS * muRPrime / std::sqrt(1 - cosTheta * cosTheta);
    CaseResult r;
    r.quantities.push_back(
        absoluteQuantity("h_final without twist resistance", "m", run.hTheoryFinal, run.hFinal, 0.3,
                         "vs the reference integrator with the same torque (no twist); 0.3 m keeps the lock "
                         "(2.5 m below h_c*) "
                         "distinct from the correct height while allowing for the non-smooth type-A torque"));
    r.quantities.push_back(absoluteQuantity(
        "h_final below the spec-1c band", "m", 0, std::max(0.0, run.hFinal - (hStar - band - 0.05)), 0,
        "the spurious lock must stay outside the pass band of the default model"));
    r.notes.push_back(
        format("h_c* = %.4f m; locks at %.4f m (BENCHMARKS: 5.39 m); spin about the normal at 600 s: "
               "DEM %.0f rad/s, reference %.0f rad/s (BENCHMARKS: ~2000 rad/s)",
               hStar, run.hFinal, run.spinFinal, run.spinTheoryFinal));
    r.series.push_back(trajectorySeries(run));
    return r;
}

} // namespace

#define VERIDEM_DISH_CASE(caseName, omega, release, labelList, text)                                         \
    VERIDEM_CASE({.name = caseName,                                                                          \
                  .summary = text,                                                                           \
                  .reference = "Xiang et al. eqs. 5-6, Figs. 10-12; BENCHMARKS 1c",                          \
                  .labels = labelList,                                                                       \
                  .run = [](const CaseContext& c) { return runDishCase(omega, release, c, caseName); }})

VERIDEM_DISH_CASE("dish_omega_0p5", 0.5, 1.0, (std::vector<std::string>{"dem", "paper"}),
                  "concave dish at 0.5 rad/s (< Omega_c): ball ends near the bottom (Fig. 10)");
VERIDEM_DISH_CASE("dish_omega_0p6", 0.6, 1.0, (std::vector<std::string>{"dem", "paper"}),
                  "concave dish at 0.6 rad/s (< Omega_c): ball ends near the bottom");
VERIDEM_DISH_CASE(
    "dish_omega_0p8", 0.8, 1.0, (std::vector<std::string>{"dem", "paper"}),
    "concave dish at 0.8 rad/s, r0 = 1 m inside the bottom's rolling-resistance band: stays near the bottom");
VERIDEM_DISH_CASE("dish_omega_0p8_release_2", 0.8, 2.0, (std::vector<std::string>{"dem", "paper"}),
                  "concave dish at 0.8 rad/s released at 2 m, outside the bottom's band: climbs to h_c*");
VERIDEM_DISH_CASE("dish_omega_0p9", 0.9, 1.0, (std::vector<std::string>{"dem", "paper"}),
                  "concave dish at 0.9 rad/s: ball climbs to h_c* (Fig. 11)");
VERIDEM_DISH_CASE("dish_omega_1", 1.0, 1.0, (std::vector<std::string>{"dem", "paper"}),
                  "concave dish at 1 rad/s: ball climbs to h_c*");
VERIDEM_DISH_CASE("dish_omega_1p5", 1.5, 1.0, (std::vector<std::string>{"dem", "paper"}),
                  "concave dish at 1.5 rad/s: ball climbs to h_c*");
VERIDEM_DISH_CASE("dish_omega_2", 2.0, 1.0, (std::vector<std::string>{"dem", "paper"}),
                  "concave dish at 2 rad/s: ball climbs to h_c*");
VERIDEM_DISH_CASE("dish_omega_3", 3.0, 1.0, (std::vector<std::string>{"dem", "paper"}),
                  "concave dish at 3 rad/s: ball climbs to h_c*");
VERIDEM_DISH_CASE("dish_omega_5", 5.0, 1.0, (std::vector<std::string>{"dem", "paper"}),
                  "concave dish at 5 rad/s: ball climbs to h_c*");
VERIDEM_DISH_CASE("dish_omega_7", 7.0, 1.0, (std::vector<std::string>{"dem", "paper"}),
                  "concave dish at 7 rad/s: ball climbs to h_c*");
VERIDEM_DISH_CASE("dish_omega_10", 10.0, 1.0, (std::vector<std::string>{"dem", "paper"}),
                  "concave dish at 10 rad/s: ball climbs to h_c* near the rim");

VERIDEM_CASE(
    {.name = "dish_mesh",
     .summary = "concave dish at 2 rad/s as a triangle mesh: ball climbs to h_c* (facet tilt < muR')",
     .reference = "Xiang et al. eq. 5, Figs. 10-12; BENCHMARKS 1c; Kremmer & Favier 2001",
     .labels = {"dem", "mesh"},
     .run = runDishMesh});

VERIDEM_CASE(
    {.name = "dish_twist_regression",
     .summary = "rolling torque without twist resistance locks the dish ball at a wrong height (0.9 rad/s)",
     .reference = "BENCHMARKS 1c consequence (i)",
     .labels = {"dem", "paper"},
     .run = runTwistRegression});

} // namespace veridem::verify
