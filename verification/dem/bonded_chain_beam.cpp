// A chain of N + 1 equal spheres (radius R, centre spacing L) joined by N parallel bonds
// (dem/bonds/bond_law.h), clamped at sphere 0 (frozen), loaded at sphere N and relaxed to rest.
//
// Bending. With the bond's bending stiffness kn I, the moment in bond i is the tip load P times
// the lever from its contact point (the middle of the bond) to the tip, and each bond turns its
// outer sphere by M_i / (kn I): the chain is a beam of flexural rigidity EI = kn I L, and the
// spheres' rotations are exactly those of that beam at the sphere centres (the moment is linear,
// the midpoint rule exact). The deflection adds, per bond, the shear slide P / (ks A) and the
// chord of the rotations, L (theta_i + theta_i+1) / 2 (the trapezoid rule of a quadratic):
//
//   w_N = P l^3 / (3 EI) (1 - L^2 / (4 l^2)) + N P / (ks A),     l = N L
//
// the Euler-Bernoulli cantilever P l^3 / (3 EI) plus the discretisation -1/(4 N^2) and the
// Timoshenko-like shear term 3 EI / (ks A L l^2) = (3/16) (kn/ks) lambda^2 / N^2 for L = 2R (both
// ~1e-3 for N = 10): the slender limit agrees with Euler-Bernoulli within 1 %, the discrete
// formula to the relaxation's residual.
//
// Axial: a tip force F stretches each bond by F / (kn A): u_N = N F / (kn A). Torsion: a tip
// torque T twists each bond by T / (ks J): phi_N = N T / (ks J).
//
// Loads are small (deflection 1e-5 of the length): the geometric non-linearity is ~1e-10. The
// chain is relaxed by mass-proportional damping at 0.9 of its first bending frequency
// omega_1 = 1.875^2 sqrt(EI / (mu l^4)), mu = m / L: every underdamped mode's amplitude decays
// as exp(-0.45 omega_1 t) (the first is the slowest and underdamped, zeta = 0.45), so 60 / omega_1
// leaves < 1e-11 of the initial transient.
#include "bonded_chain.h"

#include <cmath>

namespace veridem::verify
{
namespace
{

struct Relaxed
{
    Vec3 tipDisplacement; // [m]
    Real tipTwist;        // [rad]
};

Relaxed relaxUnder(const BondedChain& chain, const Vec3& force, const Vec3& torque, Real dt, Real rate,
                   std::uint64_t steps)
{
    World world = chainWorld(chain);
    const std::size_t tip = world.particles.size() - 1;
    const Vec3 start = world.particles.position[tip];
    world.particles.externalForce[tip] = force;
    world.particles.externalTorque[tip] = torque;
    const Real twist = relaxChain(world, dt, rate, steps);
    return {world.particles.position[tip] - start, twist};
}

CaseResult run(const CaseContext& context)
{
    BondedChain chain;
    chain.law.normalStiffness = 1e11; // [N/m^3]
    chain.law.shearStiffness = 4e10;
    chain.law.radiusMultiplier = 1;
    const int n = chain.bonds;
    const Real spacing = chain.spacing(), length = n * spacing;
    const dem::BondSection sec = dem::bondSection(chain.law, chain.radius, chain.radius);
    const Real ei = chain.law.normalStiffness * sec.bend * spacing; // [N m^2]
    const Real axial = chain.law.normalStiffness * sec.area;        // kn A [N/m]
    const Real shear = chain.law.shearStiffness * sec.area;         // ks A [N/m]
    const Real twist = chain.law.shearStiffness * sec.twist;        // ks J [N m/rad]
    const Real mu = sphereMass(chain.density, chain.radius) / spacing;
    const Real omega1 = 1.875 * 1.875 * std::sqrt(ei / (mu * std::pow(length, 4))); // [rad/s]
    const Real rate = 0.9 * omega1;
    const Real dt = 5e-7 * context.dtScale; // ~0.2 of the bonds' pair limit (io/bond_keys.cpp)
    const auto steps = static_cast<std::uint64_t>(std::ceil(60 / omega1 / dt));

    const Real p = 3 * ei * 1e-5 * length / std::pow(length, 3); // deflection ~1e-5 l
    const Real f = axial * 1e-5 * length / n;                    // stretch ~1e-5 l
    const Real t = twist * 1e-5 / n;                             // twist ~1e-5 rad
    Relaxed bent{}, pulled{}, twisted{};
    context.forEach(3,
                    [&](std::size_t k)
                    {
                        if (k == 0)
                            bent = relaxUnder(chain, {0, p, 0}, {}, dt, rate, steps);
                        else if (k == 1)
                            pulled = relaxUnder(chain, {f, 0, 0}, {}, dt, rate, steps);
                        else
                            twisted = relaxUnder(chain, {}, {t, 0, 0}, dt, rate, steps);
                    });

    const Real eulerBernoulli = p * std::pow(length, 3) / (3 * ei);
    const Real discrete = eulerBernoulli * (1 - spacing * spacing / (4 * length * length)) + n * p / shear;
    CaseResult r;
    r.quantities.push_back(relativeQuantity(
        "tip deflection vs Euler-Bernoulli P l^3/(3 EI)", "m", eulerBernoulli, bent.tipDisplacement.y, 0.01,
        "slender limit: discretisation -1/(4N^2) and shear 3EI/(ks A L l^2), 1e-3 together at N = 10"));
    r.quantities.push_back(relativeQuantity(
        "tip deflection vs the discrete beam", "m", discrete, bent.tipDisplacement.y, 1e-6,
        "exact for the bonded chain; residual transient < 1e-11, geometric non-linearity ~1e-10"));
    r.quantities.push_back(relativeQuantity("axial tip displacement vs N F/(kn A)", "m", n * f / axial,
                                            pulled.tipDisplacement.x, 1e-6,
                                            "exact (total normal force); residual transient < 1e-11"));
    r.quantities.push_back(relativeQuantity("tip twist vs N T/(ks J)", "rad", n * t / twist, twisted.tipTwist,
                                            1e-6, "exact (twist about a fixed axis); residual < 1e-11"));
    char note[200];
    std::snprintf(note, sizeof note,
                  "N = %d bonds, L = %.4g m, EI = kn I L = %.4g N m^2, %llu steps of %.3g s", n, spacing, ei,
                  static_cast<unsigned long long>(steps), dt);
    r.notes.emplace_back(note);
    return r;
}

} // namespace

VERIDEM_CASE(
    {.name = "bonded_chain_beam",
     .summary = "bonded sphere chain: cantilever deflection (Euler-Bernoulli), axial and torsional stiffness",
     .reference = "Potyondy & Cundall 2004 (parallel bond); Euler-Bernoulli cantilever",
     .labels = {"dem", "quick", "bonds"},
     .run = run});
} // namespace veridem::verify
