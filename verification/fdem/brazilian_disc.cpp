// Brazilian (diametral compression) test of a flattened disc that cracks (fdem/fracture/): the
// centre's tensile stress at crack initiation, from Hondros's solution for a load spread over the
// arc 2 alpha, against the joints' f_t on three meshes, and the crack along the loaded diameter.
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

constexpr Real kRadius = 0.025, kDiameter = 2 * kRadius;                       // [m]
constexpr Real kModulus = 1e10, kDensity = 2500, kTensile = 3e6, kEnergy = 50; // Pa, kg/m^3, Pa, J/m^2
constexpr Real kSpeed = 0.05;                                                  // each platen [m/s]
constexpr Real kPlaten = 0.005;                                                // platen thickness [m]
// Loading angle 2 alpha of the flats (Wang et al. 2004 recommend 20-30 degrees: the largest tension
// is then at the centre, and the contact width 2 R sin(alpha) is fixed by the shape, not by h).
constexpr Real kHalfAngle = 15 * kPi / 180; // alpha [rad]

/// Hondros (1959) for a radial pressure over the arc 2 alpha of a disc (P = 2 alpha R p per unit
/// thickness): along the loaded diameter, at rho = r / R, the stress normal to it in units of
/// 2 P / (pi D) (tension positive): [(1 - rho^2) sin 2a / (1 - 2 rho^2 cos 2a + rho^4)
/// - atan((1 + rho^2) / (1 - rho^2) tan a)] / a; at the centre (sin 2a - a) / a (0.910 at 2a = 30
/// degrees, 1 - 2a^2/3 for a small arc; a point load, a -> 0, gives 1). Equations as in Li & Wong,
/// Rock Mech. Rock Eng. 46:269 (2013), eqs. 6-7.
Real hondrosFactor(Real rho, Real alpha)
{
    const Real r2 = rho * rho;
    return ((1 - r2) * std::sin(2 * alpha) / (1 - 2 * r2 * std::cos(2 * alpha) + r2 * r2) -
            std::atan((1 + r2) / (1 - r2) * std::tan(alpha))) /
           alpha;
}

/// The flattened disc's outline (counter-clockwise): the circle of radius R cut by the two flats
/// x = +-R cos(alpha); arcs in pieces of about h (meshPolygonRefined splits the flats).
std::vector<Vec2> flattenedDiscOutline(Real h)
{
    std::vector<Vec2> outline;
    const Real span = kPi - 2 * kHalfAngle;
    // An even count puts a vertex at the top and bottom (y = +-R: the lattice rows stay centred on y = 0).
    const int pieces = 2 * std::max(1, static_cast<int>(std::lround(span * kRadius / (2 * h))));
    for (const Real start : {kHalfAngle, kPi + kHalfAngle})
        for (int i = 0; i <= pieces; ++i)
        {
            const Real angle = start + span * Real(i) / Real(pieces);
            outline.push_back({kRadius * std::cos(angle), kRadius * std::sin(angle)});
        }
    return outline;
}

struct DiscRun
{
    int rows = 0;              // lattice rows across the diameter
    Real edge = 0;             // target edge length h [m]
    std::size_t triangles = 0; // of the disc
    std::size_t joints = 0;    // inserted
    Real peak = 0;             // peak platen force P [N/m]
    Real initiation = 0;       // platen force when the first joint reaches f_t (damage > 0) [N/m]
    Real initiationTime = 0;   // [s]
    Vec2 initiationAt{};       // midpoint of that joint (reference) [m]
    Real peakTime = 0;         // [s]
    Real centreAtHalf = 0;     // centre's element sigma_yy / Hondros's at half the predicted initiation load
    Real centreAtInitiation = 0; // the same at the initiation
    Real asymmetry = 0;          // |P_left - P_right| / P at the peak
    std::size_t broken = 0;      // at the end
    std::size_t inBand = 0;      // broken joints whose midpoint is within the band of the diameter
    Real band = 0;               // half-width of that band [m]
    Real dt = 0;                 // [s]
    std::uint64_t steps = 0;     //
    double seconds = 0;          // wall time of the run
    Series series;
};

/// Area-weighted mean of sigma_yy (normal to the loaded diameter) over the disc's triangles whose
/// centroid lies within `radius` of the centre [Pa].
Real centreStress(const World& world, Real radius)
{
    Real sum = 0, area = 0;
    const TriangleStore& triangles = world.triangles();
    for (std::size_t t = 0; t < triangles.size(); ++t)
    {
        if (triangles.body[t] != 0)
            continue;
        const auto& n = triangles.nodes[t];
        const Vec2 centroid = (world.nodes().referencePosition[n[0]] + world.nodes().referencePosition[n[1]] +
                               world.nodes().referencePosition[n[2]]) /
                              3.0;
        if (length(centroid) > radius)
            continue;
        sum += triangles.stress[t].yy * triangles.referenceArea[t];
        area += triangles.referenceArea[t];
    }
    return area > 0 ? sum / area : 0;
}

/// `penalty`: the joints' p in units of E; `cracks` false: an elastic disc (no joints) loaded to
/// the same time as the jointed one's initiation, for its centre stress.
DiscRun runDisc(int rows, bool progress, Real penalty = 10, bool cracks = true)
{
    // The flattened disc (D = 0.05 m, flats at x = +-R cos(alpha)) meshed to h such that 2 R holds
    // rows + 1/2 lattice rows (h sqrt(3)/2 apart, rows even): the mesher centres the rows, so one
    // runs along the loaded (horizontal) diameter and the crack can follow mesh edges. Platens:
    // rigid (prescribed) rectangles touching the flats, moving towards each other at 0.05 m/s each.
    DiscRun run;
    run.rows = rows;
    run.edge = 2 * kDiameter / ((Real(rows) + 0.5) * std::sqrt(3.0));
    const TriangleMesh discMesh = meshPolygonRefined(flattenedDiscOutline(run.edge), run.edge);
    run.triangles = discMesh.triangles.size();
    const Real face = kRadius * std::cos(kHalfAngle); // x of the flats
    const Real c = std::sqrt(kModulus / kDensity), omega = kPi * c / kDiameter;
    // Viscosity damping the disc's lowest modes (~ pi c / D) at 20 %: the start of the loading
    // rings otherwise; its stress at the centre, eta f_t / (E t_peak) with t_peak ~ 1 ms, is ~3e-3 of f_t.
    Material rock{kDensity, kModulus, 0.2, 2 * 0.2 * kModulus / omega, StressLaw::Linear, PlaneModel::Stress};
    rock.fracture.tensileStrength = kTensile;
    rock.fracture.fractureEnergy = rock.fracture.shearFractureEnergy = kEnergy;
    // Shear strength well above the tensile one (rock: c ~ 2-3 f_t): the test measures f_t only if
    // the disc splits in tension, not in shear (Brazilian test validity, ISRM 1978).
    rock.fracture.cohesion = 3 * kTensile;
    rock.fracture.frictionAngle = degToRad(30.0);
    rock.fracture.penalty = penalty * kModulus;
    WorldSettings s;
    s.gravity = {0, 0};
    s.contact.normalPenalty = 10 * kModulus;
    s.contact.tangentialPenalty = 10 * kModulus;
    // Frictionless platens: Hondros's load is a pressure without shear. With mu = 0.5 the flats stick
    // and the inward shear against their lateral (Poisson) expansion lowers the centre's tension by
    // 3.5 % (elastic disc, centre sigma_yy / Hondros: 0.853 -> 0.881 at h = 3.5 mm, 0.874 -> 0.907 at
    // 1.8 mm).
    s.contact.friction = 0;
    const auto build = [&](World& world)
    {
        const auto m = world.addMaterial(rock, "rock");
        BodyDefinition disc{"disc", discMesh, m};
        disc.cracks = cracks;
        // Joints everywhere but within 0.17 R of the flats (|x| > 0.8 R): the contact stresses there
        // are compressive, with the rigid flat's corner singularities, and their crushing is not
        // what the test measures.
        disc.crackRegion = true;
        disc.crackMin = {-0.8 * kRadius, -kRadius};
        disc.crackMax = {0.8 * kRadius, kRadius};
        world.addBody(disc);
        const TriangleMesh platen = meshRectangle({0, -0.4 * kRadius}, {kPlaten, 0.8 * kRadius}, 1, 4);
        TriangleMesh right = platen, left = platen;
        for (auto& p : right.points)
            p.x += face;
        for (auto& p : left.points)
            p.x -= face + kPlaten;
        world.addBody({"right", right, m, {-kSpeed, 0}, true});
        world.addBody({"left", left, m, {kSpeed, 0}, true});
    };
    s.timeStep = 1;
    World probe(s);
    build(probe);
    s.timeStep = 0.7 * stableTimeStep(probe).limit; // the contact estimate is conservative (docs/fdem.md)
    run.dt = s.timeStep;
    World world(s);
    build(world);
    run.joints = world.joints().size();
    run.series = {"brazilian_disc_" + std::to_string(rows), {"t_s", "approach_m", "P_N_per_m", "broken"}, {}};
    const auto start = std::chrono::steady_clock::now();
    // Runs until 1.5 times the time of the crack's initiation (the crack grows from the centre), at
    // most 3 ms.
    Real endTime = cracks ? 3e-3 : 7e-4;
    // The centre's element stress against Hondros when the load passes half the initiation load the
    // elastic solution predicts (joints still nearly linear: r = 0.29 on the pre-peak curve).
    const Real halfLoad = 0.5 * kTensile * kPi * kDiameter / (2 * hondrosFactor(0, kHalfAngle));
    std::size_t i = 0;
    while (world.time() < endTime)
    {
        world.step();
        Real right = 0, left = 0;
        for (std::size_t n = 0; n < world.nodes().size(); ++n)
        {
            const auto body = world.nodes().body[n];
            if (body == 1)
                right += world.nodes().force[n].x;
            else if (body == 2)
                left -= world.nodes().force[n].x;
        }
        const Real load = 0.5 * (left + right), t = world.time() - s.timeStep;
        if (run.centreAtHalf == 0 && load > halfLoad)
            run.centreAtHalf = centreStress(world, std::max(0.1 * kRadius, run.edge)) /
                               (hondrosFactor(0, kHalfAngle) * 2 * load / (kPi * kDiameter));
        if (load > run.peak)
        {
            run.peak = load;
            run.peakTime = t;
            run.asymmetry = std::abs(left - right) / load;
        }
        if (++i % 200 == 0)
            run.series.rows.push_back({t, 2 * kSpeed * t, load, double(world.fractureState().broken)});
        if (progress && i % 20000 == 0)
            std::fprintf(stderr,
                         "  brazilian disc %d rows: t = %g s, P = %g N/m (peak %g), broken %zu, %.0f s\n",
                         rows, t, load, run.peak, world.fractureState().broken,
                         std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count());
        if (run.initiationTime == 0)
        {
            const JointStore& joints = world.joints();
            for (std::size_t j = 0; j < joints.size(); ++j)
                if (joints.damage[j][0] > 0 || joints.damage[j][1] > 0)
                {
                    run.initiation = load;
                    run.centreAtInitiation = centreStress(world, std::max(0.1 * kRadius, run.edge)) /
                                             (hondrosFactor(0, kHalfAngle) * 2 * load / (kPi * kDiameter));
                    run.initiationTime = t;
                    run.initiationAt = 0.5 * (world.nodes().referencePosition[joints.nodes[j][0]] +
                                              world.nodes().referencePosition[joints.nodes[j][1]]);
                    endTime = std::min(endTime, 1.5 * t);
                    break;
                }
        }
    }
    run.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    run.steps = world.stepCount();
    // The crack: broken joints' midpoints (reference) within a band of the loaded diameter y = 0,
    // one lattice row (h sqrt(3)/2) plus h/2 to each side: a crack that follows the edges of the
    // rows next to the diameter stays inside.
    run.band = run.edge * (std::sqrt(3.0) / 2 + 0.5);
    const JointStore& joints = world.joints();
    for (std::size_t j = 0; j < joints.size(); ++j)
        if (joints.broken[j])
        {
            ++run.broken;
            const Vec2 p = world.nodes().referencePosition[joints.nodes[j][0]];
            const Vec2 q = world.nodes().referencePosition[joints.nodes[j][1]];
            if (std::abs(0.5 * (p.y + q.y)) <= run.band)
                ++run.inBand;
        }
    return run;
}

CaseResult brazilianDisc(const CaseContext& context)
{
    // Diametral compression of a flattened disc between rigid platens (plane stress, per unit
    // thickness). The elastic stress normal to the loaded diameter at the centre is tension
    // sigma_c = k 2 P / (pi D), k = hondrosFactor(0, alpha) = 0.910 for 2 alpha = 30 degrees (Hondros
    // 1959; Wang et al., Int. J. Rock Mech. Min. Sci. 41:245, 2004, use the flats so that it is the
    // largest tension in the disc: hondrosFactor falls to 0.94 k at r = 0.3 R and below 0 at 0.8 R).
    // Criterion, chosen before running: the crack initiates (the first joint reaches f_t, damage
    // leaves 0) near the centre on the loaded diameter, and there sigma_c = f_t:
    //  - initiation at |x| <= 0.3 R + h/2 and within the band of the diameter, every mesh;
    //  - k 2 P_i / (pi D) = f_t within 5 % on the finest mesh: the joint nearest the centre carries
    //    sigma_c less ~3 % (its midpoint within 0.3 R, hondrosFactor), the CST stress error O(h/R)
    //    in a field varying over R (1-2 % at h/R = 0.07), the load's distribution over the flat
    //    (Hondros's uniform radial pressure: k = 0.910; a uniform strip load cos^3 alpha = 0.901: 1 %),
    //    the loading's dynamics and viscosity (< 0.5 %).
    // The joints within 0.17 R of the flats do not crack, so the halves stay held at their ends and the
    // load goes on rising after the crack has run along the diameter: the peak is reported, not compared.
    CaseResult result;
    const std::vector<int> rows{8, 16, 32};
    std::vector<DiscRun> runs(rows.size());
    const Real k = hondrosFactor(0, kHalfAngle);
    // Diagnostics of the initiation load: the middle mesh with a 10 times stiffer joint penalty, and
    // the middle and finest meshes without joints (elastic).
    DiscRun stiff, elastic16, elastic32;
    context.forEach(rows.size() + 3,
                    [&](std::size_t m)
                    {
                        if (m < rows.size())
                            runs[m] = runDisc(rows[m], context.showProgress);
                        else if (m == rows.size())
                            stiff = runDisc(16, context.showProgress, 100);
                        else if (m == rows.size() + 1)
                            elastic16 = runDisc(16, context.showProgress, 10, false);
                        else
                            elastic32 = runDisc(32, context.showProgress, 10, false);
                    });
    Series trend{"brazilian_disc_trend",
                 {"h_m", "triangles", "centre_stress_at_initiation_over_ft", "peak_over_ft",
                  "initiation_x_over_R", "broken", "in_band"},
                 {}};
    for (std::size_t m = 0; m < runs.size(); ++m)
    {
        const DiscRun& r = runs[m];
        const Real sigma = k * 2 * r.initiation / (kPi * kDiameter),
                   peak = k * 2 * r.peak / (kPi * kDiameter);
        trend.rows.push_back({r.edge, double(r.triangles), sigma / kTensile, peak / kTensile,
                              r.initiationAt.x / kRadius, double(r.broken), double(r.inBand)});
        std::ostringstream note;
        note << "h = " << r.edge * 1e3 << " mm (" << r.rows << " rows, " << r.triangles << " triangles, "
             << r.joints << " joints): k 2P/(pi D) / f_t = " << sigma / kTensile << " (k = " << k
             << ") at the first joint reaching f_t (t = " << r.initiationTime << " s, at ("
             << r.initiationAt.x << ", " << r.initiationAt.y << ") m), largest load to the end "
             << peak / kTensile << " f_t, left/right asymmetry " << r.asymmetry << ", broken " << r.broken
             << " (" << r.inBand << " within " << r.band * 1e3 << " mm of the diameter); dt = " << r.dt
             << " s, " << r.steps << " steps, " << r.seconds << " s";
        result.notes.push_back(note.str());
        result.series.push_back(r.series);
        const std::string mesh = " (h = " + std::to_string(r.edge * 1e3).substr(0, 4) + " mm)";
        // The crack starts near the centre of the loaded diameter, where the tension is largest.
        result.quantities.push_back(absoluteQuantity(
            "initiation |x| / R" + mesh, "", 0, std::abs(r.initiationAt.x) / kRadius,
            0.3 + 0.5 * r.edge / kRadius, "sigma_c within 6 % (Hondros) up to 0.3 R, + half an edge"));
        result.quantities.push_back(
            absoluteQuantity("initiation |y| / R" + mesh, "", 0, std::abs(r.initiationAt.y) / kRadius,
                             r.band / kRadius, "within the band of the diameter (a lattice row + h/2)"));
        // Crack direction: the broken joints lie along the loaded diameter.
        result.quantities.push_back(absoluteQuantity(
            "broken joints outside the band" + mesh, "", 0, double(r.broken - r.inBand),
            0.1 * double(r.broken), "at most 10 % off the diameter (branches near the platens)"));
    }
    std::ostringstream diagnosis;
    diagnosis << "joint penalty 100 E (h = " << stiff.edge * 1e3 << " mm): k 2P/(pi D) / f_t at initiation = "
              << k * 2 * stiff.initiation / (kPi * kDiameter) / kTensile << " at (" << stiff.initiationAt.x
              << ", " << stiff.initiationAt.y << ") m, centre sigma_yy / Hondros " << stiff.centreAtHalf
              << " at half load, " << stiff.centreAtInitiation << " at initiation, " << stiff.seconds
              << " s; no joints: centre sigma_yy / Hondros at half the predicted load "
              << elastic16.centreAtHalf << " (h = " << elastic16.edge * 1e3 << " mm), "
              << elastic32.centreAtHalf << " (h = " << elastic32.edge * 1e3 << " mm)";
    result.notes.push_back(diagnosis.str());
    // The elastic field: without joints the centre's stress should follow Hondros: the mean over
    // r <= 0.1 R is ~1 % below the centre's value (hondrosFactor), the load's spread over the flat was
    // budgeted at 1 %, plus the CST error. Measured (docs/fdem.md, "Brazilian disc"): the rigid flat
    // presses like a punch (its corner nodes carry ~40 % of P), not with Hondros's uniform pressure,
    // and the frictionless elastic disc converges to ~0.94 of his centre stress as h -> 0; so this
    // row and the next fail on the reference's load shape, not on the joints (initiation x the elastic
    // ratio = 1.01 on the two finer meshes). The 1 % budget was set before that was known and is kept.
    result.quantities.push_back(relativeQuantity("elastic disc: centre sigma_yy / Hondros, finest mesh", "",
                                                 1, elastic32.centreAtHalf, 0.03,
                                                 "mean over r <= 0.1 R (1 %), load spread (1 %), CST"));
    const DiscRun& finest = runs.back();
    result.quantities.push_back(
        relativeQuantity("centre stress k 2P/(pi D) at initiation, finest mesh", "Pa", kTensile,
                         k * 2 * finest.initiation / (kPi * kDiameter), 0.05,
                         "joint within 0.3 R of the centre, O(h/R) CST stress, load spread"));
    result.series.push_back(trend);
    return result;
}

} // namespace

VERIDEM_CASE(
    {.name = "fdem_brazilian_disc",
     .summary = "FEM/DEM flattened Brazilian disc: centre stress at initiation -> f_t on three meshes",
     .reference = "Hondros 1959; Wang et al. 2004 (flattened disc); ISRM 1978 (Brazilian test)",
     .labels = {"fdem", "slow"},
     .run = brazilianDisc});

} // namespace veridem::verify
