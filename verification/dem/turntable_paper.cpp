// Paper Tests 2-5 (Figs. 4-9) and a centred orbit growing under rolling friction, on the flat
// rotating turntable (BENCHMARKS 1b). Each case runs the DEM ball and, in lock-step, the rigid
// rolling equations (T2, turntable_theory.h) with RK4 from the same initial state, and compares
// the whole orbit-centre path c(t) = r + k x v / omega_o, not only end values.
//
// Set-ups (captions; lab-frame v0; no-slip start with zero spin about k; table Omega about +k):
//   T2   Omega 10,   tilt 0.17 deg toward 135 deg, muR 1.5e-6, r0 0.04 @ 180, v0 0.107 @ 270
//   T3   Omega 17.6, tilt 0.52 deg toward  90 deg, muR 1.5e-6, r0 0.01 @   0, v0 0.008 @  90
//   T3b  as T3 with muR 2.5e-5
//   T4   Omega 17.6, tilt 0.17 deg toward  90 deg, muR 1.5e-6, r0 0.13 @ 180, v0 0.009 @ 270
//   T4b  as T4, flat
//   T5   Omega 17.6, tilt 0.10 deg (and 0.010 deg) toward 180 deg, muR 1.5e-6, r0 0.08 @ 45, v0 0
//   growth  Omega 17.6, flat, muR 1.5e-6, r0 0.05 @ 0, v0 = omega_o k x r0 (orbit centred on the axis)
// Runs end when the theory's ball reaches the table edge (|r| = R - a) or at the case's duration.
//
// Time step: dt = 1e-5 s = t_c / 91 (t_c = 0.911 ms for k = 1e5, BENCHMARKS 1b spec 1b).
//
// Tolerances:
//   * far-field centre drift: BENCHMARKS spec 1b, 3 % in magnitude and 2 deg in direction. The
//     closed form V_t k x g - V_r c_hat neglects terms of order ((5/7) rho / |c|)^2 and the twist
//     dilution of the rolling torque (< 2 %), hence the allowance.
//   * inward drift (T4b) and radius growth: BENCHMARKS spec 1b, 5 %.
//   * whole path against the RK4 rigid-rolling theory: 0.5 mm, the spec's bound for the orbit
//     centre over 10 orbits (T1b). The DEM departs from rigid rolling only through the contact's
//     elasticity (overlap / a ~ 1e-4, tangential micro-slip F / kt ~ 1e-8 m) and O(dt^2) errors, so
//     the measured deviation is expected orders of magnitude below it; it is printed.
#include "dem/models/normal.h"
#include "turntable.h"
#include "turntable_theory.h"

#include <algorithm>
#include <limits>
#include <sstream>

namespace veridem::verify
{
namespace
{

constexpr Real kStep = 1e-5;          // DEM time step [s]
constexpr Real kSample = 0.01;        // sampling interval of the comparison [s]
constexpr Real kTheoryStep = 1e-3;    // RK4 step of the theory [s]
constexpr Real kPathTolerance = 5e-4; // [m]

struct PaperTest
{
    TurntableSetup setup;
    Real maxDuration = 60;        // [s]
    Real benchmarkLeaveTime = -1; // BENCHMARKS 1b table "leaves" [s]; < 0: not given
    bool farFieldDrift = false;   // spec T2/T3/T3b/T4 (and T5)
    bool inwardDrift = false;     // spec T4b
    bool radiusGrowth = false;    // spec "radius growth"
    bool approach = false;        // T5 at 0.010 deg: axis crossing and approach point
};

template <typename... Args> std::string format(const char* fmt, Args... args)
{
    char buffer[320];
    std::snprintf(buffer, sizeof buffer, fmt, static_cast<double>(args)...);
    return buffer;
}

Real wrapDegrees(Real d)
{
    return d - 360.0 * std::round(d / 360.0);
}

CaseResult runPaperTest(const PaperTest& test, const CaseContext& context, const std::string& label)
{
    const TurntableSetup& s = test.setup;
    World world = turntableWorld(s);
    const TableFrame f = tableFrame(s);
    const Real a = kFlatBallRadius;
    const Real omegaOrbit = 2.0 / 7.0 * s.omega, period = 2 * kPi / omegaOrbit;

    const Vec3 gravityPlane = world.gravity - dot(world.gravity, f.k) * f.k;
    RollingTableParams theoryParams{
        s.omega, {f.u(gravityPlane), f.v(gravityPlane), 0}, -dot(world.gravity, f.k), s.rollingFriction, a,
        true};
    RollingTableParams printedParams = theoryParams; // BENCHMARKS T2 as printed: no twist torque
    printedParams.twist = false;
    const auto demState = [&](const World& w)
    {
        const auto& p = w.particles;
        return RollingTableState{{f.u(p.position[0]), f.v(p.position[0]), 0},
                                 {f.u(p.velocity[0]), f.v(p.velocity[0]), 0},
                                 dot(p.angularVelocity[0], f.k)};
    };
    const RollingTableState start = demState(world);
    const int substeps = static_cast<int>(std::lround(kSample / kTheoryStep));
    const auto advance = [&](const RollingTableParams& p, RollingTableState x)
    {
        for (int i = 0; i < substeps; ++i)
            x = rollingTableStep(p, x, kTheoryStep);
        return x;
    };

    // The run ends when the theory's ball reaches the table edge, |r| = R - a.
    const auto edgeTime = [&](const RollingTableParams& p)
    {
        RollingTableState x = start;
        for (Real t = 0; t < test.maxDuration + 1; t += kSample)
        {
            x = advance(p, x);
            if (length(x.r) > s.tableRadius - a)
                return t + kSample;
        }
        return std::numeric_limits<Real>::infinity();
    };
    const Real leaveTime = edgeTime(theoryParams);
    const Real duration = std::min(test.maxDuration, kSample * std::floor((leaveTime - 0.1) / kSample));

    // Rigid rolling needs a friction force F = m (dv/dt - g_plane) within mu N (Coulomb). Beyond it
    // the ball slides and the theory no longer applies: e.g. a centred orbit at Omega = 17.6 rad/s
    // can roll only while rho < (7/2) mu g / (Omega omega_o) = 58 mm.
    Real maxFrictionUse = 0;
    {
        RollingTableState x = start;
        for (Real t = 0; t < duration; t += kSample)
        {
            const Vec3 force =
                rollingTableRate(theoryParams, x).v - theoryParams.gravityInPlane; // per unit mass
            maxFrictionUse = std::max(
                maxFrictionUse, length(force) / (flatTurntableBall().friction * theoryParams.gravityNormal));
            x = advance(theoryParams, x);
        }
    }

    // Lock-step run: every kSample the DEM state is compared with both theories.
    std::vector<Real> time;
    std::vector<RollingTableState> dem, theory, printed;
    RollingTableState theoryState = start, printedState = start;
    const auto sampleSteps = static_cast<std::uint64_t>(std::llround(kSample / kStep));
    time.push_back(0);
    dem.push_back(start);
    theory.push_back(start);
    printed.push_back(start);
    runFor(world, duration, kStep, context, label,
           [&](const World& w)
           {
               if (w.stepCount % sampleSteps != 0)
                   return;
               theoryState = advance(theoryParams, theoryState);
               printedState = advance(printedParams, printedState);
               time.push_back(w.time);
               dem.push_back(demState(w));
               theory.push_back(theoryState);
               printed.push_back(printedState);
           });
    const std::size_t n = time.size();

    std::vector<Vec3> centre(n), centreTheory(n);
    std::vector<Real> rho(n), rhoTheory(n);
    Real maxCentreError = 0, maxPathError = 0, maxPrintedGap = 0;
    for (std::size_t i = 0; i < n; ++i)
    {
        centre[i] = orbitCentre(dem[i], s.omega);
        centreTheory[i] = orbitCentre(theory[i], s.omega);
        rho[i] = orbitRadius(dem[i], s.omega);
        rhoTheory[i] = orbitRadius(theory[i], s.omega);
        maxCentreError = std::max(maxCentreError, length(centre[i] - centreTheory[i]));
        maxPathError = std::max(maxPathError, length(dem[i].r - theory[i].r));
        maxPrintedGap = std::max(maxPrintedGap, length(centreTheory[i] - orbitCentre(printed[i], s.omega)));
    }

    CaseResult r;
    // Contact time of the ball on the table, t_c = pi / (omega_n sqrt(1 - zeta^2)).
    const Real mass = sphereMass(flatTurntableBall().density, a);
    const Real zeta = dem::dampingRatioFromRestitution(flatTurntableBall().restitution);
    const Real contactTime = kPi / (std::sqrt(s.stiffness / mass) * std::sqrt(1 - zeta * zeta));
    r.notes.push_back(
        format("k = %.0e N/m, dt = %.0e s (t_c/%.0f); run %.2f s = %.1f orbits; samples every %.2f s",
               s.stiffness, kStep, contactTime / kStep, duration, duration / period, kSample));
    if (std::isfinite(leaveTime))
        r.notes.push_back(format("theory: the ball reaches the table edge at %.2f s (T2 as printed: %.2f s; "
                                 "BENCHMARKS 1b table: %.1f s)",
                                 leaveTime, edgeTime(printedParams), test.benchmarkLeaveTime));
    r.notes.push_back(format("orbit radius rho: %.3f mm at the start, %.3f mm at the end (theory %.3f mm)",
                             1e3 * rho.front(), 1e3 * rho.back(), 1e3 * rhoTheory.back()));
    r.notes.push_back(format("rigid rolling needs at most %.3f of the available friction mu N along the run "
                             "(the theory holds while < 1)",
                             maxFrictionUse));
    r.notes.push_back(
        format("theory with the engine's torque (twist included, s0 = 0) vs BENCHMARKS T2 as printed "
               "(rolling part only): orbit centres differ by at most %.3g mm over the run",
               1e3 * maxPrintedGap));

    r.quantities.push_back(absoluteQuantity("max |c - c_theory| over the run", "m", 0, maxCentreError,
                                            kPathTolerance,
                                            "orbit-centre path vs RK4 rigid rolling (T2 + twist) sampled "
                                            "every 0.01 s; 0.5 mm = spec 1b centre bound"));
    r.quantities.push_back(absoluteQuantity("max |r - r_theory| over the run", "m", 0, maxPathError,
                                            kPathTolerance,
                                            "ball path vs RK4 rigid rolling; same bound as the centre"));

    // Closed-form drift velocities (BENCHMARKS 1b guiding-centre equations).
    const Real alpha = degToRad(s.tiltDegrees);
    const Real tiltDrift = 2.5 * kG * std::sin(alpha) / s.omega;                               // V_t
    const Real frictionDrift = 2.5 * s.rollingFriction * kG * std::cos(alpha) / (a * s.omega); // V_r
    const Vec3 downhill = normalizedOrZero(theoryParams.gravityInPlane);
    const Vec3 tiltDirection = kCross(downhill); // k x g_hat

    if (test.farFieldDrift)
    {
        // Longest stretch with |c| > 3 rho (far field); c is averaged over one orbit at each end so
        // that the orbital wobble of c cancels, and the closed form is averaged over the same span.
        std::size_t bestStart = 0, bestLength = 0;
        for (std::size_t i = 0; i < n;)
        {
            if (length(centre[i]) <= 3 * rho[i])
            {
                ++i;
                continue;
            }
            std::size_t j = i;
            while (j < n && length(centre[j]) > 3 * rho[j])
                ++j;
            if (j - i > bestLength)
            {
                bestStart = i;
                bestLength = j - i;
            }
            i = j;
        }
        const auto orbitSamples = static_cast<std::size_t>(std::lround(period / kSample));
        if (bestLength < 2 * orbitSamples)
        {
            r.notes.push_back(
                format("far-field drift not checked: the longest stretch with |c| > 3 rho lasts %.2f s, "
                       "less than 2 orbits (%.2f s)",
                       Real(bestLength) * kSample, 2 * period));
        }
        else
        {
            const std::size_t i0 = bestStart, i1 = bestStart + bestLength - orbitSamples; // window starts
            auto meanCentre = [&](std::size_t from)
            {
                Vec3 sum;
                for (std::size_t k = from; k < from + orbitSamples; ++k)
                    sum += centre[k];
                return sum / Real(orbitSamples);
            };
            const Vec3 measured = (meanCentre(i1) - meanCentre(i0)) / (time[i1] - time[i0]);
            Vec3 expected;
            for (std::size_t k = i0 + orbitSamples / 2; k < i1 + orbitSamples / 2; ++k)
                expected += tiltDrift * tiltDirection - frictionDrift * normalizedOrZero(centre[k]);
            expected = expected / Real(i1 - i0);
            const Real expectedAngle =
                std::fmod(std::atan2(expected.y, expected.x) * 180 / kPi + 360.0, 360.0);
            const Real measuredAngle =
                expectedAngle + wrapDegrees(std::atan2(measured.y, measured.x) * 180 / kPi - expectedAngle);
            r.notes.push_back(
                format("far-field window %.2f-%.2f s; V_t = %.4g mm/s toward k x g, V_r = %.4g mm/s",
                       time[i0], time[i1] + period, 1e3 * tiltDrift, 1e3 * frictionDrift));
            r.quantities.push_back(relativeQuantity(
                "far-field centre drift speed", "m/s", length(expected), length(measured), 0.03,
                "spec 1b: |V_t k x g - V_r c_hat| to 3 % (neglects ((5/7) rho/|c|)^2 and twist dilution)"));
            r.quantities.push_back(absoluteQuantity("far-field centre drift direction", "deg", expectedAngle,
                                                    measuredAngle, 2.0, "spec 1b: direction to 2 deg"));
        }
    }
    if (test.inwardDrift)
    {
        std::vector<Real> distance(n);
        for (std::size_t i = 0; i < n; ++i)
            distance[i] = length(centre[i]);
        r.quantities.push_back(relativeQuantity("inward centre drift -d|c|/dt", "m/s", frictionDrift,
                                                -fitSlope(time, distance), 0.05,
                                                "spec 1b T4b: V_r = (5/2) muR g / (a Omega) to 5 %"));
    }
    if (test.radiusGrowth)
    {
        Real maxCentre = 0;
        for (const Vec3& c : centre)
            maxCentre = std::max(maxCentre, length(c));
        std::vector<Real> rhoTheoryFit(rhoTheory);
        r.notes.push_back(
            format("theory with twist dilution: d rho/dt = %.5g mm/s (closed form V_r = %.5g mm/s)",
                   1e3 * fitSlope(time, rhoTheoryFit), 1e3 * frictionDrift));
        r.quantities.push_back(relativeQuantity("radius growth d rho/dt", "m/s", frictionDrift,
                                                fitSlope(time, rho), 0.05,
                                                "spec 1b: centred orbit grows at V_r to 5 %"));
        r.quantities.push_back(absoluteQuantity(
            "max |c| (centre stays on the axis)", "m", 0, maxCentre, 1e-3,
            "c wobbles by V_r / omega_o ~ 0.07 mm about the axis; 1 mm allows no net drift over the run"));
    }
    if (test.approach)
    {
        // The orbit centre's first crossing of the x axis (c_y = 0) and its closest approach to
        // the spin axis: points on the path, so the path bound applies to them.
        auto crossingX = [&](const std::vector<Vec3>& c)
        {
            for (std::size_t i = 1; i < c.size(); ++i)
                if (c[i - 1].y > 0 && c[i].y <= 0)
                {
                    const Real w = c[i - 1].y / (c[i - 1].y - c[i].y);
                    return std::pair{c[i - 1].x + w * (c[i].x - c[i - 1].x), time[i - 1] + w * kSample};
                }
            return std::pair{std::numeric_limits<Real>::quiet_NaN(), std::numeric_limits<Real>::quiet_NaN()};
        };
        auto closest = [&](const std::vector<Vec3>& c)
        {
            std::size_t best = 0;
            for (std::size_t i = 1; i < c.size(); ++i)
                if (length(c[i]) < length(c[best]))
                    best = i;
            return best;
        };
        const auto [xDem, tDem] = crossingX(centre);
        const auto [xTheory, tTheory] = crossingX(centreTheory);
        const std::size_t kDem = closest(centre), kTheory = closest(centreTheory);
        std::vector<Vec3> printedCentre(n);
        for (std::size_t i = 0; i < n; ++i)
            printedCentre[i] = orbitCentre(printed[i], s.omega);
        const auto [xPrinted, tPrinted] = crossingX(printedCentre);
        const std::size_t kPrinted = closest(printedCentre);
        r.notes.push_back(
            format("centre crosses the x axis at x = %.2f mm, t = %.1f s (DEM); theory %.2f mm, %.1f s",
                   1e3 * xDem, tDem, 1e3 * xTheory, tTheory));
        r.notes.push_back(format(
            "closest approach to the axis: DEM (%.2f, %.2f) mm at %.1f s; theory %.2f mm",
            1e3 * centre[kDem].x, 1e3 * centre[kDem].y, time[kDem], 1e3 * length(centreTheory[kTheory])));
        r.notes.push_back(
            format("BENCHMARKS T2 as printed (no twist torque): crossing at x = %.2f mm, t = %.1f s; "
                   "closest approach %.2f mm at %.1f s (BENCHMARKS: ~16 mm, ~145 s; ~2 mm, ~240 s)",
                   1e3 * xPrinted, tPrinted, 1e3 * length(printedCentre[kPrinted]), time[kPrinted]));
        r.quantities.push_back(absoluteQuantity("x of the centre's x-axis crossing", "m", xTheory, xDem,
                                                kPathTolerance,
                                                "a point of the centre path: the path bound"));
        r.quantities.push_back(absoluteQuantity(
            "closest approach of c to the axis", "m", length(centreTheory[kTheory]), length(centre[kDem]),
            kPathTolerance, "a point of the centre path: the path bound"));
    }

    // Series for the report: ball path and orbit centre, DEM and theory, every 0.02-0.05 s.
    const std::size_t stride = duration > 60 ? 5 : 2;
    Series path{"trajectory",
                {"t", "x", "y", "x_theory", "y_theory", "cx", "cy", "cx_theory", "cy_theory", "rho",
                 "rho_theory", "x_t2", "y_t2"},
                {}};
    for (std::size_t i = 0; i < n; i += stride)
        path.rows.push_back({time[i], dem[i].r.x, dem[i].r.y, theory[i].r.x, theory[i].r.y, centre[i].x,
                             centre[i].y, centreTheory[i].x, centreTheory[i].y, rho[i], rhoTheory[i],
                             printed[i].r.x, printed[i].r.y});
    r.series.push_back(std::move(path));
    return r;
}

TurntableSetup setup(Real omega, Real tilt, Real downhill, Real muR, Real r0, Real angle0, Real v0,
                     Real direction0)
{
    TurntableSetup s;
    s.omega = omega;
    s.tiltDegrees = tilt;
    s.downhillDegrees = downhill;
    s.rollingFriction = muR;
    s.initialRadius = r0;
    s.initialAngleDegrees = angle0;
    s.initialSpeed = v0;
    s.initialDirectionDegrees = direction0;
    return s;
}

PaperTest testT2(Real stiffness = 1e5)
{
    PaperTest t{.setup = setup(10, 0.17, 135, 1.5e-6, 0.04, 180, 0.107, 270),
                .maxDuration = 60,
                .benchmarkLeaveTime = 24.1,
                .farFieldDrift = true};
    t.setup.stiffness = stiffness;
    return t;
}
PaperTest testT3(Real muR, Real leave)
{
    return {.setup = setup(17.6, 0.52, 90, muR, 0.01, 0, 0.008, 90),
            .maxDuration = 60,
            .benchmarkLeaveTime = leave,
            .farFieldDrift = true};
}
PaperTest testT4(Real tilt)
{
    return {.setup = setup(17.6, tilt, 90, 1.5e-6, 0.13, 180, 0.009, 270),
            .maxDuration = tilt > 0 ? 60.0 : 180.0,
            .benchmarkLeaveTime = tilt > 0 ? 17.1 : -1.0,
            .farFieldDrift = tilt > 0,
            .inwardDrift = tilt == 0};
}
PaperTest testT5(Real tilt)
{
    return {.setup = setup(17.6, tilt, 180, 1.5e-6, 0.08, 45, 0, 0),
            .maxDuration = tilt > 0.05 ? 150.0 : 300.0,
            .benchmarkLeaveTime = tilt > 0.05 ? 110.0 : -1.0,
            .farFieldDrift = true,
            .approach = tilt < 0.05};
}
PaperTest testGrowth()
{
    // BENCHMARKS proposes r0 = 0.05 m; rolling is possible only while rho < (7/2) mu g / (Omega omega_o)
    // = 58.2 mm (mu = 0.15): that orbit reaches the limit after 25 s, then slides and is thrown off
    // the table (the DEM shows it). r0 = 0.04 m for 40 s ends at rho = 53 mm (92 % of the friction).
    const Real omega = 17.6, r0 = 0.04;
    return {.setup = setup(omega, 0, 0, 1.5e-6, r0, 0, 2.0 / 7.0 * omega * r0, 90),
            .maxDuration = 40,
            .radiusGrowth = true};
}

} // namespace

#define VERIDEM_TURNTABLE_CASE(caseName, labelList, text, ref, make)                                         \
    VERIDEM_CASE({.name = caseName,                                                                          \
                  .summary = text,                                                                           \
                  .reference = ref,                                                                          \
                  .labels = labelList,                                                                       \
                  .run = [](const CaseContext& c) { return runPaperTest(make, c, caseName); }})

VERIDEM_TURNTABLE_CASE("turntable_t2_tilted", (std::vector<std::string>{"dem", "quick", "paper"}),
                       "paper Test 2: 0.17 deg tilt toward 135 deg, centre drifts along k x g (225 deg)",
                       "Xiang et al. Fig. 4; Soodak & Tiersten 1996; BENCHMARKS 1b", testT2());
// BENCHMARKS 1b: the stiffness is truncated in the paper's table; report 1e4 as well as 1e5 N/m
// (dt = 1e-5 s is then t_c/290). The orbit results must not depend on it while overlap << a.
VERIDEM_TURNTABLE_CASE("turntable_t2_k1e4", (std::vector<std::string>{"dem", "quick", "paper"}),
                       "paper Test 2 with k = 1e4 N/m: the drift does not depend on the contact stiffness",
                       "Xiang et al. Fig. 4 (Table 1 stiffness truncated); BENCHMARKS 1b", testT2(1e4));
VERIDEM_TURNTABLE_CASE("turntable_t3_tilted", (std::vector<std::string>{"dem", "quick", "paper"}),
                       "paper Test 3: 0.52 deg tilt toward 90 deg, centre drifts west",
                       "Xiang et al. Fig. 5; E&T 1994 Fig. 5; BENCHMARKS 1b", testT3(1.5e-6, 16.6));
VERIDEM_TURNTABLE_CASE("turntable_t3b_rolling_friction", (std::vector<std::string>{"dem", "quick", "paper"}),
                       "paper Test 3 with muR = 2.5e-5 m: orbit grows while the centre drifts",
                       "Xiang et al. Fig. 6; Soodak & Tiersten 1996; BENCHMARKS 1b", testT3(2.5e-5, 24.5));
VERIDEM_TURNTABLE_CASE("turntable_t4_tilted", (std::vector<std::string>{"dem", "quick", "paper"}),
                       "paper Test 4: 0.17 deg tilt toward 90 deg far from the axis, slow drift west",
                       "Xiang et al. Fig. 7; E&T 1994; BENCHMARKS 1b", testT4(0.17));
VERIDEM_TURNTABLE_CASE("turntable_t4b_flat", (std::vector<std::string>{"dem", "paper"}),
                       "paper Test 4 flat: centre drifts toward the axis at V_r = 0.329 mm/s",
                       "Xiang et al. Fig. 8; E&T 1994 Fig. 7; BENCHMARKS 1b", testT4(0));
VERIDEM_TURNTABLE_CASE("turntable_t5_tilt_0p10", (std::vector<std::string>{"dem", "paper"}),
                       "paper Test 5 at the caption's 0.10 deg: tilt drift dominates, no approach point",
                       "Xiang et al. Fig. 9; BENCHMARKS 1b", testT5(0.10));
VERIDEM_TURNTABLE_CASE("turntable_t5_tilt_0p010", (std::vector<std::string>{"dem", "paper"}),
                       "paper Test 5 at 0.010 deg: curved approach to a point near the axis, then growth",
                       "Xiang et al. Fig. 9; E&T 1994 approach-to-the-centre; BENCHMARKS 1b", testT5(0.010));
VERIDEM_TURNTABLE_CASE("turntable_radius_growth", (std::vector<std::string>{"dem", "quick", "paper"}),
                       "orbit centred on the axis grows at d rho/dt = V_r under rolling friction",
                       "Soodak & Tiersten 1996; BENCHMARKS 1b", testGrowth());

} // namespace veridem::verify
