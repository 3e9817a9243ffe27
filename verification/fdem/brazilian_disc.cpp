// Brazilian (diametral compression) test of a disc that cracks (fdem/fracture/): the indirect
// tensile strength 2 P / (pi D) per unit thickness against the joints' f_t on three meshes, and the
// crack along the loaded diameter.
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

struct DiscRun
{
    int sides = 0;             // of the disc's outline
    Real edge = 0;             // target edge length h [m]
    std::size_t triangles = 0; // of the disc
    std::size_t joints = 0;    // inserted
    Real peak = 0;             // peak platen force P [N/m]
    Real initiation = 0;       // platen force when the first joint reaches f_t (damage > 0) [N/m]
    Real initiationTime = 0;   // [s]
    Vec2 initiationAt{};       // midpoint of that joint (reference) [m]
    Real peakTime = 0;         // [s]
    Real asymmetry = 0;        // |P_left - P_right| / P at the peak
    std::size_t broken = 0;    // at the end
    std::size_t inBand = 0;    // broken joints whose midpoint is within the band of the diameter
    Real band = 0;             // half-width of that band [m]
    Real dt = 0;               // [s]
    std::uint64_t steps = 0;   //
    double seconds = 0;        // wall time of the run
    Series series;
};

DiscRun runDisc(int sides, bool progress)
{
    // The disc (D = 0.05 m) is the regular polygon of `sides` sides (even), turned by pi/sides so
    // that a flat side faces each platen; meshed to h = 2 pi R / (sides - 1/2) (discOutline then
    // gives exactly `sides` sides). The lattice's rows are horizontal, so the mesh has edges along
    // the loaded (horizontal) diameter. Platens: rigid (prescribed) rectangles touching those sides,
    // moving towards each other at V = 0.05 m/s each.
    DiscRun run;
    run.sides = sides;
    run.edge = 2 * kPi * kRadius / (sides - 0.5);
    std::vector<Vec2> outline = discOutline({0, 0}, kRadius, run.edge);
    const Real turn = kPi / sides;
    for (Vec2& p : outline)
        p = {p.x * std::cos(turn) - p.y * std::sin(turn), p.x * std::sin(turn) + p.y * std::cos(turn)};
    const TriangleMesh discMesh = meshPolygonRefined(outline, run.edge);
    run.triangles = discMesh.triangles.size();
    const Real face = kRadius * std::cos(kPi / sides); // x of the flat sides
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
    rock.fracture.penalty = 10 * kModulus;
    WorldSettings s;
    s.gravity = {0, 0};
    s.contact.normalPenalty = 10 * kModulus;
    s.contact.tangentialPenalty = 10 * kModulus;
    s.contact.friction = 0.5;
    const auto build = [&](World& world)
    {
        const auto m = world.addMaterial(rock, "rock");
        BodyDefinition disc{"disc", discMesh, m};
        disc.cracks = true;
        // Joints everywhere but under the platens (0.2 R deep): the contact stresses there are
        // compressive and far above f_t, and their crushing is not what 2 P / (pi D) describes.
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
    run.series = {
        "brazilian_disc_" + std::to_string(sides), {"t_s", "approach_m", "P_N_per_m", "broken"}, {}};
    const auto start = std::chrono::steady_clock::now();
    // Runs until 1.5 times the time of the crack's initiation (the crack grows from the centre), at
    // most 3 ms.
    Real endTime = 3e-3;
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
                         "  brazilian disc %d sides: t = %g s, P = %g N/m (peak %g), broken %zu, %.0f s\n",
                         sides, t, load, run.peak, world.fractureState().broken,
                         std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count());
        if (run.initiationTime == 0)
        {
            const JointStore& joints = world.joints();
            for (std::size_t j = 0; j < joints.size(); ++j)
                if (joints.damage[j][0] > 0 || joints.damage[j][1] > 0)
                {
                    run.initiation = load;
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
    // Diametral compression of a disc between flat rigid platens (plane stress, per unit thickness).
    // Elastic solution (Hertz 1883; Timoshenko & Goodier, Theory of Elasticity, section 41): along
    // the loaded diameter the stress normal to it is uniform tension 2 P / (pi D) (away from the
    // loaded ends), so a brittle disc splits along that diameter when 2 P / (pi D) reaches the
    // tensile strength f_t. Here the joints under the platens (0.2 R deep) do not crack, so the two
    // halves stay held at their ends and the load goes on rising after the crack has run along the
    // middle of the diameter: the strength is measured at the crack's initiation, the load when the
    // first joint reaches f_t (its damage leaves 0), as sigma = 2 P_i / (pi D) against f_t on three
    // meshes. The load spreads over a flat side of length ~h: this lowers the centre's stress by
    // ~(a/R)^2 (Hondros 1959, loaded arc of half-width a ~ h/2).
    CaseResult result;
    const std::vector<int> sides{24, 48, 96};
    std::vector<DiscRun> runs(sides.size());
    context.forEach(sides.size(),
                    [&](std::size_t k)
                    {
                        runs[k] = runDisc(sides[k], context.showProgress);
                        if (context.showProgress)
                            std::fprintf(stderr, "  brazilian disc %d sides: 2P/(pi D)/f_t = %.4f, %.0f s\n",
                                         sides[k], 2 * runs[k].initiation / (kPi * kDiameter) / kTensile,
                                         runs[k].seconds);
                    });
    Series trend{"brazilian_disc_trend",
                 {"h_m", "triangles", "initiation_over_ft", "peak_over_ft", "broken", "in_band"},
                 {}};
    for (std::size_t k = 0; k < runs.size(); ++k)
    {
        const DiscRun& r = runs[k];
        const Real sigma = 2 * r.initiation / (kPi * kDiameter), peak = 2 * r.peak / (kPi * kDiameter);
        trend.rows.push_back({r.edge, double(r.triangles), sigma / kTensile, peak / kTensile,
                              double(r.broken), double(r.inBand)});
        std::ostringstream note;
        note << "h = " << r.edge * 1e3 << " mm (" << r.sides << " sides, " << r.triangles << " triangles, "
             << r.joints << " joints): 2P/(pi D) / f_t = " << sigma / kTensile
             << " at the first joint reaching f_t (t = " << r.initiationTime << " s, at (" << r.initiationAt.x
             << ", " << r.initiationAt.y << ") m), largest load to the end " << peak / kTensile
             << " f_t, left/right asymmetry " << r.asymmetry << ", broken " << r.broken << " (" << r.inBand
             << " within " << r.band * 1e3 << " mm of the diameter); dt = " << r.dt << " s, " << r.steps
             << " steps, " << r.seconds << " s";
        result.notes.push_back(note.str());
        result.series.push_back(r.series);
        const std::string mesh = " (h = " + std::to_string(r.edge * 1e3).substr(0, 4) + " mm)";
        // The crack starts near the centre of the loaded diameter, where the tension is largest.
        result.quantities.push_back(
            absoluteQuantity("initiation |y| / R" + mesh, "", 0, std::abs(r.initiationAt.y) / kRadius,
                             r.band / kRadius, "within the band of the diameter (a lattice row + h/2)"));
        // Crack direction: the broken joints lie along the loaded diameter.
        result.quantities.push_back(absoluteQuantity(
            "broken joints outside the band" + mesh, "", 0, double(r.broken - r.inBand),
            0.1 * double(r.broken), "at most 10 % off the diameter (branches near the platens)"));
    }
    // The strength on the finest mesh: the CST stress error is O(h / R) (h/R = 0.065 here) and the flat
    // contact of width ~h lowers the centre's stress by ~(a/R)^2 (Hondros 1959): 10 %.
    const DiscRun& finest = runs.back();
    result.quantities.push_back(relativeQuantity("2P/(pi D) at initiation, finest mesh", "Pa", kTensile,
                                                 2 * finest.initiation / (kPi * kDiameter), 0.1,
                                                 "O(h/R) element stress error, contact width (a/R)^2"));
    result.series.push_back(trend);
    return result;
}

} // namespace

VERIDEM_CASE({.name = "fdem_brazilian_disc",
              .summary = "FEM/DEM Brazilian disc: 2P/(pi D) -> f_t on three meshes, crack along the diameter",
              .reference = "Hertz 1883; Timoshenko & Goodier sec. 41; ISRM 1978 (Brazilian test)",
              .labels = {"fdem", "slow"},
              .run = brazilianDisc});

} // namespace veridem::verify
