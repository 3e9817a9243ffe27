// The contact law, written once: normal force, then tangential force capped by it, then rolling
// torque capped by it, in that fixed visible order. One template over the number type T (double
// for the scalar path, a vector of lanes for the batched kernels: dem/lanes.h) and over the pair's
// models (LawModel, chosen once per pair-table entry), so every width gives the same bits by
// construction. The same function serves particle pairs and particle-wall contacts: a wall is a
// partner of infinite mass with a prescribed velocity and angular velocity.
#pragma once

#include "core/hot.h"
#include "core/vec3.h"
#include "dem/contact_assembly.h"
#include "dem/lanes.h"
#include "dem/materials.h"
#include "dem/models/cohesion.h"
#include "dem/models/normal.h"
#include "dem/models/rolling.h"
#include "dem/models/tangential.h"
#include "dem/models/thornton.h"

#include <array>
#include <cmath>
#include <iterator>
#include <type_traits>
#include <utility>
#include <vector>

namespace veridem::dem
{

/// The models of a pair, as compile-time parameters of the law.
template <NormalModel N, RollingModel R> struct LawModel
{
    static constexpr NormalModel normal = N;
    static constexpr RollingModel rolling = R;
};

/// The number of model combinations (LawModel) and each one's index: normal * count + rolling.
inline constexpr unsigned kRollingModelCount = std::size(kRollingModelList);
inline constexpr unsigned kNormalModelCount = std::size(kNormalModelList);
inline constexpr unsigned kLawModels = kNormalModelCount * kRollingModelCount;
inline unsigned lawModelIndex(const PairParams& p)
{
    return static_cast<unsigned>(p.normalModel) * kRollingModelCount + static_cast<unsigned>(p.rollingModel);
}

/// Calls f.operator()<model>() for the listed model equal to `value` (one comparison per listed
/// model; a value outside the list stops the run: unregisteredContactModel).
template <const auto& kList, std::size_t kIndex = 0, class E, class F>
VERIDEM_HOT_INLINE decltype(auto) dispatchListedModel(E value, F& f)
{
    constexpr E kModel = kList[kIndex].model;
    if constexpr (kIndex + 1 < std::size(kList))
    {
        if (value == kModel)
            return f.template operator()<kModel>();
        return dispatchListedModel<kList, kIndex + 1>(value, f);
    }
    else
    {
        if (value != kModel) [[unlikely]]
            unregisteredContactModel(static_cast<unsigned>(value));
        return f.template operator()<kModel>();
    }
}

/// Calls f(LawModel<...>{}) for the models of p (outside the law). Every listed model is
/// dispatched by construction; there is no default.
template <class F> VERIDEM_HOT_INLINE decltype(auto) withLawModel(const PairParams& p, F&& f)
{
    auto normal = [&]<NormalModel N>() VERIDEM_INLINE_LAMBDA -> decltype(auto)
    {
        auto rolling = [&]<RollingModel R>() VERIDEM_INLINE_LAMBDA -> decltype(auto)
        { return f(LawModel<N, R>{}); };
        return dispatchListedModel<kRollingModelList>(p.rollingModel, rolling);
    };
    return dispatchListedModel<kNormalModelList>(p.normalModel, normal);
}

/// The lawModelIndex bits of the models with rolling resistance, and of the JKR models (whose
/// contacts carry a formed/not-formed state: their touch criterion has hysteresis).
inline constexpr unsigned kRollingModels = []
{
    unsigned mask = 0;
    for (unsigned n = 0; n < kNormalModelCount; ++n)
        mask |= ((1u << kRollingModelCount) - 2) << (n * kRollingModelCount);
    return mask;
}();
inline constexpr unsigned kJkrModels = ((1u << kRollingModelCount) - 1)
                                       << (static_cast<unsigned>(NormalModel::Jkr) * kRollingModelCount);
static_assert(kLawModels <= 32, "lawModelIndex bits are kept in an unsigned mask");

/// Calls f(LawModel<...>{}, index) for every model whose bit `index` is set in `mask`, in index
/// order (every combination of the lists, by construction).
template <class F> VERIDEM_HOT_INLINE void forEachLawModel(unsigned mask, F&& f)
{
    [&]<unsigned... kIndex>(std::integer_sequence<unsigned, kIndex...>) VERIDEM_INLINE_LAMBDA
    {
        (((mask & (1u << kIndex)) != 0 ? f(LawModel<kNormalModelList[kIndex / kRollingModelCount].model,
                                                    kRollingModelList[kIndex % kRollingModelCount].model>{},
                                           kIndex)
                                       : void()),
         ...);
    }
    (std::make_integer_sequence<unsigned, kLawModels>{});
}

/// The pair parameters as the law reads them (one value per lane).
template <class T> struct LawParamsOf
{
    T kn;             // [N/m] (linear)
    T ktRatio;        // kt/kn [-] (linear)
    T modulus;        // E* [Pa] (Hertz)
    T shearModulus;   // G* [Pa] (Hertz-Mindlin)
    T dampingRate;    // gamma_n [1/s] if >= 0 (etaN = gamma_n m*), else damping from restitution
    T dampingFactor;  // etaN / sqrt(m* kn): 2 zeta (linear) or 2 sqrt(5/6) beta (Hertz) [-]
    T etaRatio;       // etaT / etaN [-]
    T mu;             // [-]
    T rollingLength;  // muR as a length [m]
    T rollingDimless; // muR' [-] (muR = rollingLength + muR' R*)
    T rollingDamping; // EPSD etaR [-]
    T rollingTwist;   // 1: the rolling torque also opposes twist about the normal; 0: not [-]
    T rollingViscous; // type B c_r [s/m]
    T adhesion;       // work of adhesion w [J/m^2] (JKR, DMT)
    T yieldPressure;  // limiting contact pressure p_y [Pa] (Thornton)
};
using LawParams = LawParamsOf<Real>;

/// Calls f(a.field, b.field) for every field of two LawParamsOf (of any number types: a lane
/// twin, batch::LaneParams, is a LawParamsOf of columns), in the order of the declaration. The
/// fields are bound from the declaration itself: a field added to LawParamsOf stops this from
/// compiling until it is bound here, and no reordering can pair two different fields.
template <class A, class B, class F> VERIDEM_HOT_INLINE void forEachLawParam(A& a, B& b, F&& f)
{
    auto& [a0, a1, a2, a3, a4, a5, a6, a7, a8, a9, a10, a11, a12, a13, a14] = a;
    auto& [b0, b1, b2, b3, b4, b5, b6, b7, b8, b9, b10, b11, b12, b13, b14] = b;
    f(a0, b0), f(a1, b1), f(a2, b2), f(a3, b3), f(a4, b4), f(a5, b5), f(a6, b6);
    f(a7, b7), f(a8, b8), f(a9, b9), f(a10, b10), f(a11, b11), f(a12, b12), f(a13, b13), f(a14, b14);
}

/// The law's parameters of a pair (designated: a reordering of LawParamsOf does not compile).
inline LawParams lawParams(const PairParams& p)
{
    return {.kn = p.kn,
            .ktRatio = p.ktRatio,
            .modulus = p.effectiveModulus,
            .shearModulus = p.effectiveShearModulus,
            .dampingRate = p.dampingRate,
            .dampingFactor =
                isHertzian(p.normalModel) ? hertzDampingFactor(p.hertzBeta) : 2.0 * p.dampingRatio,
            .etaRatio = p.tangentialDampingRatio,
            .mu = p.mu,
            .rollingLength = p.rollingLength,
            .rollingDimless = p.rollingDimensionless,
            .rollingDamping = p.rollingDampingRatio,
            .rollingTwist = p.rollingTwist ? 1.0 : 0.0,
            .rollingViscous = p.rollingViscous,
            .adhesion = p.workOfAdhesion,
            .yieldPressure = p.yieldPressure};
}

/// Geometry and kinematics of one contact, as seen by particle i.
template <class T> struct ContactInputOf
{
    lanes::Vec3Of<T> normal{};                  // unit, from the partner towards particle i
    T overlap{};                                // delta > 0 [m]
    lanes::Vec3Of<T> relativeVelocity{};        // contact-point velocity of i minus the partner's [m/s]
    lanes::Vec3Of<T> relativeAngularVelocity{}; // w_i - w_partner [rad/s]
    T effectiveMass{};                          // m* [kg]
    T effectiveRadius{};                        // R* [m] (Hertz, and R_r for dimensionless rolling friction)
    T rollingInertia{}; // I_r = [(I1 + m1 r1^2)^-1 + (I2 + m2 r2^2)^-1]^-1 [kg m^2] (EPSD damping)
    T spinInertia{};    // [1/I1 + 1/I2]^-1 [kg m^2] (type A rest treatment; twist-safe)
    lanes::Vec3Of<T> angularVelocity{}; // w_i, particle i's own [rad/s] (absolute-frame type A only)
};
using ContactInput = ContactInputOf<Real>;

/// Per-contact history carried from step to step.
template <class T> struct ContactHistoryOf
{
    lanes::Vec3Of<T> tangentialSpring{}; // xi [m]
    lanes::Vec3Of<T> rollingSpring{};    // EPSD elastic torque [N m]
    T formed{}; // 1 while a JKR contact is formed, else 0 [-] (the law writes 1 for other models)
    // The normal model's own history (ModelEntry::historyScalars of them; zero at first touch;
    // units the model's): e.g. Thornton's largest overlap [m].
    std::array<T, kHistoryScalarRoom> scalars{};
};
using ContactHistory = ContactHistoryOf<Real>;

template <class T> struct ContactOutputOf
{
    lanes::Vec3Of<T> force;           // total force on i [N] (normal + tangential)
    lanes::Vec3Of<T> tangentialForce; // its tangential part [N] (its torque lever is applied by the caller)
    lanes::Vec3Of<T> rollingTorque;   // rolling/twisting resistance torque on i [N m]
    T normalForce{};                  // signed Fn [N] (> 0 repulsive; linear may pull slightly)
    lanes::MaskOf<T> sliding{};
};
using ContactOutput = ContactOutputOf<Real>;

/// Normal and tangential stiffness/damping of a pair at overlap delta (kn, kt [N/m]; eta [N s/m]).
template <class T> struct ContactCoefficientsOf
{
    T kn{}, kt{}, etaN{}, etaT{};
};
using ContactCoefficients = ContactCoefficientsOf<Real>;

/// The contact radius a [m] of a Hertz-family contact at overlap delta [m] (Hertz and DMT:
/// sqrt(R* delta); JKR: models/cohesion.h); unused by the linear model.
template <class Model, class T>
VERIDEM_HOT_INLINE T contactRadiusOf(const LawParamsOf<T>& p, T overlap, T effectiveRadius)
{
    if constexpr (Model::normal == NormalModel::Linear)
        return T{};
    else if constexpr (Model::normal == NormalModel::Jkr)
        return jkrContactRadius<T>(p.modulus, effectiveRadius, p.adhesion, overlap);
    else
        return lanes::laneSqrt(effectiveRadius * overlap);
}

/// The coefficients at contact radius a [m] (contactRadiusOf; Hertz-family models): kn = 2 E* a
/// and kt = 8 G* a (Mindlin), the damping from them.
template <class Model, class T>
VERIDEM_HOT_INLINE ContactCoefficientsOf<T> contactCoefficientsAt(const LawParamsOf<T>& p, T contactRadius,
                                                                  T effectiveMass)
{
    using namespace lanes;
    ContactCoefficientsOf<T> c;
    const MaskOf<T> fromRate = p.dampingRate >= T{};
    c.etaN = p.dampingRate * effectiveMass;
    if constexpr (Model::normal == NormalModel::Linear)
    {
        (void)contactRadius;
        c.kn = p.kn;
        c.kt = p.ktRatio * p.kn;
        if (!allLanes(fromRate)) // damping from restitution: 2 zeta sqrt(m* kn)
            c.etaN = fromRate ? c.etaN : p.dampingFactor * laneSqrt(effectiveMass * c.kn);
    }
    else
    {
        c.kn = 2.0 * p.modulus * contactRadius;
        c.kt = 8.0 * p.shearModulus * contactRadius;
        if (!allLanes(fromRate))
            c.etaN = fromRate ? c.etaN : p.dampingFactor * laneSqrt(c.kn * effectiveMass);
    }
    c.etaT = p.etaRatio * c.etaN;
    return c;
}

template <class Model, class T>
VERIDEM_HOT_INLINE ContactCoefficientsOf<T> contactCoefficientsOf(const LawParamsOf<T>& p, T overlap,
                                                                  T effectiveMass, T effectiveRadius)
{
    return contactCoefficientsAt<Model, T>(p, contactRadiusOf<Model, T>(p, overlap, effectiveRadius),
                                           effectiveMass);
}

/// Coefficients of a pair (scalar: the time-step estimate, tests).
inline ContactCoefficients contactCoefficients(const PairParams& p, Real overlap, Real effectiveMass,
                                               Real effectiveRadius)
{
    return withLawModel(p,
                        [&](auto model) {
                            return contactCoefficientsOf<decltype(model)>(lawParams(p), overlap,
                                                                          effectiveMass, effectiveRadius);
                        });
}

/// The law's intermediate terms, reported on request (dem/contact_diagnostics.h: the energy
/// ledger, the force split). The default NoLawTerms reports nothing: its law compiles to the code
/// of a law without the report.
struct NoLawTerms
{
};
template <class T> struct LawTermsOf
{
    T elasticNormalForce{};                // spring part of Fn (signed, > 0 repulsive) [N]
    T dampingNormalForce{};                // dashpot part of Fn, Fn - elastic [N]
    ContactCoefficientsOf<T> coefficients; // kn, kt [N/m], etaN, etaT [N s/m] at this overlap
    lanes::Vec3Of<T> tangentialStart{};    // stored spring in the tangent plane before the step [m]
    lanes::Vec3Of<T> tangentialTrial{};    // the spring with this step's increment, before the cap [m]
    lanes::Vec3Of<T> tangentialDamping{};  // Ft + kt xi: -etaT vt, or all of Ft if xi is zeroed [N]
    T rollingStiffness{};                  // EPSD kr [N m/rad] (0 for the other rolling models)
    lanes::Vec3Of<T> rollingStart{};       // EPSD stored spring torque before the step [N m]
    lanes::Vec3Of<T> rollingTrial{};       // EPSD spring with this step's increment, before the cap [N m]
    lanes::Vec3Of<T> rollingDamping{};     // EPSD dashpot part of the rolling torque [N m]
};
using LawTerms = LawTermsOf<Real>;

/// The law. kProjected: the stored tangential spring is already in the tangent plane (the pair
/// kernel rotates it in its input pass). `terms`: where to report the intermediate terms if
/// Terms is LawTermsOf<T> (else unused).
template <class Model, class T, bool kProjected = false, class Terms = NoLawTerms>
VERIDEM_HOT_INLINE ContactOutputOf<T> contactLaw(const LawParamsOf<T>& p, const ContactInputOf<T>& in,
                                                 ContactHistoryOf<T>& history, Real dt,
                                                 [[maybe_unused]] Terms* terms = nullptr)
{
    using namespace lanes;
    using V = Vec3Of<T>;
    constexpr bool kReport = !std::is_same_v<Terms, NoLawTerms>;
    const T zero{}, one = broadcast<T>(1.0);
    constexpr bool kAdhesive = isAdhesive(Model::normal);
    const T contactRadius = contactRadiusOf<Model, T>(p, in.overlap, in.effectiveRadius);
    const ContactCoefficientsOf<T> c = contactCoefficientsAt<Model, T>(p, contactRadius, in.effectiveMass);

    // 0. The touch criterion: whether the contact is formed. Every model but JKR is formed exactly
    // while delta > 0 (the force stage passes only those). A JKR contact forms at delta >= 0 and
    // holds while delta > delta_c < 0 (the force stage passes contacts within its reach).
    MaskOf<T> formed{};
    if constexpr (Model::normal == NormalModel::Jkr)
        formed = (in.overlap >= zero) |
                 ((history.formed != zero) &
                  (in.overlap > jkrBreakingOverlap<T>(p.modulus, in.effectiveRadius, p.adhesion)));

    // 1. Normal force.
    const T normalSpeed = dot(in.relativeVelocity, in.normal); // < 0 while approaching
    T elastic;
    if constexpr (Model::normal == NormalModel::Linear)
        elastic = linearElasticForce<T>(c.kn, in.overlap);
    else if constexpr (Model::normal == NormalModel::Hertz)
        elastic = hertzElasticForce<T>(p.modulus, in.effectiveRadius, in.overlap);
    else if constexpr (Model::normal == NormalModel::Dmt)
        elastic = dmtForce<T>(p.modulus, in.effectiveRadius, p.adhesion, in.overlap);
    else if constexpr (Model::normal == NormalModel::Thornton)
    {
        // The largest overlap so far, this step's included (history scalar 0): the unloading
        // branch hangs from it. (Scalar only: models with history scalars run one contact at a
        // time, dem/exec/law_batch.h.)
        static_assert(std::is_same_v<T, Real>, "a Thornton contact runs on the scalar path");
        history.scalars[0] = std::fmax(history.scalars[0], in.overlap);
        elastic =
            thorntonForce(p.modulus, in.effectiveRadius, p.yieldPressure, in.overlap, history.scalars[0]);
    }
    else
        elastic = jkrForce<T>(p.modulus, in.effectiveRadius, p.adhesion, contactRadius);
    // Contact transitions. The dashpot force jumps to etaN |vn| at first touch and from it at
    // separation, so the force sampled at t+dt (which acts over the kick window
    // [t+dt/2, t+3dt/2]) would otherwise act for a full step whatever fraction of the window is
    // in contact: an O(zeta omega dt) error in e that depends on where first touch falls between
    // steps. When the neighbouring step (t before first touch, t+2dt after separation) is out of
    // contact, i.e. delta < |vn| dt, the dashpot is weighted by the contact time credited to this
    // window, 1/2 + delta/(|vn| dt) (derivation in docs/models.md). Its division runs only if a
    // lane needs it.
    // (Adhesive contacts form and break with a jump of the elastic force itself: no weighting.)
    T dashpotWeight = one;
    if constexpr (!kAdhesive)
    {
        const T travel = laneAbs(normalSpeed) * dt;
        const MaskOf<T> transition = in.overlap < travel;
        if (anyLane(transition))
            dashpotWeight = transition ? 0.5 + in.overlap / travel : one;
    }
    // The dashpot needs the normal speed at t+dt, but only the half-step speed is known. Solve
    // the pair's own final half kick for it, u = u_half + dt/2 (elastic - eta u)/m*, so that
    // the damping of an isolated contact is integrated to second order (other forces on the two
    // bodies are neglected in this estimate). Written with m* in numerator and denominator,
    // u = (m* u_half + dt/2 elastic) / (m* + dt/2 eta), so that it costs one division.
    const T dampingWeight = dashpotWeight * c.etaN;
    T normalForce =
        springDashpotNormalForce<T>(elastic, dampingWeight, normalSpeed, in.effectiveMass, 0.5 * dt);
    // A Hertz contact never pulls: Fn = max(0, ...), with beta computed for the clipped law
    // (models/normal.h). The clip agrees with the end-of-step speed above: the estimated force,
    // m* (elastic - eta u_half) / (m* + dt/2 eta), has the sign of the force at the half-step
    // speed, so where it is clipped no force acts over the final half kick and u = u_half.
    if constexpr (Model::normal == NormalModel::Hertz)
        normalForce = normalForce < zero ? zero : normalForce; // (NaN passes: the health check sees it)
    if constexpr (kReport)
    {
        terms->elasticNormalForce = elastic;
        terms->dampingNormalForce = normalForce - elastic;
        terms->coefficients = c;
    }

    // The load the friction and rolling caps take: Fn, or Fn + 2 F_pulloff with adhesion.
    T load = normalForce;
    if constexpr (Model::normal == NormalModel::Jkr)
        load = normalForce + 2.0 * jkrPullOffForce<T>(in.effectiveRadius, p.adhesion);
    else if constexpr (Model::normal == NormalModel::Dmt)
        load = normalForce + 2.0 * dmtPullOffForce<T>(in.effectiveRadius, p.adhesion);

    // 2. Tangential force, capped by mu * load.
    const V tangentialVelocity = in.relativeVelocity - normalSpeed * in.normal;
    if constexpr (kReport)
    {
        terms->tangentialStart =
            kProjected ? history.tangentialSpring : projectSpring<T>(history.tangentialSpring, in.normal);
        terms->tangentialTrial = terms->tangentialStart + tangentialVelocity * dt;
        terms->rollingStart = history.rollingSpring;
    }
    TangentialResultOf<T> t = coulombSpring<T, kProjected>(c.kt, c.etaT, p.mu, load, history.tangentialSpring,
                                                           in.normal, tangentialVelocity, dt);
    history.tangentialSpring = t.spring;
    if constexpr (kReport) // the force's part beyond the stored spring's -kt xi: -etaT vt, or all of
        terms->tangentialDamping = t.force + c.kt * t.spring; // it when the spring holds nothing

    // 3. Rolling resistance, capped by muR * Fn. It opposes the whole relative angular velocity
    // unless the pair opts out of twist resistance (PairParams::rollingTwist, see materials.h).
    V rollingTorque{};
    if constexpr (Model::rolling != RollingModel::None)
    {
        const V w = in.relativeAngularVelocity;
        const V resisted = select(p.rollingTwist != zero, w, w - dot(w, in.normal) * in.normal);
        const T muR = p.rollingLength + p.rollingDimless * in.effectiveRadius;
        if constexpr (Model::rolling == RollingModel::ConstantTorque)
            rollingTorque = constantRollingTorqueOf<T>(muR, load, resisted, in.spinInertia, dt);
        else if constexpr (Model::rolling == RollingModel::ConstantTorqueAbsolute)
            rollingTorque = constantRollingTorqueOf<T>(muR, load, in.angularVelocity, in.spinInertia, dt);
        else if constexpr (Model::rolling == RollingModel::Viscous)
            rollingTorque = viscousRollingTorqueOf<T>(p.rollingViscous, in.effectiveRadius, load, resisted);
        else
        {
            const T kr = epsdRollingStiffness<T>(c.kn, muR);
            const T cr = p.rollingDamping * 2.0 * laneSqrt(in.rollingInertia * kr);
            const RollingSpringResultOf<T> r =
                epsdRollingTorqueOf<T>(kr, cr, muR, load, history.rollingSpring, resisted, dt);
            history.rollingSpring = r.spring;
            rollingTorque = r.torque;
            if constexpr (kReport)
            {
                terms->rollingStiffness = kr;
                terms->rollingTrial = terms->rollingStart - resisted * (kr * dt);
                terms->rollingDamping = r.torque - r.spring;
            }
        }
    }
    // A JKR contact that is not formed carries no force and forgets its history.
    T force = normalForce;
    history.formed = one;
    if constexpr (Model::normal == NormalModel::Jkr)
    {
        history.formed = formed ? one : zero;
        if (!allLanes(formed))
        {
            force = formed ? force : zero;
            t.force = select(formed, t.force, V{});
            rollingTorque = select(formed, rollingTorque, V{});
            history.tangentialSpring = select(formed, history.tangentialSpring, V{});
            history.rollingSpring = select(formed, history.rollingSpring, V{});
        }
    }
    return {contactForceOf<T>(in.normal, force, t.force), t.force, rollingTorque, force, t.sliding};
}

/// The law for one contact of a pair with parameters p (the scalar path: width one).
VERIDEM_HOT_INLINE ContactOutput evaluateContact(const PairParams& p, const ContactInput& in,
                                                 ContactHistory& history, Real dt)
{
    return withLawModel(p, [&](auto model) VERIDEM_INLINE_LAMBDA
                        { return contactLaw<decltype(model), Real>(lawParams(p), in, history, dt); });
}

/// evaluateContact that also reports the law's intermediate terms into `terms` (diagnostics).
inline ContactOutput evaluateContactReporting(const PairParams& p, const ContactInput& in,
                                              ContactHistory& history, Real dt, LawTerms& terms)
{
    return withLawModel(p,
                        [&](auto model) {
                            return contactLaw<decltype(model), Real, false, LawTerms>(lawParams(p), in,
                                                                                      history, dt, &terms);
                        });
}

/// The touch criterion's reach of a pair [m]: the largest separation (r_i + r_j minus the centre
/// distance, negated) at which a contact of its model and effective radius R* [m] still acts: JKR
/// |delta_c| (models/cohesion.h), 0 for every other model (they act only while delta > 0).
inline Real touchReach(const PairParams& p, Real effectiveRadius)
{
    if (p.normalModel != NormalModel::Jkr || !(p.workOfAdhesion > 0))
        return 0;
    return -jkrBreakingOverlap<Real>(p.effectiveModulus, effectiveRadius, p.workOfAdhesion);
}

/// Rolling friction as a length [m] for a contact of rolling radius R_r [m].
inline Real rollingFrictionLength(const PairParams& p, Real rollingRadius)
{
    return p.rollingLength + p.rollingDimensionless * rollingRadius;
}

} // namespace veridem::dem
