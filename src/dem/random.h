// The random numbers of particle insertion (dem/particle_flow.h): xoshiro256** (Blackman & Vigna
// 2018) seeded through splitmix64, and the few distributions insertion draws from, written here
// (std:: distributions differ between standard libraries). Uniform draws use only integer
// operations and one exact scaling; the normal draw (Marsaglia's polar method) uses std::sqrt
// (exact in IEEE arithmetic) and std::log, the log-normal one std::exp: the same seed gives the
// same bits on every machine whose C library computes log and exp alike (glibc on x86-64 does).
#pragma once

#include "core/vec3.h"

#include <array>
#include <cmath>
#include <cstdint>

namespace veridem::dem
{

/// splitmix64 (Steele, Lea & Flood 2014): the next value of the sequence with state `state`.
inline std::uint64_t splitmix64(std::uint64_t& state)
{
    state += 0x9E3779B97F4A7C15ull;
    std::uint64_t z = state;
    z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ull;
    z = (z ^ (z >> 27)) * 0x94D049BB133111EBull;
    return z ^ (z >> 31);
}

class Random
{
  public:
    explicit Random(std::uint64_t seed = 1)
    {
        std::uint64_t s = seed;
        for (auto& word : state)
            word = splitmix64(s);
    }

    /// The next 64 random bits (xoshiro256**).
    std::uint64_t next()
    {
        const std::uint64_t result = rotl(state[1] * 5, 7) * 9;
        const std::uint64_t t = state[1] << 17;
        state[2] ^= state[0];
        state[3] ^= state[1];
        state[1] ^= state[2];
        state[0] ^= state[3];
        state[2] ^= t;
        state[3] = rotl(state[3], 45);
        return result;
    }
    /// Uniform in [0, 1), a multiple of 2^-53.
    Real uniform() { return Real(next() >> 11) * 0x1.0p-53; }
    /// Uniform in [a, b).
    Real uniform(Real a, Real b) { return a + (b - a) * uniform(); }
    /// Standard normal (Marsaglia's polar method; the second value of each pair is not kept, so the
    /// state alone determines the next draw).
    Real normal()
    {
        for (;;)
        {
            const Real u = 2 * uniform() - 1, v = 2 * uniform() - 1;
            const Real s = u * u + v * v;
            if (s > 0 && s < 1)
                return u * std::sqrt(-2 * std::log(s) / s);
        }
    }

    std::array<std::uint64_t, 4> state; // saved in a checkpoint

  private:
    static std::uint64_t rotl(std::uint64_t x, int k) { return (x << k) | (x >> (64 - k)); }
};

} // namespace veridem::dem
