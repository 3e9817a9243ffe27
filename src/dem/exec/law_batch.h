// The contact law run on a batch of contacts in SIMD lanes: the batch's inputs and outputs, one
// array per component (LawBatch), the pair parameters per lane (LaneParams) or broadcast (UniformLaw),
// and lawLanes, which instantiates the law (contactLaw, dem/contact_law.h, one template over the
// number type) at the lane width and runs each model of the batch once over it. Pairs
// (dem/pair_kernel.cpp) and walls (dem/wall_forces.cpp) fill a LawBatch and read it back.
//
// One contact is a chain of dependent divisions and square roots (normal, lever arms, m*, the
// end-of-step normal speed, the spring rotation, the Coulomb cap), so a scalar loop waits on
// latency; in lanes independent contacts overlap: four with AVX2 (x86-64-v3), two with SSE2 (the
// portable variant), chosen at run time (exec/isa.h). (Eight AVX-512 lanes measure no faster on
// Zen 4, and 1-3 % on Zen 5, inside the noise: the gathers and the scatter around the arithmetic
// dominate.) No multiply-add is fused (-ffp-contract=off), so the bits are those of the scalar path
// (evaluateContact) on every variant (tests/dem/determinism_test.cpp checks it for every model).
// Execution only: the physics is the law's.
#pragma once

#include "dem/contact_law.h"
#include "dem/lanes.h"
#include "dem/world.h"

#include <array>
#include <cstdint>
#include <optional>

namespace veridem::dem::batch
{

using namespace lanes; // Lanes2, Lanes4, kWidth, load, store, broadcast (dem/lanes.h)

inline constexpr std::size_t kBatch = 64; // contacts per batch (a multiple of every width); ~20 KB, in L1

/// One parameter of LawParams in every lane of a batch [the parameter's unit].
using LaneColumn = std::array<double, kBatch>;

/// Pair parameters per lane of a batch (filled only if there is more than one material pair):
/// LawParams' lane twin, one column per field, bound to LawParams by forEachLawParam.
struct LaneParams
{
    alignas(64) LawParamsOf<LaneColumn> column;

    void set(std::size_t m, const LawParams& p)
    {
        forEachLawParam(column, p, [m](LaneColumn& c, Real v) VERIDEM_INLINE_LAMBDA { c[m] = v; });
    }
    /// Lanes [count, padded) repeat lane count - 1 (padding).
    void pad(std::size_t count, std::size_t padded)
    {
        forEachLawParam(column, column,
                        [&](LaneColumn& c, const LaneColumn&)
                        {
                            for (std::size_t m = count; m < padded; ++m)
                                c[m] = c[count - 1];
                        });
    }
};

/// The pair parameters in lanes: broadcast once per kernel call if there is one material pair
/// (`uniform`), else loaded per lane from a LaneParams.
template <class Lanes>
VERIDEM_HOT_INLINE LawParamsOf<Lanes> laneLawParams(const LawParams* uniform, const LaneParams& law,
                                                    std::size_t m)
{
    LawParamsOf<Lanes> p{};
    if (uniform)
        forEachLawParam(p, *uniform, [](Lanes& v, Real u) VERIDEM_INLINE_LAMBDA { v = broadcast<Lanes>(u); });
    else
        forEachLawParam(p, law.column,
                        [m](Lanes& v, const LaneColumn& c) VERIDEM_INLINE_LAMBDA
                        { v = load<Lanes>(c.data() + m); });
    return p;
}

/// The law of a world with a single material pair: its parameters and model bit (no table look-up
/// per contact).
struct UniformLaw
{
    LawParams params;
    unsigned models; // 1 << lawModelIndex
};

/// A batch of touching contacts for the lane law, pairs or walls: the contact inputs as the scalar
/// path computes them (pairContactScalar, wallContactInput), one array per component, and the
/// law's outputs. The rolling inputs and outputs are filled only if a model of the batch has
/// rolling resistance (`rolling`).
struct LawBatch
{
    LaneParams law;
    alignas(32) double nx[kBatch], ny[kBatch], nz[kBatch], overlap[kBatch], rvx[kBatch], rvy[kBatch],
        rvz[kBatch], mass[kBatch], hx[kBatch], hy[kBatch], hz[kBatch];
    alignas(32) double wx[kBatch], wy[kBatch], wz[kBatch], radius[kBatch], spinInertia[kBatch],
        rollingInertia[kBatch], rx[kBatch], ry[kBatch], rz[kBatch], ox[kBatch], oy[kBatch], oz[kBatch];
    alignas(32) double normalForce[kBatch], ftx[kBatch], fty[kBatch], ftz[kBatch], springX[kBatch],
        springY[kBatch], springZ[kBatch];
    alignas(32) double torqueX[kBatch], torqueY[kBatch], torqueZ[kBatch], rollingX[kBatch], rollingY[kBatch],
        rollingZ[kBatch];
    // Whether each contact is formed (1) or not (0), before the law (read if `formedKnown`, else
    // taken as 0) and after it (written if `jkr`): the state of the JKR touch criterion.
    alignas(32) double formed[kBatch];
    std::uint32_t slot[kBatch], particle[kBatch];
    std::uint8_t model[kBatch]; // lawModelIndex of each contact's pair
    unsigned models = 0;        // bit lawModelIndex set for every model in the batch
    bool rolling = false;       // some model of the batch has rolling resistance
    bool jkr = false;           // some model of the batch is JKR (kJkrModels)
    bool formedKnown = false;   // `formed` holds the contacts' states (pairs; walls keep none)

    /// Contact m's inputs: its slot and particle, unit normal, overlap [m], relative contact
    /// velocity [m/s], effective mass [kg] and stored spring [m].
    VERIDEM_HOT_INLINE void setInputs(std::size_t m, std::size_t k, std::uint32_t i, const Vec3& normal,
                                      Real overlapDepth, const Vec3& relativeVelocity, Real effectiveMass,
                                      const Vec3& spring)
    {
        slot[m] = static_cast<std::uint32_t>(k);
        particle[m] = i;
        nx[m] = normal.x;
        ny[m] = normal.y;
        nz[m] = normal.z;
        overlap[m] = overlapDepth;
        rvx[m] = relativeVelocity.x;
        rvy[m] = relativeVelocity.y;
        rvz[m] = relativeVelocity.z;
        mass[m] = effectiveMass;
        hx[m] = spring.x;
        hy[m] = spring.y;
        hz[m] = spring.z;
    }
    /// Contact m's rolling inputs: relative angular velocity [rad/s], R* [m], spin and rolling
    /// inertia [kg m^2], stored rolling spring [N m].
    VERIDEM_HOT_INLINE void setRollingInputs(std::size_t m, const ContactInput& in, const Vec3& rollingSpring)
    {
        wx[m] = in.relativeAngularVelocity.x;
        wy[m] = in.relativeAngularVelocity.y;
        wz[m] = in.relativeAngularVelocity.z;
        radius[m] = in.effectiveRadius;
        spinInertia[m] = in.spinInertia;
        rollingInertia[m] = in.rollingInertia;
        ox[m] = in.angularVelocity.x;
        oy[m] = in.angularVelocity.y;
        oz[m] = in.angularVelocity.z;
        rx[m] = rollingSpring.x;
        ry[m] = rollingSpring.y;
        rz[m] = rollingSpring.z;
    }
    /// Contact q's rolling torque [N m] and updated rolling spring [N m] (zero without rolling).
    Vec3 rollingTorqueOf(std::size_t q) const
    {
        return rolling ? Vec3{torqueX[q], torqueY[q], torqueZ[q]} : Vec3{};
    }
    Vec3 rollingSpringOf(std::size_t q) const
    {
        return rolling ? Vec3{rollingX[q], rollingY[q], rollingZ[q]} : Vec3{};
    }
    /// The arrays of the inputs (padding lanes repeat the last contact).
    std::array<double*, 24> inputs()
    {
        return {nx, ny,     nz,          overlap,        rvx, rvy, rvz, mass, hx, hy, hz,    wx, wy,
                wz, radius, spinInertia, rollingInertia, rx,  ry,  rz,  ox,   oy, oz, formed};
    }
};

/// lawLanesOf with the parameters known to be uniform (kUniform) or per lane.
template <class Model, class Lanes, bool kProjected, bool kAll, bool kUniform>
VERIDEM_HOT_INLINE void lawLanesWith(LawBatch& b, std::size_t padded, Real dt, const LawParams* uniform,
                                     unsigned index)
{
    constexpr std::size_t kLanes = kWidth<Lanes>;
    constexpr bool kRolling = Model::rolling != RollingModel::None;
    const LawParamsOf<Lanes> fixed = laneLawParams<Lanes>(kUniform ? uniform : nullptr, b.law, 0);
    for (std::size_t m = 0; m < padded; m += kLanes)
    {
        const auto l = [&](const double* a) VERIDEM_INLINE_LAMBDA { return load<Lanes>(a + m); };
        ContactInputOf<Lanes> in;
        in.normal = {l(b.nx), l(b.ny), l(b.nz)};
        in.overlap = l(b.overlap);
        in.relativeVelocity = {l(b.rvx), l(b.rvy), l(b.rvz)};
        in.effectiveMass = l(b.mass);
        ContactHistoryOf<Lanes> h;
        h.tangentialSpring = {l(b.hx), l(b.hy), l(b.hz)};
        if constexpr (kRolling || isHertzian(Model::normal))
            in.effectiveRadius = l(b.radius);
        if constexpr (Model::normal == NormalModel::Jkr)
            if (b.formedKnown)
                h.formed = l(b.formed);
        if constexpr (kRolling)
        {
            in.relativeAngularVelocity = {l(b.wx), l(b.wy), l(b.wz)};
            in.spinInertia = l(b.spinInertia);
            in.rollingInertia = l(b.rollingInertia);
            h.rollingSpring = {l(b.rx), l(b.ry), l(b.rz)};
            if constexpr (Model::rolling == RollingModel::ConstantTorqueAbsolute)
                in.angularVelocity = {l(b.ox), l(b.oy), l(b.oz)};
        }
        ContactOutputOf<Lanes> out;
        if constexpr (kUniform)
            out = contactLaw<Model, Lanes, kProjected>(fixed, in, h, dt);
        else
            out = contactLaw<Model, Lanes, kProjected>(laneLawParams<Lanes>(nullptr, b.law, m), in, h, dt);
        const auto put = [&](double* a, const Lanes& v) VERIDEM_INLINE_LAMBDA
        {
            if constexpr (kAll)
                store(a + m, v);
            else
                for (std::size_t q = 0; q < kLanes; ++q)
                    if (b.model[m + q] == index)
                        a[m + q] = v[q];
        };
        put(b.normalForce, out.normalForce);
        put(b.ftx, out.tangentialForce.x);
        put(b.fty, out.tangentialForce.y);
        put(b.ftz, out.tangentialForce.z);
        put(b.springX, h.tangentialSpring.x);
        put(b.springY, h.tangentialSpring.y);
        put(b.springZ, h.tangentialSpring.z);
        if (b.jkr)
            put(b.formed, h.formed);
        if (b.rolling)
        {
            put(b.torqueX, out.rollingTorque.x);
            put(b.torqueY, out.rollingTorque.y);
            put(b.torqueZ, out.rollingTorque.z);
            put(b.rollingX, h.rollingSpring.x);
            put(b.rollingY, h.rollingSpring.y);
            put(b.rollingZ, h.rollingSpring.z);
        }
    }
}

/// The law for the lanes [0, padded) of `b` with the models `Model`, results into `b`'s outputs:
/// all lanes (kAll), or the lanes whose model is `index`. Parameters: `uniform` in every lane, or
/// per lane from b.law if it is null.
template <class Model, class Lanes, bool kProjected, bool kAll>
VERIDEM_HOT_INLINE void lawLanesOf(LawBatch& b, std::size_t padded, Real dt, const LawParams* uniform,
                                   unsigned index)
{
    // A model with history scalars never reaches the lanes: the force stage runs such scenes one
    // contact at a time (dem/forces.cpp, dem/wall_forces.cpp), since the batch carries no scalars.
    if constexpr (historyScalarsOf(Model::normal) > 0)
        unregisteredContactModel(static_cast<unsigned>(Model::normal));
    else if (uniform)
        lawLanesWith<Model, Lanes, kProjected, kAll, true>(b, padded, dt, uniform, index);
    else
        lawLanesWith<Model, Lanes, kProjected, kAll, false>(b, padded, dt, uniform, index);
}

/// lawLanes for a batch of several models: each model present runs over the whole batch, and
/// each contact keeps its own model's results (out of line: it is rare).
template <class Lanes, bool kProjected>
[[gnu::noinline]] void mixedLawLanes(LawBatch& b, std::size_t padded, Real dt, const LawParams* uniform)
{
    forEachLawModel(b.models,
                    [&](auto model, unsigned index) VERIDEM_INLINE_LAMBDA {
                        lawLanesOf<decltype(model), Lanes, kProjected, false>(b, padded, dt, uniform, index);
                    });
}

/// The contact law of the contacts [0, count) of `b` in lanes (the same law and bits as
/// evaluateContact; a wall is a partner of infinite mass, so m* = m). kProjected: b's springs are
/// already in the tangent plane (the pair kernel's input pass rotates them). Each model of the
/// batch runs once over the batch, and a contact takes the results of its own model.
template <class Lanes, bool kProjected>
VERIDEM_HOT_INLINE void lawLanes(LawBatch& b, std::size_t count, Real dt, const LawParams* uniform)
{
    constexpr std::size_t kLanes = kWidth<Lanes>;
    const std::size_t padded = (count + kLanes - 1) / kLanes * kLanes;
    for (std::size_t m = count; m < padded; ++m) // padding lanes repeat the last contact
    {
        for (double* a : b.inputs())
            a[m] = a[count - 1];
        b.model[m] = b.model[count - 1];
    }
    if (!uniform)
        b.law.pad(count, padded);
    if ((b.models & (b.models - 1)) == 0) // one model: every lane takes its results
        forEachLawModel(
            b.models, [&](auto model, unsigned index) VERIDEM_INLINE_LAMBDA
            { lawLanesOf<decltype(model), Lanes, kProjected, true>(b, padded, dt, uniform, index); });
    else
        mixedLawLanes<Lanes, kProjected>(b, padded, dt, uniform);
}

/// The laws of the contacts [0, padded) of `b`: the uniform law's model, or each contact's pair
/// (pairOf(m)) parameters and model.
template <class PairOf>
VERIDEM_HOT_INLINE void setBatchLaws(LawBatch& b, std::size_t padded, const UniformLaw* uniform,
                                     const PairOf& pairOf)
{
    if (uniform)
        b.models = uniform->models;
    else
    {
        b.models = 0;
        for (std::size_t m = 0; m < padded; ++m)
        {
            const PairParams& pp = pairOf(m);
            const unsigned model = lawModelIndex(pp);
            b.law.set(m, lawParams(pp));
            b.model[m] = static_cast<std::uint8_t>(model);
            b.models |= 1u << model;
        }
    }
    b.rolling = (b.models & kRollingModels) != 0;
    b.jkr = (b.models & kJkrModels) != 0;
}

/// Contact m's law, if the world has more than one pair: its pair's parameters and model.
VERIDEM_HOT_INLINE void addContactLaw(LawBatch& b, std::size_t m, const PairParams& pp)
{
    const unsigned model = lawModelIndex(pp);
    b.law.set(m, lawParams(pp));
    b.model[m] = static_cast<std::uint8_t>(model);
    b.models |= 1u << model;
}

/// Before the law of a batch filled by addContactLaw: the models it holds; after it, `models` is
/// reset for the next batch by the caller (finishBatchLaws sets, the kernel reads).
VERIDEM_HOT_INLINE void finishBatchLaws(LawBatch& b, const UniformLaw* uniform)
{
    if (uniform)
        b.models = uniform->models;
    b.rolling = (b.models & kRollingModels) != 0;
    b.jkr = (b.models & kJkrModels) != 0;
}

/// The law of the world's single material pair, if it has one.
inline std::optional<UniformLaw> uniformLaw(const World& world)
{
    if (world.pairs.count() != 1)
        return std::nullopt;
    const PairParams& p = world.pairs(0, 0);
    return UniformLaw{lawParams(p), 1u << lawModelIndex(p)};
}

/// Per-batch laws of a world with several materials (up to kMaxBatchLawMaterials): entry
/// a * materials + b is the law of the ordered material pair (a, b), the same lawParams of the same
/// PairParams that the per-lane look-up (addContactLaw, LawBatch::law) would set, so a batch given
/// one of them computes the same bits, broadcast instead of looked up and loaded lane by lane. Pairs
/// (dem/forces.cpp) and walls (dem/wall_forces.cpp: the particle's and the wall's material) use it.
inline constexpr std::uint32_t kMaxBatchLawMaterials = 4;
struct BatchLaws
{
    std::uint32_t materials = 0; // 0: no per-batch laws (one material, or more than the maximum)
    UniformLaw law[kMaxBatchLawMaterials * kMaxBatchLawMaterials];
};

/// The per-batch laws of `world` (none if it has a single law, `uniform`, or too many materials).
inline BatchLaws batchLaws(const World& world, const UniformLaw* uniform)
{
    BatchLaws laws;
    const std::uint32_t count = world.pairs.count();
    if (uniform || count > kMaxBatchLawMaterials)
        return laws;
    laws.materials = count;
    for (std::uint32_t a = 0; a < count; ++a)
        for (std::uint32_t b = 0; b < count; ++b)
        {
            const PairParams& pp = world.pairs(a, b);
            laws.law[a * count + b] = UniformLaw{lawParams(pp), 1u << lawModelIndex(pp)};
        }
    return laws;
}

/// The law of the contacts [0, count) of `b`, contact m joining the materials first[m] and
/// second[m] (in that order): `uniform` if the world has one; the per-batch law of their ordered
/// pair if they all join the same one (a bed of one material on a steel wall: nearly every batch);
/// else null, after setting each contact's law in `b` (addContactLaw) for the per-lane look-up.
/// Sets b's model flags for the law (finishBatchLaws).
VERIDEM_HOT_INLINE const UniformLaw* lawOfContacts(const World& world, const BatchLaws& laws,
                                                   const UniformLaw* uniform, LawBatch& b, std::size_t count,
                                                   const std::uint32_t* first, const std::uint32_t* second)
{
    const UniformLaw* law = uniform;
    if (!law && laws.materials != 0)
    {
        bool one = true;
        for (std::size_t m = 1; m < count; ++m)
            one = one && first[m] == first[0] && second[m] == second[0];
        if (one)
            law = &laws.law[first[0] * laws.materials + second[0]];
    }
    if (!law)
        for (std::size_t m = 0; m < count; ++m)
            addContactLaw(b, m, world.pairs(first[m], second[m]));
    finishBatchLaws(b, law);
    return law;
}

} // namespace veridem::dem::batch
