#include "dem/exec/pair_selection.h"

#include <algorithm>
#include <array>
#include <cstring>
#include <immintrin.h>

namespace veridem::dem::batch
{

namespace
{

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

} // namespace

SelectPass selectPassFor(exec::Isa isa)
{
    return isa == exec::Isa::Avx2 ? selectTouchingAvx2 : selectTouchingPortable;
}

} // namespace veridem::dem::batch
