// Above 500 lines: the force stage with its execution machinery (instruction-set dispatch, batches,
// block sums, the thread split); splitting the machinery into its own module is the next step of
// the contact-core rebuild (docs/architecture.md, "Contact law").
// Contact lever arms ("contact radius convention", docs/models.md):
//  * sphere-wall: the lever arm is the undeformed radius r. The contact-point velocity
//    v + w x (-r n) and the torque (-r n) x Ft use the same arm, so the discrete dynamics are
//    exactly those of a rigid ball of radius r rolling on the wall (v = r w when rolling), which
//    is what the analytical solutions assume (2/7 Omega orbit, 5/7 v0 bowling ball).
//  * sphere-sphere: the contact point divides the centre distance d in the ratio of the radii,
//    l_i = r_i d / (r_i + r_j), so l_i + l_j = d and the tangential force conserves the total
//    angular momentum exactly (with r_i alone it would be violated by delta n x Ft).
//
// Parallel layout (STYLE 3.4, neighbor_list.h): the pair loop runs over fixed blocks of particles,
// each thread a contiguous range of blocks, and adds every contact straight into its particles'
// force and torque, except the share of a second particle in a later block, which goes to the
// slot's deferred entry; a per-particle pass then adds the deferred entries in slot order, and the
// wall contacts, per particle, in slot order. No sum depends on the thread schedule. The health
// record (largest overlap) is reduced per chunk and combined in chunk order, so it too is
// independent of the thread count.
#include "dem/forces.h"

#include "core/error.h"
#include "dem/contact_law.h"
#include "dem/lanes.h"
#include "dem/parallel.h"

#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <cstdlib>
#include <cstring>
#include <immintrin.h>
#include <optional>
#include <string>

namespace veridem::dem
{

namespace
{

constexpr int kMaxChunks = 64;

struct WorstOverlap // the running largest overlap of a chunk's contacts
{
    Real ratio;
    std::uint32_t particle;
    bool found;

    /// overlap / radius > ratio, without the division (radius > 0 [m]; overlap [m]); the division
    /// is paid only when the worst contact changes, which is rare.
    bool exceededBy(Real overlap, Real radius) const { return overlap > ratio * radius; }
};

/// Folds per-chunk health into world health in chunk order (strictly greater wins: the first slot
/// with the largest ratio, as a serial loop would find); sets `touching` to the chunks' total.
void foldHealth(StepHealth& health, const ContactHealth* chunk, int chunks, std::size_t& touching)
{
    touching = 0;
    for (int c = 0; c < chunks; ++c)
    {
        touching += chunk[c].touching;
        if (chunk[c].found && chunk[c].maxOverlapRatio > health.maxOverlapRatio)
        {
            health.maxOverlapRatio = chunk[c].maxOverlapRatio;
            health.worstParticle = chunk[c].worstParticle;
        }
    }
}

/// Where the pair loop writes. Array bases are held in locals: a byte store (mayBeActive) may alias
/// anything, so GCC would otherwise reload every vector's pointer after it.
struct PairSink
{
    PaddedVec3* force;                     // per-particle sums [N] (ParticleStore::force)
    PaddedVec3* torque;                    // [N m]
    const std::uint32_t* deferredIndex;    // per candidate, or NeighborList::kInBlock
    NeighborList::DeferredShare* deferred; // on the second particle of a cross-block slot
    Vec3* spring;                          // tangential spring per candidate [m]
    Vec3* rolling;                         // rolling spring per candidate [N m], or null if none is kept
    std::uint8_t* mayBeActive;             // per candidate

    explicit PairSink(World& world)
        : force(world.particles.force.data()), torque(world.particles.torque.data()),
          deferredIndex(world.neighbors.activeDeferred.data()), deferred(world.neighbors.deferred.data()),
          spring(world.neighbors.activeSpring.data()),
          rolling(world.neighbors.keepRollingHistory ? world.neighbors.activeRolling.data() : nullptr),
          mayBeActive(world.neighbors.activeMayBeActive.data())
    {
    }

    static void add(PaddedVec3& sum, const Vec3& v)
    {
        sum.x += v.x;
        sum.y += v.y;
        sum.z += v.z;
    }
    static void subtract(PaddedVec3& sum, const Vec3& v)
    {
        sum.x -= v.x;
        sum.y -= v.y;
        sum.z -= v.z;
    }

    /// Adds the contact of candidate k: force f [N] on i and -f on j, torques ti on i and tj on j
    /// [N m].
    void add(std::uint32_t k, std::uint32_t i, std::uint32_t j, const Vec3& f, const Vec3& ti,
             const Vec3& tj) const
    {
        add(force[i], f);
        add(torque[i], ti);
        const std::uint32_t d = deferredIndex[k];
        if (d == NeighborList::kInBlock)
        {
            subtract(force[j], f);
            add(torque[j], tj);
        }
        else
        {
            deferred[d].force = -f;
            deferred[d].torque = tj;
        }
    }
};

// ---------------------------------------------------------------------------------------------
// Contacts in vector lanes (every model).
//
// One contact is a chain of dependent divisions and square roots (normal, lever arms, m*, the
// end-of-step normal speed, the spring rotation, the Coulomb cap), so a scalar loop waits on
// latency. Here the same law (contactLaw, contact_law.h, a template over the number type) runs
// on independent contacts in the lanes of a GCC vector type: four with AVX2 (x86-64-v3), two with
// SSE2 (the portable variant), chosen at run time from the CPU. (Eight AVX-512 lanes measure no
// faster on Zen 4, and 1-3 % on Zen 5, inside the noise: the gathers and the scatter around the
// arithmetic dominate.) No multiply-add is fused (-ffp-contract=off), so the bits are those of
// the scalar path (pairContactScalar + evaluateContact) on every variant
// (tests/dem/determinism_test.cpp checks it for every model). Pairs and walls share LawBatch.
// ---------------------------------------------------------------------------------------------
using namespace lanes; // Lanes2, Lanes4, Index4, kWidth, load, store (dem/lanes.h)

/// Four contacts' x, y, z lanes -> one (x, y, z, 0) vector per contact: unpacks within 128-bit
/// halves, then half swaps (8 shuffles; interleaving across halves first costs 14).
VERIDEM_HOT_INLINE void transpose(const Lanes4& x, const Lanes4& y, const Lanes4& z, Lanes4* out)
{
    const Lanes4 zero = {};
    const Lanes4 xyEven = __builtin_shufflevector(x, y, 0, 4, 2, 6);    // x0 y0 x2 y2
    const Lanes4 xyOdd = __builtin_shufflevector(x, y, 1, 5, 3, 7);     // x1 y1 x3 y3
    const Lanes4 z0Even = __builtin_shufflevector(z, zero, 0, 4, 2, 6); // z0 0 z2 0
    const Lanes4 z0Odd = __builtin_shufflevector(z, zero, 1, 5, 3, 7);  // z1 0 z3 0
    out[0] = __builtin_shufflevector(xyEven, z0Even, 0, 1, 4, 5);
    out[1] = __builtin_shufflevector(xyOdd, z0Odd, 0, 1, 4, 5);
    out[2] = __builtin_shufflevector(xyEven, z0Even, 2, 3, 6, 7);
    out[3] = __builtin_shufflevector(xyOdd, z0Odd, 2, 3, 6, 7);
}

/// Two contacts (the portable variant: one SSE2 register per quantity).
VERIDEM_HOT_INLINE void transpose(const Lanes2& x, const Lanes2& y, const Lanes2& z, Lanes4* out)
{
    out[0] = Lanes4{x[0], y[0], z[0], 0.0};
    out[1] = Lanes4{x[1], y[1], z[1], 0.0};
}

/// sum[0..3] += v; sum[0..3] -= v (a PaddedVec3).
VERIDEM_HOT_INLINE void addInto(double* sum, const Lanes4& v)
{
    store(sum, load<Lanes4>(sum) + v);
}
VERIDEM_HOT_INLINE void subtractFrom(double* sum, const Lanes4& v)
{
    store(sum, load<Lanes4>(sum) - v);
}

constexpr std::size_t kPrefetchAhead = 16; // candidates between a prefetch and its use
constexpr std::size_t kBatch = 64;         // contacts per batch (a multiple of every width); ~20 KB, in L1

/// Pair parameters per lane of a batch (filled only if there is more than one material pair):
/// LawParams, one array per field.
struct LaneParams
{
    alignas(64) double kn[kBatch], ktRatio[kBatch], modulus[kBatch], shearModulus[kBatch], rate[kBatch],
        factor[kBatch], etaRatio[kBatch], mu[kBatch], rollingLength[kBatch], rollingDimless[kBatch],
        rollingDamping[kBatch], rollingTwist[kBatch], rollingViscous[kBatch], adhesion[kBatch];

    /// The fields, in LawParams' order.
    std::array<double*, 14> fields()
    {
        return {kn, ktRatio,       modulus,        shearModulus,   rate,         factor,         etaRatio,
                mu, rollingLength, rollingDimless, rollingDamping, rollingTwist, rollingViscous, adhesion};
    }
    void set(std::size_t m, const LawParams& p)
    {
        const std::array<double, 14> values{p.kn,
                                            p.ktRatio,
                                            p.modulus,
                                            p.shearModulus,
                                            p.dampingRate,
                                            p.dampingFactor,
                                            p.etaRatio,
                                            p.mu,
                                            p.rollingLength,
                                            p.rollingDimless,
                                            p.rollingDamping,
                                            p.rollingTwist,
                                            p.rollingViscous,
                                            p.adhesion};
        const std::array<double*, 14> f = fields();
        for (std::size_t k = 0; k < f.size(); ++k)
            f[k][m] = values[k];
    }
};

/// A batch of touching pair contacts: their candidate indices (NeighborList::activeSlots) and
/// particles, and the geometry the selection pass computed for its distance test: the separation
/// x_i - x_j [m] and the radii r_i, r_j [m] (the same values the kernel would compute again, so
/// it reads them here instead of gathering both particles' positions and radii a second time).
/// The kernel loads the rest straight into lanes.
struct PairBatch
{
    std::uint32_t candidate[kBatch], i[kBatch], j[kBatch];
    alignas(32) double sx[kBatch], sy[kBatch], sz[kBatch], ri[kBatch], rj[kBatch];
};

/// Lanes l = a[index[l]].*field (element loads and inserts, no staging through memory).
template <class V> VERIDEM_HOT_INLINE V gather(const Vec3* a, const std::uint32_t* index, double Vec3::*field)
{
    if constexpr (kWidth<V> == 4)
        return V{a[index[0]].*field, a[index[1]].*field, a[index[2]].*field, a[index[3]].*field};
    else
        return V{a[index[0]].*field, a[index[1]].*field};
}
template <class V> VERIDEM_HOT_INLINE V gather(const double* a, const std::uint32_t* index)
{
    if constexpr (kWidth<V> == 4)
        return V{a[index[0]], a[index[1]], a[index[2]], a[index[3]]};
    else
        return V{a[index[0]], a[index[1]]};
}

/// The three components of a[index[l]] in lanes. Four lanes: (x, y) of each vector with one
/// 16-byte load, two of them joined per register and split by unpacking (4 shuffles for x and y
/// instead of 6 with element inserts: the shuffle port bounds the four-lane kernel on Zen 3).
template <class V> struct Lanes3
{
    V x, y, z;
};
template <class V> VERIDEM_HOT_INLINE Lanes3<V> gatherVec3(const Vec3* a, const std::uint32_t* index)
{
    if constexpr (kWidth<V> == 4)
    {
        const Lanes2 xy0 = load<Lanes2>(&a[index[0]].x), xy1 = load<Lanes2>(&a[index[1]].x),
                     xy2 = load<Lanes2>(&a[index[2]].x), xy3 = load<Lanes2>(&a[index[3]].x);
        const Lanes4 even = __builtin_shufflevector(xy0, xy2, 0, 1, 2, 3); // x0 y0 x2 y2
        const Lanes4 odd = __builtin_shufflevector(xy1, xy3, 0, 1, 2, 3);  // x1 y1 x3 y3
        return {__builtin_shufflevector(even, odd, 0, 4, 2, 6),
                __builtin_shufflevector(even, odd, 1, 5, 3, 7), gather<V>(a, index, &Vec3::z)};
    }
    else
        return {gather<V>(a, index, &Vec3::x), gather<V>(a, index, &Vec3::y), gather<V>(a, index, &Vec3::z)};
}

/// The touching-candidate sub-list of a chunk as the selection pass reads it (array bases in one
/// place: NeighborList::activeFirst/activeSecond and activeMayBeActive, the particles' positions
/// [m] and radii [m]).
struct Candidates
{
    const std::uint32_t* first;
    const std::uint32_t* second;
    const Vec3* position;
    const Real* radius;
    const PaddedVec3* positionRadius; // (x, y, z, r) per particle: position and radius in one row
    const std::uint8_t* mayBeActive;
    std::size_t end; // one past the chunk's last candidate
    Real reach;      // NeighborList::reach [m]: a pair within r_i + r_j + reach is passed to the law
};

/// The selection pass from candidate a on: appends each touching one (a, i, j) to the batch at
/// m ("touching": within r_i + r_j + reach, the models' touch criterion, see NeighborList::reach),
/// m, and records at opened[o] each one found open that may have been in contact (its history is
/// cleared by the caller). Stops at the chunk's end, when the batch or `opened` is full (kBatch),
/// or at the first candidate of a new block (first particle >= zeroedEnd), whose sums the caller
/// zeroes first. Returns where it stopped. Branch-free per candidate but for those stops; calls
/// nothing, so the array bases stay in registers.
VERIDEM_HOT_INLINE std::size_t selectTouchingScalar(const Candidates& c, std::size_t a, std::size_t zeroedEnd,
                                                    PairBatch& b, std::size_t& m, std::uint32_t* opened,
                                                    std::size_t& o)
{
    // Everything in locals: GCC cannot tell that the batch stores leave m, o and c unchanged.
    const std::uint32_t *const first = c.first, *const second = c.second;
    const Vec3* const position = c.position;
    const Real* const radius = c.radius;
    const std::uint8_t* const mayBeActive = c.mayBeActive;
    const Real reach = c.reach;
    const std::size_t end = c.end, last = c.end - 1;
    std::size_t touchingEnd = m, openedEnd = o;
    for (; a < end && touchingEnd < kBatch && openedEnd < kBatch; ++a)
    {
        const std::uint32_t k = static_cast<std::uint32_t>(a), i = first[a], j = second[a];
        if (__builtin_expect(i >= zeroedEnd, 0)) // a new block
            break;
        // The partner's position kPrefetchAhead candidates on, into cache: j jumps across the
        // Morton order (the neighbours above and below), and on a 512 KB L2 its rows often come
        // from L3. (The kernel fetches the rest of its rows ahead.)
        __builtin_prefetch(&position[second[std::min(a + kPrefetchAhead, last)]]);
        const Vec3 &xi = position[i], &xj = position[j];
        const Real ri = radius[i], rj = radius[j];
        const Real sx = xi.x - xj.x, sy = xi.y - xj.y, sz = xi.z - xj.z;
        const Real touching = ri + rj + reach;
        const bool isTouching = sx * sx + sy * sy + sz * sz < touching * touching;
        b.candidate[touchingEnd] = k;
        b.i[touchingEnd] = i;
        b.j[touchingEnd] = j;
        b.sx[touchingEnd] = sx;
        b.sy[touchingEnd] = sy;
        b.sz[touchingEnd] = sz;
        b.ri[touchingEnd] = ri;
        b.rj[touchingEnd] = rj;
        touchingEnd += isTouching;
        opened[openedEnd] = k; // kept if it was in contact and is no more (rare)
        openedEnd += mayBeActive[k] & static_cast<std::uint8_t>(!isTouching);
    }
    m = touchingEnd;
    o = openedEnd;
    return a;
}

/// The pair parameters in lanes: broadcast once per kernel call if there is one material pair
/// (`uniform`), else loaded per lane from a LaneParams.
template <class Lanes>
VERIDEM_HOT_INLINE LawParamsOf<Lanes> laneLawParams(const LawParams* uniform, const LaneParams& law,
                                                    std::size_t m)
{
    if (uniform)
    {
        const auto b = [](Real v) VERIDEM_INLINE_LAMBDA { return broadcast<Lanes>(v); };
        return {b(uniform->kn),
                b(uniform->ktRatio),
                b(uniform->modulus),
                b(uniform->shearModulus),
                b(uniform->dampingRate),
                b(uniform->dampingFactor),
                b(uniform->etaRatio),
                b(uniform->mu),
                b(uniform->rollingLength),
                b(uniform->rollingDimless),
                b(uniform->rollingDamping),
                b(uniform->rollingTwist),
                b(uniform->rollingViscous),
                b(uniform->adhesion)};
    }
    const auto l = [&](const double* a) VERIDEM_INLINE_LAMBDA { return load<Lanes>(a + m); };
    return {l(law.kn),
            l(law.ktRatio),
            l(law.modulus),
            l(law.shearModulus),
            l(law.rate),
            l(law.factor),
            l(law.etaRatio),
            l(law.mu),
            l(law.rollingLength),
            l(law.rollingDimless),
            l(law.rollingDamping),
            l(law.rollingTwist),
            l(law.rollingViscous),
            l(law.adhesion)};
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
    if (uniform)
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
        if (!uniform)
            for (double* a : b.law.fields())
                a[m] = a[count - 1];
    }
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

/// The inputs beyond the linear law's of the pair contacts [0, padded) of `b` (R*, the inertias,
/// the relative angular velocity, the stored rolling spring), as pairContactScalar computes them.
[[gnu::noinline]] void pairExtraInputs(const World& world, const PairBatch& b, LawBatch& law,
                                       std::size_t padded)
{
    const ParticleStore& p = world.particles;
    const NeighborList& list = world.neighbors;
    for (std::size_t m = 0; m < padded; ++m)
    {
        const std::uint32_t i = b.i[m], j = b.j[m];
        const Real ri = b.ri[m], rj = b.rj[m];
        ContactInput in;
        in.relativeAngularVelocity = p.angularVelocity[i] - p.angularVelocity[j];
        in.angularVelocity = p.angularVelocity[i];
        in.effectiveRadius = ri * rj / (ri + rj);
        in.spinInertia = 1.0 / (p.invInertia[i] + p.invInertia[j]);
        in.rollingInertia = 1.0 / (1.0 / (1.0 / p.invInertia[i] + p.mass[i] * ri * ri) +
                                   1.0 / (1.0 / p.invInertia[j] + p.mass[j] * rj * rj));
        law.setRollingInputs(m, in, list.keepRollingHistory ? list.activeRolling[b.candidate[m]] : Vec3{});
    }
}

/// The law of the world's single material pair, if it has one.
std::optional<UniformLaw> uniformLaw(const World& world)
{
    if (world.pairs.count() != 1)
        return std::nullopt;
    const PairParams& p = world.pairs(0, 0);
    return UniformLaw{lawParams(p), 1u << lawModelIndex(p)};
}

/// lawLanes on four (AVX2) or two lanes, the springs already in the tangent plane (the pair kernel).
[[gnu::noinline]] VERIDEM_AVX2_TARGET void projectedLawAvx2(LawBatch& b, std::size_t count, Real dt,
                                                            const LawParams* uniform)
{
    lawLanes<Lanes4, true>(b, count, dt, uniform);
}
[[gnu::noinline]] void projectedLawPortable(LawBatch& b, std::size_t count, Real dt, const LawParams* uniform)
{
    lawLanes<Lanes2, true>(b, count, dt, uniform);
}

/// Adds contact q of batch `b` to the sink: force f [N] on i and -f on j, torques ti on i and tj
/// on j [N m] (vectors (x, y, z, 0)), or j's share to the slot's deferred entry; stores the new
/// tangential spring [m] and marks the candidate mayBeActive.
VERIDEM_HOT_INLINE void scatterContact(const PairSink& sink, const PairBatch& b, std::size_t q,
                                       const Lanes4& f, const Lanes4& ti, const Lanes4& tj,
                                       const Lanes4& spring)
{
    const std::uint32_t k = b.candidate[q], i = b.i[q], j = b.j[q];
    sink.mayBeActive[k] = 1;
    std::memcpy(&sink.spring[k].x, &spring, 3 * sizeof(double)); // x, y, z of (x, y, z, 0)
    addInto(&sink.force[i].x, f);
    addInto(&sink.torque[i].x, ti);
    const std::uint32_t d = sink.deferredIndex[k];
    if (d == NeighborList::kInBlock)
    {
        subtractFrom(&sink.force[j].x, f);
        addInto(&sink.torque[j].x, tj);
    }
    else
    {
        // -f in x, y, z (a sign flip, as the scalar path's); the padding stays +0.
        const Index4 flipXyz = {INT64_MIN, INT64_MIN, INT64_MIN, 0};
        store(&sink.deferred[d].force.x, reinterpret_cast<Lanes4>(reinterpret_cast<Index4>(f) ^ flipXyz));
        store(&sink.deferred[d].torque.x, tj);
    }
}

/// Evaluates the touching contacts [0, count) of `b` (count <= kBatch; slot, i and j collected by
/// the caller; the law batchable) and adds them into
/// the sink in lane order, exactly as the scalar path does. `uniform`: the pair parameters if
/// there is a single material pair (no table look-up), else null.
template <class Lanes>
VERIDEM_HOT_INLINE void pairContactsLanes(const World& world, const PairSink& sink, Real dt,
                                          std::size_t count, WorstOverlap& worst, PairBatch& b,
                                          const UniformLaw* uniform)
{
    constexpr std::size_t kLanes = kWidth<Lanes>;
    using LaneMask = decltype(Lanes{} < Lanes{});
    const ParticleStore& p = world.particles;
    const NeighborList& list = world.neighbors;
    const std::size_t padded = (count + kLanes - 1) / kLanes * kLanes;
    for (std::size_t m = count; m < padded; ++m)
    {
        // Padding lanes repeat the last contact; their results are not written.
        b.candidate[m] = b.candidate[count - 1];
        b.i[m] = b.i[count - 1];
        b.j[m] = b.j[count - 1];
        for (double* a : {b.sx, b.sy, b.sz, b.ri, b.rj})
            a[m] = a[count - 1];
    }
    const Vec3* const velocity = p.velocity.data();
    const Vec3* const angularVelocity = p.angularVelocity.data();
    const Real* const candidateMass = list.activeMass.data();
    // In three passes over the batch, group by group: the contact inputs, the law, the scatter.
    // Each pass's body is short enough for the out-of-order core to overlap one group's chain of
    // divisions and square roots with the next group's (one pass of ~600 instructions a group,
    // more than the reorder buffer, left them in sequence); the inputs and outputs stay in L1.
    LawBatch law;
    alignas(32) double leverIs[kBatch], leverJs[kBatch], minRadii[kBatch];
    setBatchLaws(law, padded, uniform,
                 [&](std::size_t m) VERIDEM_INLINE_LAMBDA -> const PairParams&
                 { return world.pairs(p.material[b.i[m]], p.material[b.j[m]]); });
    if (law.models != 1u) // another model than linear without rolling: R*, inertias, w_rel
        pairExtraInputs(world, b, law, padded);

    const Lanes zero = {}, one = zero + 1.0;
    // No prefetch of the partners' velocity rows: issued directly (two per contact, eight contacts
    // ahead) they measure no faster on the 20k bed, since the out-of-order core hides those loads;
    // the selection pass's prefetch of the positions stays. (Never issue a prefetch from a lambda
    // here: GCC 12 deletes calls of a lambda whose only effect is a prefetch once it is inlined
    // into an always_inline function.)
    // 1. Inputs (as pairContactScalar).
    for (std::size_t m = 0; m < padded; m += kLanes)
    {
        const std::uint32_t *const laneI = b.i + m, *const laneJ = b.j + m, *const laneK = b.candidate + m;
        // x_i - x_j and the radii as the selection pass computed them.
        const Lanes sx = load<Lanes>(b.sx + m), sy = load<Lanes>(b.sy + m), sz = load<Lanes>(b.sz + m);
        const Lanes ri = load<Lanes>(b.ri + m), rj = load<Lanes>(b.rj + m);
        const Lanes touching = ri + rj;
        const Lanes distance2 = sx * sx + sy * sy + sz * sz;
        const Lanes distance = laneSqrt(distance2);
        const LaneMask positive = distance > zero;
        const Lanes reciprocal = one / (distance * touching); // one division for 1/d and d/(r_i + r_j)
        const Lanes inverseDistance = touching * reciprocal;
        const Lanes nx = positive ? sx * inverseDistance : zero;
        const Lanes ny = positive ? sy * inverseDistance : zero;
        const Lanes nz = positive ? sz * inverseDistance : one;
        const Lanes share = positive ? distance * distance * reciprocal : zero;
        const Lanes leverI = ri * share, leverJ = rj * share;
        // Particle and slot data straight into lanes (gatherVec3: paired 16-byte loads).
        const Lanes3<Lanes> wi = gatherVec3<Lanes>(angularVelocity, laneI),
                            wj = gatherVec3<Lanes>(angularVelocity, laneJ);
        const Lanes ax = wi.x * leverI + wj.x * leverJ;
        const Lanes ay = wi.y * leverI + wj.y * leverJ;
        const Lanes az = wi.z * leverI + wj.z * leverJ;
        const Lanes3<Lanes> vi = gatherVec3<Lanes>(velocity, laneI), vj = gatherVec3<Lanes>(velocity, laneJ);
        const Lanes dvx = vi.x - vj.x, dvy = vi.y - vj.y, dvz = vi.z - vj.z;
        const Lanes3<Lanes> h = gatherVec3<Lanes>(sink.spring, laneK);
        store(law.nx + m, nx);
        store(law.ny + m, ny);
        store(law.nz + m, nz);
        store(law.overlap + m, touching - distance);
        store(law.rvx + m, dvx - (ay * nz - az * ny));
        store(law.rvy + m, dvy - (az * nx - ax * nz));
        store(law.rvz + m, dvz - (ax * ny - ay * nx));
        store(law.mass + m, gather<Lanes>(candidateMass, laneK)); // m_i m_j / (m_i + m_j)
        // The spring rotated into the tangent plane here rather than in the law pass (its
        // division and square root): the divider work of the two passes is then about even
        // (two square roots and two divisions here, one division there, per group).
        const V3<Lanes> projected = projectSpring<Lanes>({h.x, h.y, h.z}, {nx, ny, nz});
        store(law.hx + m, projected.x);
        store(law.hy + m, projected.y);
        store(law.hz + m, projected.z);
        store(leverIs + m, leverI);
        store(leverJs + m, leverJ);
        store(minRadii + m, rj < ri ? rj : ri);
    }

    // The JKR touch criterion's state: formed or not at the previous step.
    law.formedKnown = law.jkr;
    if (law.jkr)
        for (std::size_t m = 0; m < padded; ++m)
            law.formed[m] = sink.mayBeActive[b.candidate[m]];

    // 2. The law (lawLanes, as the wall contacts').
    // (In its own function, as the walls': inlined, its register pressure spills the other passes.)
    if constexpr (kWidth<Lanes> == 4)
        projectedLawAvx2(law, padded, dt, uniform ? &uniform->params : nullptr);
    else
        projectedLawPortable(law, padded, dt, uniform ? &uniform->params : nullptr);

    // 3. Forces and torques, scattered in lane (= slot) order; the health record. Compiled with and
    // without rolling torques (kRolling), so that the common case carries none of their work.
    const auto scatter = [&]<bool kRolling>() VERIDEM_INLINE_LAMBDA
    {
        for (std::size_t m = 0; m < padded; m += kLanes)
        {
            const Lanes nx = load<Lanes>(law.nx + m), ny = load<Lanes>(law.ny + m),
                        nz = load<Lanes>(law.nz + m);
            const Lanes normalForce = load<Lanes>(law.normalForce + m), ftx = load<Lanes>(law.ftx + m),
                        fty = load<Lanes>(law.fty + m), ftz = load<Lanes>(law.ftz + m);
            const Lanes leverI = load<Lanes>(leverIs + m), leverJ = load<Lanes>(leverJs + m);
            const Lanes fx = normalForce * nx + ftx, fy = normalForce * ny + fty, fz = normalForce * nz + ftz;
            // Torques: rolling - l_i (n x Ft) on i, -rolling - l_j (n x Ft) on j (rolling = +0 without
            // a rolling model, so -rolling = -0, as the scalar path's).
            const Lanes ttx = ny * ftz - nz * fty, tty = nz * ftx - nx * ftz, ttz = nx * fty - ny * ftx;
            Lanes rx = zero, ry = zero, rz = zero;
            if constexpr (kRolling)
            {
                rx = load<Lanes>(law.torqueX + m);
                ry = load<Lanes>(law.torqueY + m);
                rz = load<Lanes>(law.torqueZ + m);
            }
            const Lanes tix = rx - leverI * ttx, tiy = ry - leverI * tty, tiz = rz - leverI * ttz;
            const Lanes tjx = -rx - leverJ * ttx, tjy = -ry - leverJ * tty, tjz = -rz - leverJ * ttz;

            // Scatter: one (x, y, z, 0) vector per contact and sum.
            Lanes4 force[kLanes], torqueI[kLanes], torqueJ[kLanes], spring[kLanes];
            transpose(fx, fy, fz, force);
            transpose(tix, tiy, tiz, torqueI);
            transpose(tjx, tjy, tjz, torqueJ);
            transpose(load<Lanes>(law.springX + m), load<Lanes>(law.springY + m),
                      load<Lanes>(law.springZ + m), spring);
            const std::size_t lanes = std::min(kLanes, count - m);
            if (kRolling && sink.rolling)
                for (std::size_t l = 0; l < lanes; ++l)
                    sink.rolling[b.candidate[m + l]] = {law.rollingX[m + l], law.rollingY[m + l],
                                                        law.rollingZ[m + l]};
            if (lanes == kLanes) // (a constant trip count: unrolled, every lane index a constant)
            {
#pragma GCC unroll 4
                for (std::size_t l = 0; l < kLanes; ++l)
                    scatterContact(sink, b, m + l, force[l], torqueI[l], torqueJ[l], spring[l]);
            }
            else
                for (std::size_t l = 0; l < lanes; ++l)
                    scatterContact(sink, b, m + l, force[l], torqueI[l], torqueJ[l], spring[l]);

            // The health record, in lane order. One comparison first: the running ratio only grows,
            // so a lane that does not exceed it now cannot exceed it after an earlier lane's update.
            const Lanes overlap = load<Lanes>(law.overlap + m), minRadius = load<Lanes>(minRadii + m);
            if (anyLane(overlap > worst.ratio * minRadius))
                for (std::size_t l = 0; l < lanes; ++l)
                    if (worst.exceededBy(overlap[l], minRadius[l]))
                        worst = {overlap[l] / minRadius[l], b.i[m + l], true};
        }
    };
    if (law.rolling)
        scatter.template operator()<true>();
    else
        scatter.template operator()<false>();
    if (law.jkr) // (scatterContact marked every contact formed)
        for (std::size_t q = 0; q < count; ++q)
            sink.mayBeActive[b.candidate[q]] = law.formed[q] != 0;
}

VERIDEM_AVX2_TARGET void pairContactsAvx2(const World& world, const PairSink& sink, Real dt,
                                          std::size_t count, WorstOverlap& worst, PairBatch& b,
                                          const UniformLaw* uniform)
{
    pairContactsLanes<Lanes4>(world, sink, dt, count, worst, b, uniform);
}

void pairContactsPortable(const World& world, const PairSink& sink, Real dt, std::size_t count,
                          WorstOverlap& worst, PairBatch& b, const UniformLaw* uniform)
{
    pairContactsLanes<Lanes2>(world, sink, dt, count, worst, b, uniform);
}

[[gnu::noinline]] VERIDEM_AVX2_TARGET void wallContactsAvx2(LawBatch& b, std::size_t count, Real dt,
                                                            const LawParams* uniform)
{
    lawLanes<Lanes4, false>(b, count, dt, uniform);
}

[[gnu::noinline]] void wallContactsPortable(LawBatch& b, std::size_t count, Real dt, const LawParams* uniform)
{
    lawLanes<Lanes2, false>(b, count, dt, uniform);
}

/// For each 4-bit mask of lanes, the shuffle indices that move the lanes whose bit is set to the
/// front, in lane order: each lane is kParts consecutive elements of the shuffle, and the
/// elements after the moved lanes are kRest.
template <class T, unsigned kParts, T kRest> struct PackTable
{
    alignas(32) T index[16][4 * kParts];
    constexpr PackTable() : index{}
    {
        for (unsigned mask = 0; mask < 16; ++mask)
        {
            unsigned out = 0;
            for (unsigned lane = 0; lane < 4; ++lane)
                if (mask & (1u << lane))
                {
                    for (unsigned part = 0; part < kParts; ++part)
                        index[mask][kParts * out + part] = static_cast<T>(kParts * lane + part);
                    ++out;
                }
            for (unsigned e = kParts * out; e < 4 * kParts; ++e)
                index[mask][e] = kRest;
        }
    }
};
/// 32-bit lanes moved by a byte shuffle (pshufb; 0x80 zeroes the rest).
constexpr PackTable<std::uint8_t, 4, 0x80> kPackLanesTable;
const __m128i* const kPackLanes = reinterpret_cast<const __m128i*>(kPackLanesTable.index);
/// 64-bit lanes moved as pairs of 32-bit halves (vpermd; the rest take lane 0, never read).
constexpr PackTable<std::int32_t, 2, 0> kPackDoublesTable;

/// The lanes of v selected by `pack` (a kPackDoublesTable row), stored from `out` on (32 bytes).
VERIDEM_AVX2_TARGET VERIDEM_HOT_INLINE void storePacked(double* out, const Lanes4& v, const __m256i& pack)
{
    _mm256_storeu_pd(out, _mm256_castps_pd(_mm256_permutevar8x32_ps(_mm256_castpd_ps(v), pack)));
}

/// selectTouchingScalar with the distance test of four candidates in AVX2 lanes (the same IEEE
/// operations, so the same choices) and their bookkeeping four at a time: the touching ones packed
/// by a byte shuffle, the opened ones (rare) from a bit mask, both in candidate order as there.
VERIDEM_AVX2_TARGET std::size_t selectTouchingAvx2(const Candidates& c, std::size_t a, std::size_t zeroedEnd,
                                                   PairBatch& b, std::size_t& m, std::uint32_t* opened,
                                                   std::size_t& o)
{
    const PaddedVec3* const positionRadius = c.positionRadius;
    const std::uint8_t* const mayBeActive = c.mayBeActive;
    const std::size_t end = c.end;
    const Lanes4 reach = broadcast<Lanes4>(c.reach);
    std::size_t touchingEnd = m, openedEnd = o;
    for (; a + 4 <= end && touchingEnd + 4 <= kBatch && openedEnd + 4 <= kBatch; a += 4)
    {
        const std::uint32_t* const laneI = c.first + a;
        const std::uint32_t* const laneJ = c.second + a;
        if (laneI[3] >= zeroedEnd) // a new block starts in these four (first is ascending)
            break;
        const std::uint32_t* const ahead = c.second + std::min(a + kPrefetchAhead, end - 4);
        for (std::size_t l = 0; l < 4; ++l)
            __builtin_prefetch(&positionRadius[ahead[l]]);
        // Each particle's (x, y, z, r) row in one 32-byte load, four rows transposed to lanes.
        const auto rowLanes = [&](const std::uint32_t* index) __attribute__((always_inline))
        {
            const Lanes4 r0 = load<Lanes4>(&positionRadius[index[0]].x),
                         r1 = load<Lanes4>(&positionRadius[index[1]].x),
                         r2 = load<Lanes4>(&positionRadius[index[2]].x),
                         r3 = load<Lanes4>(&positionRadius[index[3]].x);
            const Lanes4 ab02 = __builtin_shufflevector(r0, r1, 0, 4, 2, 6),
                         ab13 = __builtin_shufflevector(r0, r1, 1, 5, 3, 7),
                         cd02 = __builtin_shufflevector(r2, r3, 0, 4, 2, 6),
                         cd13 = __builtin_shufflevector(r2, r3, 1, 5, 3, 7);
            return std::array<Lanes4, 4>{__builtin_shufflevector(ab02, cd02, 0, 1, 4, 5),
                                         __builtin_shufflevector(ab13, cd13, 0, 1, 4, 5),
                                         __builtin_shufflevector(ab02, cd02, 2, 3, 6, 7),
                                         __builtin_shufflevector(ab13, cd13, 2, 3, 6, 7)};
        };
        const std::array<Lanes4, 4> rowI = rowLanes(laneI), rowJ = rowLanes(laneJ);
        const Lanes4 sx = rowI[0] - rowJ[0], sy = rowI[1] - rowJ[1], sz = rowI[2] - rowJ[2];
        const Lanes4 ri = rowI[3], rj = rowJ[3];
        const Lanes4 touching = ri + rj + reach;
        const Lanes4 distance2 = sx * sx + sy * sy + sz * sz;
        const unsigned touchingLanes = static_cast<unsigned>(
            _mm256_movemask_pd(reinterpret_cast<__m256d>(distance2 < touching * touching)));
        // The touching lanes' (candidate, i, j), packed in lane order to the front of one 16-byte
        // store each (the loop keeps four entries of room), instead of twelve scalar stores.
        const __m128i pack = _mm_load_si128(&kPackLanes[touchingLanes]);
        const __m128i candidates =
            _mm_add_epi32(_mm_set1_epi32(static_cast<int>(a)), _mm_setr_epi32(0, 1, 2, 3));
        _mm_storeu_si128(reinterpret_cast<__m128i*>(b.candidate + touchingEnd),
                         _mm_shuffle_epi8(candidates, pack));
        _mm_storeu_si128(reinterpret_cast<__m128i*>(b.i + touchingEnd),
                         _mm_shuffle_epi8(_mm_loadu_si128(reinterpret_cast<const __m128i*>(laneI)), pack));
        _mm_storeu_si128(reinterpret_cast<__m128i*>(b.j + touchingEnd),
                         _mm_shuffle_epi8(_mm_loadu_si128(reinterpret_cast<const __m128i*>(laneJ)), pack));
        // Their separations and radii, packed the same way (the kernel reads them, PairBatch).
        const __m256i packDoubles =
            _mm256_load_si256(reinterpret_cast<const __m256i*>(kPackDoublesTable.index[touchingLanes]));
        storePacked(b.sx + touchingEnd, sx, packDoubles);
        storePacked(b.sy + touchingEnd, sy, packDoubles);
        storePacked(b.sz + touchingEnd, sz, packDoubles);
        storePacked(b.ri + touchingEnd, ri, packDoubles);
        storePacked(b.rj + touchingEnd, rj, packDoubles);
        touchingEnd += static_cast<std::size_t>(__builtin_popcount(touchingLanes));
        // Lanes that may have been in contact and do not touch now (rare): recorded in lane order.
        std::uint32_t mayBytes;
        std::memcpy(&mayBytes, mayBeActive + a, sizeof mayBytes); // four 0/1 flags
        for (unsigned open = _pext_u32(mayBytes, 0x01010101u) & ~touchingLanes & 0xfu; open != 0;
             open &= open - 1)
            opened[openedEnd++] =
                static_cast<std::uint32_t>(a) + static_cast<std::uint32_t>(__builtin_ctz(open));
    }
    m = touchingEnd;
    o = openedEnd;
    return selectTouchingScalar(c, a, zeroedEnd, b, m, opened, o); // up to a full batch, or a new block
}

std::size_t selectTouchingPortable(const Candidates& c, std::size_t a, std::size_t zeroedEnd, PairBatch& b,
                                   std::size_t& m, std::uint32_t* opened, std::size_t& o)
{
    return selectTouchingScalar(c, a, zeroedEnd, b, m, opened, o);
}

using SelectPass = std::size_t (*)(const Candidates&, std::size_t, std::size_t, PairBatch&, std::size_t&,
                                   std::uint32_t*, std::size_t&);

using WallKernel = void (*)(LawBatch&, std::size_t, Real, const LawParams*);

using PairKernel = void (*)(const World&, const PairSink&, Real, std::size_t, WorstOverlap&, PairBatch&,
                            const UniformLaw*);

struct KernelVariant
{
    const char* name;
    PairKernel kernel;
    WallKernel wallKernel;
    SelectPass select;
    bool (*supported)();
};

bool cpuHasAvx2()
{
#if defined(__x86_64__) && defined(__GNUC__)
    __builtin_cpu_init();
    return __builtin_cpu_supports("avx2") && __builtin_cpu_supports("fma") && __builtin_cpu_supports("bmi2");
#else
    return false;
#endif
}

const KernelVariant kVariants[] = {
    {"avx2", pairContactsAvx2, wallContactsAvx2, selectTouchingAvx2, cpuHasAvx2},
    {"portable", pairContactsPortable, wallContactsPortable, selectTouchingPortable, [] { return true; }}};

/// The variant in use: VERIDEM_KERNEL if set (and supported), else the widest the CPU runs.
const KernelVariant*& currentVariant()
{
    static const KernelVariant* variant = []
    {
        const char* wanted = std::getenv("VERIDEM_KERNEL");
        for (const KernelVariant& v : kVariants)
            if (v.supported() && (!wanted || !*wanted || std::strcmp(wanted, v.name) == 0))
                return &v;
        throw InputError(std::string("VERIDEM_KERNEL=") + wanted +
                         ": not a contact kernel this CPU can run (avx2, portable)");
    }();
    return variant;
}

/// True if the contacts take the lane path (World::batchedContactKernel; every model runs there).
bool lanesApply(const World& world)
{
    return world.batchedContactKernel;
}

/// Touching candidate k through the general contact law (any model), added into the sink.
void pairContactScalar(const World& world, NeighborList& list, const PairSink& sink, Real dt, std::size_t k,
                       WorstOverlap& worst)
{
    const ParticleStore& p = world.particles;
    const std::uint32_t i = list.activeFirst[k], j = list.activeSecond[k];
    const Vec3 separation = p.position[i] - p.position[j];
    const Real ri = p.radius[i], rj = p.radius[j];
    const Real touching = ri + rj;
    const Real distance2 = lengthSquared(separation);
    const PairParams& params = world.pairs(p.material[i], p.material[j]);
    const ExtraInputs extra = extraInputsFor(params);
    const Real distance = std::sqrt(distance2);
    const Real reciprocal = 1.0 / (distance * touching); // one division for 1/d and d/(r_i + r_j)
    const Real inverseDistance = touching * reciprocal;
    ContactInput in;
    in.normal = distance > 0 ? Vec3{separation.x * inverseDistance, separation.y * inverseDistance,
                                    separation.z * inverseDistance}
                             : Vec3{0, 0, 1};
    in.overlap = touching - distance;
    const Real share = distance > 0 ? distance * distance * reciprocal : 0.0;
    const Real leverI = ri * share, leverJ = rj * share;
    in.relativeVelocity = p.velocity[i] - p.velocity[j] -
                          cross(leverI * p.angularVelocity[i] + leverJ * p.angularVelocity[j], in.normal);
    in.relativeAngularVelocity = p.angularVelocity[i] - p.angularVelocity[j];
    in.angularVelocity = p.angularVelocity[i];
    in.effectiveMass = list.activeMass[k];
    if (extra.effectiveRadius)
        in.effectiveRadius = ri * rj / touching;
    if (extra.spinInertia)
        in.spinInertia = 1.0 / (p.invInertia[i] + p.invInertia[j]);
    if (extra.rollingInertia)
        in.rollingInertia = 1.0 / (1.0 / (1.0 / p.invInertia[i] + p.mass[i] * ri * ri) +
                                   1.0 / (1.0 / p.invInertia[j] + p.mass[j] * rj * rj));

    ContactHistory history = list.candidateHistory(k);
    history.formed = sink.mayBeActive[k];
    const ContactOutput out = evaluateContact(params, in, history, dt);
    list.setCandidateHistory(k, history);
    sink.mayBeActive[k] = history.formed != 0;

    const Vec3 tangentialTorque = cross(in.normal, out.tangentialForce); // n x Ft
    sink.add(static_cast<std::uint32_t>(k), i, j, out.force, out.rollingTorque - leverI * tangentialTorque,
             -out.rollingTorque - leverJ * tangentialTorque);

    const Real minRadius = std::min(ri, rj);
    if (worst.exceededBy(in.overlap, minRadius))
        worst = {in.overlap / minRadius, i, true};
}

/// Zeroes the pair sums of particles [begin, end); returns end. Out of line: it runs once a block.
[[gnu::noinline]] std::size_t zeroSums(const PairSink& sink, bool alreadyZero, std::size_t begin,
                                       std::size_t end)
{
    if (alreadyZero) // (advance()'s fused particle pass zeroed them)
        return end;
    // (memset: glibc's picks the CPU's widest stores; std::fill of the 32-byte Sums compiled to
    // eight scalar stores a particle here, -fno-tree-slp-vectorize.)
    std::memset(static_cast<void*>(sink.force + begin), 0, (end - begin) * sizeof(PaddedVec3));
    std::memset(static_cast<void*>(sink.torque + begin), 0, (end - begin) * sizeof(PaddedVec3));
    return end;
}

} // namespace

namespace
{

/// The runs of blocks the threads evaluate (world.pairSchedule), remade when the candidate
/// sub-list, the slots or the thread count changed. Weight of a block: its touching candidates
/// (the selection and the kernel follow their count), a cross-block one counted three times,
/// because its partner lies in another block and it stores a deferred entry. On the 20k bed,
/// blocks 0-9 hold 9.6 % more candidates but 55 % more cross-block ones, and two threads split
/// by plain count take 11-25 % longer on them; the weight 3 fits that (the longer thread's pair
/// time is 2.12-2.40 s against 2.44-2.97 s per 3000 steps). The imbalance is not false sharing:
/// a block's deferred entries are one range in slot order. The order of the sums does not depend on
/// the schedule: any split gives the same bits. `activeFrom`: particle -> its first candidate.
template <class ActiveFrom>
const std::vector<BlockRun>& scheduleBlocks(World& world, std::size_t blocks, int chunks,
                                            const ActiveFrom& activeFrom)
{
    PairSchedule& s = world.pairSchedule;
    const NeighborList& list = world.neighbors;
    const std::size_t n = world.particles.size();
    if (s.chunks != chunks || s.subListRebuilds != list.activeRebuildCount() ||
        s.slotRebuilds != list.rebuildCount() || s.particles != n)
    {
        constexpr std::size_t B = NeighborList::kBlockParticles;
        constexpr std::uint64_t kCrossBlockWeight = 3;
        std::vector<std::uint64_t> weight(blocks);
        for (std::size_t b = 0; b < blocks; ++b)
        {
            const std::size_t begin = activeFrom(b * B), end = activeFrom(std::min((b + 1) * B, n));
            std::uint64_t w = end - begin;
            for (std::size_t a = begin; a < end; ++a)
                w += (kCrossBlockWeight - 1) * (list.activeDeferred[a] != NeighborList::kInBlock);
            weight[b] = w;
        }
        if (s.speed.size() != static_cast<std::size_t>(chunks))
            s.speed.assign(static_cast<std::size_t>(chunks), 0.0); // other threads: measure anew
        const bool measured = std::all_of(s.speed.begin(), s.speed.end(), [](double v) { return v > 0; });
        partitionBlocks(weight.data(), blocks, chunks, s.runs, measured ? s.speed.data() : nullptr);
        s.heaviestShare = heaviestShare(weight.data(), s.runs, chunks);
        s.weight = std::move(weight);
        s.runHealth.assign(blocks, ContactHealth{});
        s.chunks = chunks;
        s.subListRebuilds = list.activeRebuildCount();
        s.slotRebuilds = list.rebuildCount();
        s.particles = n;
    }
    return s.runs;
}

/// After a parallel pair stage: folds each thread's rate on its own run (its runs' weight over
/// `seconds[c]`, the time it took) into the running mean of its speed, and moves the split if
/// the speeds predict the stage at least 3 % shorter (partitionBlocks with the speeds as shares).
/// The margin keeps the boundary from moving back and forth between two block edges as the
/// measured speeds jitter: each move carries a block's rows (~200 KB) to the other core once.
void adaptSchedule(PairSchedule& s, const double* seconds, int chunks)
{
    constexpr double kMix = 1.0 / 16; // weight of the newest step in the running mean
    constexpr double kMargin = 0.97;  // move only for a stage predicted this much shorter
    std::uint64_t runWeight[kMaxChunks] = {};
    for (const BlockRun& r : s.runs)
        for (std::uint32_t b = r.first; b < r.end; ++b)
            runWeight[r.chunk] += s.weight[b];
    bool measured = true;
    for (int c = 0; c < chunks; ++c)
    {
        double& speed = s.speed[static_cast<std::size_t>(c)];
        if (seconds[c] > 0 && runWeight[c] > 0)
        {
            const double rate = static_cast<double>(runWeight[c]) / seconds[c];
            speed = speed > 0 ? speed + kMix * (rate - speed) : rate;
        }
        measured = measured && speed > 0;
    }
    if (!measured)
        return;
    // The stage takes as long as its slowest thread: max over threads of weight / speed.
    const auto predicted = [&](const std::vector<BlockRun>& runs)
    {
        std::uint64_t load[kMaxChunks] = {};
        for (const BlockRun& r : runs)
            for (std::uint32_t b = r.first; b < r.end; ++b)
                load[r.chunk] += s.weight[b];
        double longest = 0;
        for (int c = 0; c < chunks; ++c)
            longest = std::max(longest, static_cast<double>(load[c]) / s.speed[static_cast<std::size_t>(c)]);
        return longest;
    };
    partitionBlocks(s.weight.data(), s.weight.size(), chunks, s.proposal, s.speed.data());
    if (predicted(s.proposal) < kMargin * predicted(s.runs))
    {
        std::swap(s.runs, s.proposal);
        s.heaviestShare = heaviestShare(s.weight.data(), s.runs, chunks);
        ++s.moves;
    }
}

/// computePairForces for a world with particles and pair slots.
void pairForcesOfSlots(World& world, Real dt, bool sumsAreZero)
{
    ParticleStore& p = world.particles;
    NeighborList& list = world.neighbors;
    const std::size_t n = p.size();
    const std::size_t pairCount = list.size();
    const bool allBatchable = lanesApply(world);
    const std::optional<UniformLaw> single = uniformLaw(world);
    const UniformLaw* const uniform = single ? &*single : nullptr;

    constexpr std::size_t B = NeighborList::kBlockParticles;
    const std::size_t blocks = (n + B - 1) / B;
    const int chunks = static_cast<int>(std::min(
        {static_cast<std::size_t>(loopThreads(std::max(pairCount, n))), blocks, std::size_t{kMaxChunks}}));

    list.refreshActiveSlots(p); // the touching candidates, if the sub-list is stale
    const std::uint32_t* const active = list.activeSlots.data();
    const std::size_t activeCount = list.activeSlots.size();
    const auto activeFrom = [&](std::size_t particle) // first candidate slot of this particle on
    {
        return static_cast<std::size_t>(
            std::lower_bound(active, active + activeCount, list.firstStart[particle]) - active);
    };
    const std::vector<BlockRun>& runs = scheduleBlocks(world, blocks, chunks, activeFrom);

    if (p.positionRadius.size() != n) // (prepare() and every drift keep it; a direct caller may not)
        p.refreshPositionRadius();
    const PaddedVec3* const positionRadiusRows = p.positionRadius.data();
    const PairSink sink(world);
    const PairKernel kernel = currentVariant()->kernel;
    const SelectPass select = currentVariant()->select;
    // Health per block (one thread: per run, in entry 0), folded in block order (the order of a
    // serial loop).
    ContactHealth* const health = world.pairSchedule.runHealth.data();
    // One run of consecutive blocks: their candidates, selected and evaluated in batches.
    const auto pairRun = [&](const BlockRun& run) -> ContactHealth
    {
        const std::size_t firstParticle = std::min(run.first * B, n), endParticle = std::min(run.end * B, n);
        // A block's sums are zeroed just before its first candidate, not the run's all at
        // once: a block's contacts add only into its own particles' sums (the cross-block
        // shares are deferred), so the sums are still in L2 when the contacts add to them
        // (a chunk's sums, 64 B a particle, do not fit in a 512 KB L2).
        std::size_t zeroedEnd = firstParticle; // sums [firstParticle, zeroedEnd) are zero
        const auto blockEndOf = [&](std::size_t particle)
        { return std::min((particle / B + 1) * B, endParticle); };
        const std::size_t begin = activeFrom(firstParticle),
                          end = endParticle == n ? activeCount : activeFrom(endParticle);
        WorstOverlap worst{0, 0, false};
        std::size_t touchingCount = 0;
        // Array bases in locals (the byte-sized mayBeActive stores could alias the vectors).
        const std::uint32_t* const first = list.activeFirst.data();
        const std::uint32_t* const second = list.activeSecond.data();
        const Vec3* const position = p.position.data();
        const Real* const radius = p.radius.data();
        std::uint8_t* const mayBeActive = sink.mayBeActive;
        if (!allBatchable)
        {
            for (std::size_t a = begin; a < end; ++a)
            {
                const std::uint32_t i = first[a], j = second[a];
                if (i >= zeroedEnd)
                    zeroedEnd = zeroSums(sink, sumsAreZero, zeroedEnd, blockEndOf(i));
                const Real touching = radius[i] + radius[j] + list.reach;
                if (lengthSquared(position[i] - position[j]) < touching * touching)
                {
                    pairContactScalar(world, list, sink, dt, a, worst);
                    ++touchingCount;
                }
                else if (mayBeActive[a])
                    list.openCandidate(a);
            }
            zeroSums(sink, sumsAreZero, zeroedEnd, endParticle);
            return ContactHealth{worst.ratio, worst.particle, worst.found, touchingCount};
        }
        // One pass: each touching candidate is appended (branch-free) to a batch, which runs when
        // full (selectTouching*). The selection stops at a block's first candidate, whose sums
        // are zeroed here, and candidates found open are only recorded, then opened here
        // (openCandidate touches no candidate of the batch, and nothing in this pass reads what
        // it writes again).
        const Candidates selection{first,       second, position,  radius, positionRadiusRows,
                                   mayBeActive, end,    list.reach};
        PairBatch batch;
        std::uint32_t opened[kBatch];
        std::size_t m = 0, o = 0;
        std::size_t a = begin;
        while (a < end)
        {
            a = select(selection, a, zeroedEnd, batch, m, opened, o);
            for (std::size_t q = 0; q < o; ++q)
                list.openCandidate(opened[q]);
            o = 0;
            if (m == kBatch || a == end)
            {
                if (m > 0)
                    kernel(world, sink, dt, m, worst, batch, uniform);
                touchingCount += m;
                m = 0;
            }
            if (a < end && first[a] >= zeroedEnd)
                // (the batch holds earlier blocks' contacts only)
                zeroedEnd = zeroSums(sink, sumsAreZero, zeroedEnd, blockEndOf(first[a]));
        }
        zeroSums(sink, sumsAreZero, zeroedEnd, endParticle);
        return ContactHealth{worst.ratio, worst.particle, worst.found, touchingCount};
    };
    if (chunks == 1)
    {
        for (const BlockRun& run : runs)
            health[run.first] = pairRun(run);
    }
    else
    {
        // Each thread evaluates its own run's blocks, timed for adaptSchedule.
        const BlockRun* runOf[kMaxChunks] = {};
        for (const BlockRun& run : runs)
            runOf[run.chunk] = &run;
        double seconds[kMaxChunks] = {};
        parallelChunks(
            static_cast<std::size_t>(chunks), chunks,
            [&](int chunk, std::size_t, std::size_t)
            {
                const ThreadBusyTimer busy(world.profile, world.profile.pairBusy, chunk);
                const BlockRun* const run = runOf[chunk];
                if (!run)
                    return;
                const auto start = std::chrono::steady_clock::now();
                for (std::uint32_t b = run->first; b < run->end; ++b)
                    health[b] = pairRun(BlockRun{b, b + 1, chunk});
                seconds[chunk] =
                    std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
            });
        if (world.pairSchedule.adapt)
            adaptSchedule(world.pairSchedule, seconds, chunks);
    }
    foldHealth(world.health, health, static_cast<int>(blocks), world.health.touchingPairs);
}

} // namespace

void computePairForces(World& world, Real dt, bool sumsAreZero)
{
    world.health.maxOverlapRatio = 0;
    world.health.touchingPairs = 0;
    // (Small, so that it inlines into the step: one ball on a turntable has no pair slots and no
    // sums to fill; addCrossBlockForces zeroes its force and torque.)
    if (world.particles.size() > 0 && world.neighbors.size() > 0)
        pairForcesOfSlots(world, dt, sumsAreZero);
}

const char* laneKernelName()
{
    return currentVariant()->name;
}

bool laneKernelIsAvx2()
{
    return currentVariant() == &kVariants[0];
}

bool selectLaneKernel(const std::string& name)
{
    for (const KernelVariant& v : kVariants)
        if (name == v.name && v.supported())
        {
            currentVariant() = &v;
            return true;
        }
    return false;
}

namespace
{

/// addCrossBlockForces for a world with pair slots: adds each particle's incoming cross-block
/// entries, in slot order, to the sums the pair stage left in its force and torque. Inlined into
/// an instruction-set variant below (one 32-byte add per row with AVX2, two with SSE2).
VERIDEM_HOT_INLINE void crossBlockSumsBody(World& world, std::size_t begin, std::size_t end)
{
    ParticleStore& p = world.particles;
    const NeighborList& pairs = world.neighbors;
    if (pairs.deferred.empty())
        return;
    const std::uint32_t* const start = pairs.incomingStart.data();
    const std::uint32_t* const entry = pairs.incomingEntry.data();
    const NeighborList::DeferredShare* const deferred = pairs.deferred.data();
    // The entries are stored in slot order, so a particle's lie scattered: they are fetched
    // kEntriesAhead entries before their use.
    constexpr std::uint32_t kEntriesAhead = 16;
    const std::uint32_t lastEntry = start[p.size()] - 1;
    for (std::size_t i = begin; i < end; ++i)
    {
        if (start[i] == start[i + 1])
            continue;
        // Padded rows: x, y, z and the padding (+0) summed in lanes, each lane's adds those of
        // the Vec3 sum.
        Lanes4 force = load<Lanes4>(&p.force[i].x), torque = load<Lanes4>(&p.torque[i].x);
        for (std::uint32_t e = start[i]; e < start[i + 1]; ++e)
        {
            __builtin_prefetch(&deferred[entry[std::min(e + kEntriesAhead, lastEntry)]]);
            force += load<Lanes4>(&deferred[entry[e]].force.x);
            torque += load<Lanes4>(&deferred[entry[e]].torque.x);
        }
        store(&p.force[i].x, force);
        store(&p.torque[i].x, torque);
    }
}

VERIDEM_AVX2_TARGET void crossBlockSumsAvx2(World& world, std::size_t begin, std::size_t end)
{
    crossBlockSumsBody(world, begin, end);
}

void crossBlockSumsPortable(World& world, std::size_t begin, std::size_t end)
{
    crossBlockSumsBody(world, begin, end);
}

} // namespace

void addCrossBlockForces(World& world, std::size_t begin, std::size_t end)
{
    ParticleStore& p = world.particles;
    const NeighborList& pairs = world.neighbors;
    if (pairs.incomingStart.size() != p.size() + 1) // no list built (no particles)
        return;
    if (pairs.size() == 0) // no pair slots (one ball on a turntable): the sums were not written
    {
        for (std::size_t i = begin; i < end; ++i)
            p.force[i] = p.torque[i] = Vec3{};
        return;
    }
    if (laneKernelIsAvx2())
        crossBlockSumsAvx2(world, begin, end);
    else
        crossBlockSumsPortable(world, begin, end);
}

namespace
{

/// The contact input of particle i touching `wall` (gap from wallGap), as the contact law takes
/// it; `arm` is set to the lever arm from the centre to the contact point [m].
VERIDEM_HOT_INLINE ContactInput wallContactInput(const ParticleState& s, const Wall& wall, const WallGap& gap,
                                                 Real dt, Vec3& arm)
{
    const Real r = s.radius;
    const Vec3 position = s.position, velocity = s.velocity, angularVelocity = s.angularVelocity;
    ContactInput in;
    in.normal = gap.normal;
    in.overlap = gap.overlap;
    arm = -r * gap.normal; // centre to contact point
    // The particle's velocities are those of the half step t+dt/2, so the wall's surface
    // velocity is taken at the contact point of the half step too (x - v dt/2). Using x(t+dt)
    // would add a spurious slip Omega |v| dt/2 on a rotating wall, and a ball orbiting on a
    // turntable would lose speed at a rate of order Omega v dt.
    const Vec3 midStepContactPoint = position - (0.5 * dt) * velocity + arm;
    in.relativeVelocity =
        velocity + cross(angularVelocity, arm) - wallSurfaceVelocity(wall, midStepContactPoint, -0.5 * dt);
    in.angularVelocity = angularVelocity;
    in.relativeAngularVelocity = angularVelocity - wall.motion.angularVelocity;
    in.effectiveMass = s.mass;
    in.effectiveRadius = gap.effectiveRadius;
    in.spinInertia = 1.0 / s.invInertia;
    return in;
}

/// Folds the overlap [m] of a touching wall contact of particle i (radius [m]) into `health`: the
/// first contact of the largest overlap ratio is kept.
VERIDEM_HOT_INLINE void foldWallOverlap(std::uint32_t i, Real overlap, Real radius, ContactHealth& health)
{
    const Real ratio = overlap / radius;
    if (ratio > health.maxOverlapRatio)
        health = {ratio, i, true, health.touching};
}

/// Adds one wall contact's force and torque to particle i and folds its overlap into `health`.
void addWallContact(ParticleStore& p, std::uint32_t i, const Vec3& force, const Vec3& torque, Real overlap,
                    ContactHealth& health)
{
    p.force[i] += force;
    p.torque[i] += torque;
    foldWallOverlap(i, overlap, p.radius[i], health);
}

/// computeWallForces when every contact takes the lane law: the inputs are computed per contact
/// (wallContactInput), the law runs in lanes a batch at a time, and the results are added in
/// slot order, so the sums and bits are those of the scalar path.
ContactHealth wallForcesInLanes(World& world, Real dt, std::size_t begin, std::size_t end)
{
    ParticleStore& p = world.particles;
    WallContactList& list = world.wallContacts;
    ContactHealth health{0, 0, false, 0};
    const std::optional<UniformLaw> single = uniformLaw(world);
    const UniformLaw* const uniform = single ? &*single : nullptr;
    const WallKernel kernel = currentVariant()->wallKernel;
    LawBatch b;
    std::size_t m = 0;
    const auto run = [&]
    {
        finishBatchLaws(b, uniform);
        kernel(b, m, dt, uniform ? &uniform->params : nullptr);
        for (std::size_t q = 0; q < m; ++q)
        {
            const std::uint32_t i = b.particle[q];
            const Vec3 normal{b.nx[q], b.ny[q], b.nz[q]}, tangential{b.ftx[q], b.fty[q], b.ftz[q]};
            list.setHistory(b.slot[q],
                            ContactHistory{{b.springX[q], b.springY[q], b.springZ[q]}, b.rollingSpringOf(q)});
            const Vec3 arm = -p.radius[i] * normal;
            addWallContact(p, i, b.normalForce[q] * normal + tangential,
                           b.rollingTorqueOf(q) + cross(arm, tangential), b.overlap[q], health);
        }
        m = 0;
        b.models = 0;
    };
    for (std::size_t k = list.start[begin]; k < list.start[end]; ++k)
    {
        const std::uint32_t i = list.particle[k];
        const Wall& wall = world.walls[list.wall[k]];
        const WallGap gap = wallGap(wall, p.position[i], p.radius[i]);
        if (!gap.touching)
        {
            list.setHistory(k, ContactHistory{});
            continue;
        }
        ++health.touching;
        Vec3 arm;
        ContactInput in = wallContactInput(particleState(p, i), wall, gap, dt, arm);
        b.setInputs(m, k, i, in.normal, in.overlap, in.relativeVelocity, in.effectiveMass,
                    list.tangentialSpring[k]);
        if (!uniform)
            addContactLaw(b, m, world.pairs(p.material[i], wall.material));
        if (!uniform || uniform->models != 1u) // (as wallContactScalar)
        {
            in.rollingInertia = in.spinInertia + p.mass[i] * p.radius[i] * p.radius[i];
            b.setRollingInputs(m, in, list.keepRollingHistory ? list.rollingSpring[k] : Vec3{});
        }
        if (++m == kBatch)
            run();
    }
    if (m > 0)
        run();
    return health;
}

/// A plane wall as the plane-wall pass reads it, from wallGap and wallSurfaceVelocity with the
/// parts that do not depend on the particle computed once, by the same operations: the plane's
/// current point [m] and unit normal, its disk radius squared [m^2] (if finite), and its surface
/// velocity field at the half step (velocity [m/s], angular velocity [rad/s], a point of the
/// rotation axis [m]).
struct PlaneFrame
{
    Vec3 origin, normal;
    bool finiteDisk;
    Real disk2;
    Vec3 velocity, angularVelocity, axis;
    std::uint32_t material;
};

constexpr std::size_t kMaxPlaneFrames = 16; // more walls than this take the general pass

/// The frames of `walls` at the half step (timeOffset -dt/2, as wallContactInput); false if some
/// wall is not a plane or there are more than kMaxPlaneFrames.
bool planeFrames(const std::vector<Wall>& walls, Real dt, PlaneFrame* frames)
{
    if (walls.size() > kMaxPlaneFrames)
        return false;
    for (std::size_t w = 0; w < walls.size(); ++w)
    {
        const Wall& wall = walls[w];
        const PlaneShape* plane = std::get_if<PlaneShape>(&wall.shape);
        if (!plane)
            return false;
        const Real timeOffset = -0.5 * dt;
        frames[w] = {plane->point + wall.displacement,
                     plane->normal,
                     std::isfinite(plane->diskRadius),
                     plane->diskRadius * plane->diskRadius,
                     wall.motion.velocity,
                     wall.motion.angularVelocity,
                     wall.motion.rotationCentre + wall.displacement + timeOffset * wall.motion.velocity,
                     wall.material};
    }
    return true;
}

/// The inputs beyond the linear law's of the plane-wall contacts [0, count) of `b` (as
/// wallContactInput and wallContactScalar: a plane's R* is r), out of the hot loop.
[[gnu::noinline]] void planeExtraInputs(const World& world, const PlaneFrame* frames, LawBatch& b,
                                        std::size_t count)
{
    const ParticleStore& p = world.particles;
    const WallContactList& list = world.wallContacts;
    for (std::size_t q = 0; q < count; ++q)
    {
        const std::uint32_t i = b.particle[q];
        const std::size_t k = b.slot[q];
        const Real r = p.radius[i];
        ContactInput in;
        in.relativeAngularVelocity = p.angularVelocity[i] - frames[list.wall[k]].angularVelocity;
        in.angularVelocity = p.angularVelocity[i];
        in.effectiveRadius = r;
        in.spinInertia = 1.0 / p.invInertia[i];
        in.rollingInertia = in.spinInertia + p.mass[i] * r * r;
        b.setRollingInputs(q, in, list.keepRollingHistory ? list.rollingSpring[k] : Vec3{});
    }
}

/// wallForcesInLanes for plane walls (frames from planeFrames), the wall's part of wallGap and
/// wallSurfaceVelocity taken from its frame: the same operations on the same values, so the same
/// bits. Inlined into an instruction-set variant below (three-operand AVX encodings of the same
/// scalar operations for the AVX2 one).
template <class Lanes>
VERIDEM_HOT_INLINE ContactHealth planeWallForcesBody(World& world, Real dt, std::size_t begin,
                                                     std::size_t end, const PlaneFrame* frames)
{
    ParticleStore& p = world.particles;
    WallContactList& list = world.wallContacts;
    ContactHealth health{0, 0, false, 0};
    const std::optional<UniformLaw> single = uniformLaw(world);
    const UniformLaw* const uniform = single ? &*single : nullptr;
    const bool extraInputs = !uniform || uniform->models != 1u; // some model beyond the linear law's
    const Vec3* const position = p.position.data();
    const Vec3* const velocity = p.velocity.data();
    const Vec3* const angularVelocity = p.angularVelocity.data();
    const Real* const radius = p.radius.data();
    const Real* const mass = p.mass.data();
    PaddedVec3* const force = p.force.data();
    PaddedVec3* const torque = p.torque.data();
    const std::uint32_t* const particle = list.particle.data();
    const std::uint32_t* const wallOf = list.wall.data();
    Vec3* const spring = list.tangentialSpring.data();
    const bool rolling = list.keepRollingHistory;
    const Real halfStep = 0.5 * dt;
    LawBatch b;
    std::size_t m = 0;
    // (Inlined: a lambda's own function would not have the caller's instruction set.)
    const auto run = [&]() __attribute__((always_inline))
    {
        finishBatchLaws(b, uniform);
        if (extraInputs)
            planeExtraInputs(world, frames, b, m);
        // (The law in its own function: inlined here, its register pressure spilled this loop.)
        if constexpr (kWidth<Lanes> == 4)
            wallContactsAvx2(b, m, dt, uniform ? &uniform->params : nullptr);
        else
            wallContactsPortable(b, m, dt, uniform ? &uniform->params : nullptr);
        for (std::size_t q = 0; q < m; ++q)
        {
            const std::uint32_t i = b.particle[q];
            const Vec3 normal{b.nx[q], b.ny[q], b.nz[q]}, tangential{b.ftx[q], b.fty[q], b.ftz[q]};
            if (rolling)
                list.setHistory(b.slot[q], ContactHistory{{b.springX[q], b.springY[q], b.springZ[q]},
                                                          b.rollingSpringOf(q)});
            else
                spring[b.slot[q]] = {b.springX[q], b.springY[q], b.springZ[q]};
            const Vec3 arm = -radius[i] * normal;
            const Vec3 f = b.normalForce[q] * normal + tangential,
                       t = b.rollingTorqueOf(q) + cross(arm, tangential);
            force[i].x += f.x;
            force[i].y += f.y;
            force[i].z += f.z;
            torque[i].x += t.x;
            torque[i].y += t.y;
            torque[i].z += t.z;
            foldWallOverlap(i, b.overlap[q], radius[i], health);
        }
        m = 0;
        b.models = 0;
    };
    for (std::size_t k = list.start[begin]; k < list.start[end]; ++k)
    {
        const std::uint32_t i = particle[k];
        const PlaneFrame& frame = frames[wallOf[k]];
        // wallGap(PlaneShape): the same tests, so the same choice for every value (NaN included).
        const Vec3 x = position[i];
        const Real r = radius[i];
        const Vec3 relative = x - frame.origin;
        const Real distance = dot(relative, frame.normal);
        const Real overlap = r - distance;
        bool touching = !(overlap <= 0) && !(distance < -r);
        if (touching && frame.finiteDisk)
            touching = !(lengthSquared(relative - distance * frame.normal) > frame.disk2);
        if (!touching)
        {
            spring[k] = Vec3{};
            if (rolling)
                list.setHistory(k, ContactHistory{});
            continue;
        }
        ++health.touching;
        // wallContactInput.
        const Vec3 v = velocity[i], w = angularVelocity[i];
        const Vec3 arm = -r * frame.normal;
        const Vec3 midStepContactPoint = x - halfStep * v + arm;
        const Vec3 surfaceVelocity =
            frame.velocity + cross(frame.angularVelocity, midStepContactPoint - frame.axis);
        const Vec3 relativeVelocity = v + cross(w, arm) - surfaceVelocity;
        b.setInputs(m, k, i, frame.normal, overlap, relativeVelocity, mass[i], spring[k]);
        if (!uniform)
            addContactLaw(b, m, world.pairs(p.material[i], frame.material));
        if (++m == kBatch)
            run();
    }
    if (m > 0)
        run();
    return health;
}

VERIDEM_AVX2_TARGET ContactHealth planeWallForcesAvx2(World& world, Real dt, std::size_t begin,
                                                      std::size_t end, const PlaneFrame* frames)
{
    return planeWallForcesBody<Lanes4>(world, dt, begin, end, frames);
}

ContactHealth planeWallForcesPortable(World& world, Real dt, std::size_t begin, std::size_t end,
                                      const PlaneFrame* frames)
{
    return planeWallForcesBody<Lanes2>(world, dt, begin, end, frames);
}

/// Wall contact k of the particle whose state is `s`, through the general contact law (any
/// model): updates the contact's history (cleared if it is not touching); if it touches, adds its
/// force [N] and torque [N m] to `force` and `torque` and folds it into `health`.
VERIDEM_HOT_INLINE void wallContactScalar(World& world, Real dt, std::size_t k, std::uint32_t i,
                                          const ParticleState& s, Vec3& force, Vec3& torque,
                                          ContactHealth& health)
{
    WallContactList& list = world.wallContacts;
    const Wall& wall = world.walls[list.wall[k]];
    const WallGap gap = wallGap(wall, s.position, s.radius);
    if (!gap.touching)
    {
        list.setHistory(k, ContactHistory{});
        return;
    }
    ++health.touching;
    const PairParams& params = world.pairs(s.material, wall.material);
    Vec3 arm;
    ContactInput in = wallContactInput(s, wall, gap, dt, arm);
    if (params.rollingModel == RollingModel::Epsd)
        in.rollingInertia = in.spinInertia + s.mass * s.radius * s.radius;

    ContactHistory history = list.history(k);
    const ContactOutput out = evaluateContact(params, in, history, dt);
    list.setHistory(k, history);
    force += out.force;
    torque += out.rollingTorque + cross(arm, out.tangentialForce);
    foldWallOverlap(i, in.overlap, s.radius, health);
}

} // namespace

ContactHealth computeWallForces(World& world, Real dt, std::size_t begin, std::size_t end)
{
    ParticleStore& p = world.particles;
    WallContactList& list = world.wallContacts;
    ContactHealth health{0, 0, false, 0};
    if (list.size() == 0 || list.start.size() != p.size() + 1)
        return health;
    if (lanesApply(world))
    {
        PlaneFrame frames[kMaxPlaneFrames];
        if (!planeFrames(world.walls, dt, frames))
            return wallForcesInLanes(world, dt, begin, end);
        return laneKernelIsAvx2() ? planeWallForcesAvx2(world, dt, begin, end, frames)
                                  : planeWallForcesPortable(world, dt, begin, end, frames);
    }
    for (std::size_t k = list.start[begin]; k < list.start[end]; ++k)
    {
        const std::uint32_t i = list.particle[k];
        wallContactScalar(world, dt, k, i, particleState(p, i), p.force[i], p.torque[i], health);
    }
    return health;
}

namespace
{
/// wallContactsOf's body, inlined into each instruction-set variant below.
VERIDEM_HOT_INLINE ContactHealth wallContactsOfBody(World& world, Real dt, std::uint32_t i,
                                                    const ParticleState& s, Vec3& force, Vec3& torque)
{
    const WallContactList& list = world.wallContacts;
    ContactHealth health{0, 0, false, 0};
    if (list.size() == 0 || list.start.size() != world.particles.size() + 1)
        return health;
    for (std::size_t k = list.start[i]; k < list.start[i + 1]; ++k)
        wallContactScalar(world, dt, k, i, s, force, torque, health);
    return health;
}
} // namespace

ContactHealth wallContactsOf(World& world, Real dt, std::uint32_t i, const ParticleState& s, Vec3& force,
                             Vec3& torque)
{
    return wallContactsOfBody(world, dt, i, s, force, torque);
}

VERIDEM_AVX2_TARGET ContactHealth wallContactsOfAvx2(World& world, Real dt, std::uint32_t i,
                                                     const ParticleState& s, Vec3& force, Vec3& torque)
{
    return wallContactsOfBody(world, dt, i, s, force, torque);
}

void mergeWallHealth(StepHealth& health, const ContactHealth* chunk, int chunks)
{
    foldHealth(health, chunk, chunks, health.touchingWalls);
}

void computeForces(World& world, Real dt)
{
    computePairForces(world, dt);
    const std::size_t n = world.particles.size();
    addCrossBlockForces(world, 0, n);
    const ContactHealth walls = computeWallForces(world, dt, 0, n);
    mergeWallHealth(world.health, &walls, 1);
}

} // namespace veridem::dem
