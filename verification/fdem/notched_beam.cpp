// Three-point bending of notched beams that crack (fdem/fracture/): the peak load against linear
// elastic fracture mechanics as the beam grows relative to the fracture process zone (Bazant's size
// effect law), with the crack starting at the notch tip.
#include "case.h"
#include "core/constants.h"
#include "fdem/mesher.h"
#include "fdem/time_step.h"
#include "fdem/world.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <sstream>

namespace veridem::verify
{
namespace
{

using namespace veridem::fdem;

constexpr Real kModulus = 1e10, kDensity = 2500, kTensile = 3e6, kEnergy = 50; // Pa, kg/m^3, Pa, J/m^2
constexpr Real kPoisson = 0.2;
constexpr Real kNotch = 0.5;                                                 // a0 / D
constexpr Real kSpanRatio = 4;                                               // S / D (ASTM E399 SENB)
constexpr Real kCharacteristic = kModulus * kEnergy / (kTensile * kTensile); // Irwin's l_ch [m]
constexpr Real kEdge = kCharacteristic / 8;                                  // element size h [m]

/// SENB geometry factor for S / W = 4 (Srawley 1976, as in ASTM E399 and Tada, Paris & Irwin, The
/// Stress Analysis of Cracks Handbook, 3rd ed., 2000): K_I = P S / (B W^{3/2}) f(a/W),
/// f(x) = 3 sqrt(x) [1.99 - x (1 - x)(2.15 - 3.93 x + 2.7 x^2)] / (2 (1 + 2 x)(1 - x)^{3/2}),
/// within 0.5 % for 0 <= x <= 1 [1].
Real senbFactor(Real x)
{
    return 3 * std::sqrt(x) * (1.99 - x * (1 - x) * (2.15 - 3.93 * x + 2.7 * x * x)) /
           (2 * (1 + 2 * x) * std::pow(1 - x, 1.5));
}

/// With sigma_N = P / D (per unit thickness) K_I = sigma_N sqrt(D) k, k = (S / D) f(a0 / D) [1].
Real lefmShape()
{
    return kSpanRatio * senbFactor(kNotch);
}

/// The beam S + 4 h long, D deep, h x h cells (alternate diagonals), with a zero-width notch of
/// depth a0 = D / 2 at mid-span: the nodes on x = x_c below the tip get a copy for the triangles on
/// the right, so the notch's faces are free edges meeting at the tip node (a sharp crack, as in LEFM).
TriangleMesh notchedBeamMesh(Real depth, int cells)
{
    const Real span = kSpanRatio * depth, length = span + 4 * kEdge, middle = 0.5 * length;
    TriangleMesh mesh = meshRectangle({0, 0}, {length, depth}, int(kSpanRatio) * cells + 4, cells);
    const Real tip = kNotch * depth, tolerance = 1e-6 * kEdge;
    std::vector<std::uint32_t> copy(mesh.points.size(), ~0u);
    for (auto& triangle : mesh.triangles)
    {
        const Vec2 centroid =
            (mesh.points[triangle[0]] + mesh.points[triangle[1]] + mesh.points[triangle[2]]) / 3.0;
        if (centroid.x < middle || centroid.y > tip)
            continue;
        for (auto& node : triangle)
        {
            const Vec2 p = mesh.points[node];
            if (std::abs(p.x - middle) > tolerance || p.y > tip - tolerance)
                continue;
            if (copy[node] == ~0u)
            {
                copy[node] = static_cast<std::uint32_t>(mesh.points.size());
                mesh.points.push_back(p);
            }
            node = copy[node];
        }
    }
    return mesh;
}

struct BeamRun
{
    int cells = 0;  // D / h
    Real depth = 0; // D [m]
    std::size_t triangles = 0;
    std::size_t joints = 0;
    Real peak = 0;           // largest load P [N/m]
    Real peakTime = 0;       // [s]
    Real initiationLoad = 0; // P when the first joint leaves damage 0 [N/m]
    Vec2 initiationAt{};     // that joint's midpoint (reference) [m]
    std::size_t broken = 0;  // at the end
    std::size_t offLine = 0; // broken joints farther than h / 2 from the mid-span line
    Real speed = 0;          // loading speed [m/s]
    Real dt = 0;             // [s]
    std::uint64_t steps = 0;
    double seconds = 0;
    Series series;
};

BeamRun runBeam(int cells, bool progress)
{
    BeamRun run;
    run.cells = cells;
    run.depth = cells * kEdge;
    const Real depth = run.depth, span = kSpanRatio * depth, middle = 0.5 * span + 2 * kEdge;
    const TriangleMesh mesh = notchedBeamMesh(depth, cells);
    run.triangles = mesh.triangles.size();
    const Real c = std::sqrt(kModulus / kDensity);
    // Viscosity damping the mesh's highest mode at 20 % (xi = eta omega_max / (2 E), omega_max ~ 2c/h):
    // it removes the element-scale ringing left by each joint's breaking; on the first bending mode
    // (omega_1 ~ 2 pi / (50 D / c)) that is 2e-3 % of critical.
    const Real viscosity = 0.2 * 2 * kModulus / (2 * c / kEdge);
    Material rock{kDensity, kModulus, kPoisson, viscosity, StressLaw::Linear, PlaneModel::Stress};
    rock.fracture.tensileStrength = kTensile;
    rock.fracture.fractureEnergy = rock.fracture.shearFractureEnergy = kEnergy;
    rock.fracture.cohesion = 3 * kTensile; // shear strength well above f_t: the beam fails in mode I
    rock.fracture.frictionAngle = degToRad(30.0);
    rock.fracture.penalty = 10 * kModulus;
    rock.fracture.curve = SofteningCurve::Linear; // the cohesive crack of Hillerborg et al. (1976)
    WorldSettings s;
    s.gravity = {0, 0};
    s.contact.normalPenalty = 10 * kModulus;
    s.contact.tangentialPenalty = 10 * kModulus;
    s.contact.friction = 0; // the supports are rollers (no axial restraint, no arching)
    const auto build = [&](World& world)
    {
        const auto m = world.addMaterial(rock, "rock");
        BodyDefinition beam{"beam", mesh, m};
        beam.cracks = true;
        // Joints on the edges of the ligament's strip (one cell each side of mid-span), from the
        // notch tip to the top row of cells (the loading point is left to crush elastically).
        beam.crackRegion = true;
        beam.crackMin = {middle - 1.01 * kEdge, kNotch * depth - 0.01 * kEdge};
        beam.crackMax = {middle + 1.01 * kEdge, depth - 0.99 * kEdge};
        const auto id = world.addBody(beam);
        for (const Real x : {middle - 0.5 * span, middle + 0.5 * span}) // rigid supports, 2 h wide
            world.addBody(
                {"support", meshRectangle({x - kEdge, -kEdge}, {2 * kEdge, kEdge}, 2, 1), m, {}, true});
        return id;
    };
    s.timeStep = 1;
    World probe(s);
    build(probe);
    s.timeStep = 0.8 * stableTimeStep(probe).limit;
    run.dt = s.timeStep;
    World world(s);
    const auto beam = build(world);
    // Load: the three top nodes at mid-span (a rigid flat 2 h wide) move down. The speed gives the
    // peak after ~12 periods of the first bending mode (T_1 ~ 50 D / c with the notch), for a peak
    // deflection estimated as 60 P_LEFM / E (the unnotched beam's P S^3 / (48 E I) = 16 P / E, times
    // ~3 for the notch and the cohesive zone); it is reached by 10 stages over 2 T_1 (a smooth start
    // leaves the bending mode nearly at rest).
    const Real kIc = std::sqrt(kModulus * kEnergy);
    const Real lefmLoad = kIc * std::sqrt(depth) / lefmShape();
    const Real period = 50 * depth / c;
    run.speed = 60 * lefmLoad / kModulus / (12 * period);
    std::vector<std::uint32_t> loaded;
    for (std::uint32_t n = 0; n < world.nodes().size(); ++n)
    {
        const Vec2 p = world.nodes().position[n];
        if (world.nodes().body[n] == beam && p.y > depth - 1e-6 * kEdge &&
            std::abs(p.x - middle) < 1.01 * kEdge)
            loaded.push_back(n);
    }
    run.joints = world.joints().size();
    run.series = {
        "notched_beam_" + std::to_string(cells), {"t_s", "deflection_m", "P_N_per_m", "broken"}, {}};
    const auto start = std::chrono::steady_clock::now();
    const int stages = 10;
    int stage = 0;
    Real deflection = 0;
    const Real endTime = 40 * period;
    std::size_t i = 0;
    while (world.time() < endTime)
    {
        if (stage < stages && world.time() >= stage * 2 * period / stages)
        {
            ++stage;
            const Real v = run.speed * 0.5 * (1 - std::cos(kPi * stage / stages));
            for (auto n : loaded)
                world.prescribeNode(n, {0, -v});
        }
        deflection += -world.nodes().velocity[loaded[0]].y * s.timeStep;
        world.step();
        Real load = 0;
        for (auto n : loaded)
            load += world.nodes().force[n].y;
        const Real t = world.time() - s.timeStep;
        if (load > run.peak)
        {
            run.peak = load;
            run.peakTime = t;
        }
        if (run.initiationLoad == 0)
        {
            const JointStore& joints = world.joints();
            for (std::size_t j = 0; j < joints.size(); ++j)
                if (joints.damage[j][0] > 0 || joints.damage[j][1] > 0)
                {
                    run.initiationLoad = load;
                    run.initiationAt = 0.5 * (world.nodes().referencePosition[joints.nodes[j][0]] +
                                              world.nodes().referencePosition[joints.nodes[j][1]]);
                    break;
                }
        }
        if (++i % 200 == 0)
            run.series.rows.push_back({t, deflection, load, double(world.fractureState().broken)});
        if (progress && i % 50000 == 0)
            std::fprintf(stderr,
                         "  notched beam D = %d h: t = %g s, P = %g N/m (peak %g), broken %zu, %.0f s\n",
                         cells, t, load, run.peak, world.fractureState().broken,
                         std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count());
        // Past the peak: stop once a joint has broken and the load has fallen to 40 % of the peak.
        if (world.fractureState().broken > 0 && load < 0.4 * run.peak && t > run.peakTime)
            break;
    }
    run.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    run.steps = world.stepCount();
    const JointStore& joints = world.joints();
    for (std::size_t j = 0; j < joints.size(); ++j)
        if (joints.broken[j])
        {
            ++run.broken;
            const Vec2 p = world.nodes().referencePosition[joints.nodes[j][0]];
            const Vec2 q = world.nodes().referencePosition[joints.nodes[j][1]];
            if (std::abs(0.5 * (p.x + q.x) - middle) > 0.5 * kEdge)
                ++run.offLine;
        }
    return run;
}

CaseResult notchedBeam(const CaseContext& context)
{
    // Three-point bending, S = 4 D, notch a0 = D / 2, plane stress, per unit thickness, on three
    // geometrically similar beams D = 8, 16, 32 h (h = l_ch / 8, l_ch = E G_f / f_t^2 = 55.6 mm: the
    // same mesh around the process zone in each). Nominal strength sigma_N = P / D.
    // LEFM (sharp crack, K_Ic = sqrt(E' G_f), E' = E in plane stress): sigma_N = K_Ic / (k sqrt(D)),
    // k = (S / D) f(a0 / D) (senbFactor). The process zone ahead of the notch acts as a longer crack,
    // so the cohesive beam is weaker than LEFM predicts for its notch, the more so the smaller it is.
    // Bazant's size effect law (Bazant & Planas, Fracture and Size Effect in Concrete, 1998, ch. 6):
    // sigma_N = B f_t / sqrt(1 + D / D0), i.e. 1 / sigma_N^2 = (1 + D / D0) / (B f_t)^2, linear in D;
    // its large-size asymptote is LEFM, so the slope is k^2 / K_Ic^2 (= g(a0) / (E' G_f)) and
    // D0 = c_f g'(a0) / g(a0) follows the process zone's length c_f.
    // Criteria, chosen before running:
    //  - the crack starts at the notch tip: the first joint to leave damage 0 is the one above the tip
    //    (midpoint within h of (x_c, a0 + h/2)), and the broken joints lie on the mid-span line;
    //  - the straight-line fit of 1 / sigma_N^2 against D has the LEFM slope within 15 %: Bazant's law
    //    is the first two terms of the expansion in c_f / D, and the sizes reach D / D0 of a few
    //    only, so the next term (c_f / D)^2 shifts a three-point fit by ~10 %;
    //  - P / P_LEFM stays below 1 and rises with size (Bazant: sqrt((D/D0) / (1 + D/D0))).
    CaseResult result;
    const std::vector<int> cells{8, 16, 32};
    std::vector<BeamRun> runs(cells.size());
    context.forEach(cells.size(),
                    [&](std::size_t m)
                    {
                        runs[m] = runBeam(cells[m], context.showProgress);
                        if (context.showProgress)
                            std::fprintf(stderr, "  notched beam D = %d h: peak %g N/m, %.0f s\n", cells[m],
                                         runs[m].peak, runs[m].seconds);
                    });
    const Real kIc = std::sqrt(kModulus * kEnergy), k = lefmShape();
    Series trend{"notched_beam_size_effect",
                 {"D_m", "D_over_lch", "P_peak_N_per_m", "sigma_N_Pa", "P_over_P_LEFM", "broken"},
                 {}};
    // Least squares y = A + C D with y = 1 / sigma_N^2.
    Real sx = 0, sy = 0, sxx = 0, sxy = 0;
    const Real n = Real(runs.size());
    Real previousRatio = 0;
    for (const BeamRun& r : runs)
    {
        const Real sigma = r.peak / r.depth, lefm = kIc / (k * std::sqrt(r.depth)), ratio = sigma / lefm;
        trend.rows.push_back({r.depth, r.depth / kCharacteristic, r.peak, sigma, ratio, double(r.broken)});
        const Real y = 1 / (sigma * sigma);
        sx += r.depth;
        sy += y;
        sxx += r.depth * r.depth;
        sxy += r.depth * y;
        std::ostringstream note;
        note << "D = " << r.depth * 1e3 << " mm (" << r.cells << " h, D/l_ch = " << r.depth / kCharacteristic
             << ", " << r.triangles << " triangles, " << r.joints << " joints): peak P = " << r.peak
             << " N/m at t = " << r.peakTime << " s, sigma_N = " << sigma << " Pa, P / P_LEFM = " << ratio
             << "; first damage at P = " << r.initiationLoad << " N/m, joint at (" << r.initiationAt.x << ", "
             << r.initiationAt.y << ") m; broken " << r.broken << " (" << r.offLine
             << " off the mid-span line); v = " << r.speed << " m/s, dt = " << r.dt << " s, " << r.steps
             << " steps, " << r.seconds << " s";
        result.notes.push_back(note.str());
        result.series.push_back(r.series);
        const std::string size = " (D = " + std::to_string(r.cells) + " h)";
        const Real middle = 0.5 * kSpanRatio * r.depth + 2 * kEdge;
        result.quantities.push_back(
            absoluteQuantity("initiation: distance to the joint above the notch tip / h" + size, "", 0,
                             length(r.initiationAt - Vec2{middle, kNotch * r.depth + 0.5 * kEdge}) / kEdge, 1,
                             "the crack starts at the notch tip"));
        result.quantities.push_back(absoluteQuantity("broken joints off the mid-span line" + size, "", 0,
                                                     double(r.offLine), 0.1 * double(r.broken),
                                                     "a straight mode I crack (10 % branching allowed)"));
        result.quantities.push_back(
            absoluteQuantity("P / P_LEFM below 1 and rising: 0 if so" + size, "", 0,
                             ratio < 1 && ratio > previousRatio ? 0.0 : 1.0, 0,
                             "the process zone lengthens the crack; LEFM at large D"));
        previousRatio = ratio;
    }
    const Real slope = (n * sxy - sx * sy) / (n * sxx - sx * sx), intercept = (sy - slope * sx) / n;
    const Real bft = 1 / std::sqrt(intercept), d0 = intercept / slope;
    const Real lefmSlope = k * k / (kIc * kIc);
    std::ostringstream fit;
    fit << "Bazant fit 1/sigma_N^2 = A + C D: B f_t = " << bft << " Pa (B = " << bft / kTensile
        << "), D0 = " << d0 << " m (D0/l_ch = " << d0 / kCharacteristic
        << "); LEFM limit K_Ic/(k sqrt(D)) with K_Ic = " << kIc << " Pa m^0.5, k = " << k
        << "; fitted K_Ic = k/sqrt(C) = " << k / std::sqrt(slope) << " Pa m^0.5";
    result.notes.push_back(fit.str());
    result.quantities.push_back(relativeQuantity("size-effect slope d(1/sigma_N^2)/dD", "1/(Pa^2 m)",
                                                 lefmSlope, slope, 0.15,
                                                 "Bazant's law is first order in c_f / D"));
    Series fitSeries{
        "notched_beam_fit", {"B_ft_Pa", "D0_m", "slope_fit", "slope_lefm"}, {{bft, d0, slope, lefmSlope}}};
    result.series.push_back(trend);
    result.series.push_back(fitSeries);
    return result;
}

} // namespace

VERIDEM_CASE({.name = "fdem_notched_beam",
              .summary = "FEM/DEM notched beam in 3-point bending: peak load -> LEFM with size (Bazant)",
              .reference = "ASTM E399 / Tada, Paris & Irwin (SENB); Bazant & Planas 1998 (size effect)",
              .labels = {"fdem", "slow"},
              .run = notchedBeam});

} // namespace veridem::verify
