#pragma once
/// A small, explicitly seeded random engine (PCG32, O'Neill 2014) with its own distributions,
/// so that a seed gives the same genome with every compiler and standard library.

#include <cmath>
#include <cstdint>

namespace marbler {

class Pcg32 {
public:
    explicit Pcg32(std::uint64_t seed, std::uint64_t stream = 0x14057b7ef767814fULL) {
        mInc = (stream << 1u) | 1u;
        nextUint();
        mState += seed;
        nextUint();
    }

    /// Uniform 32-bit integer.
    std::uint32_t nextUint() {
        std::uint64_t old = mState;
        mState = old * 6364136223846793005ULL + mInc;
        auto xorshifted = static_cast<std::uint32_t>(((old >> 18u) ^ old) >> 27u);
        auto rot = static_cast<std::uint32_t>(old >> 59u);
        return (xorshifted >> rot) | (xorshifted << ((-rot) & 31u));
    }

    /// Uniform in [0, 1) with 53 random bits.
    double uniform() {
        std::uint64_t hi = nextUint() >> 5, lo = nextUint() >> 6;
        return static_cast<double>((hi << 26) | lo) * (1.0 / 9007199254740992.0);
    }

    /// Uniform in [lo, hi).
    double uniform(double lo, double hi) { return lo + (hi - lo) * uniform(); }

    /// Uniform integer in [0, bound), without modulo bias.
    std::uint32_t below(std::uint32_t bound) {
        if (bound <= 1) return 0;
        std::uint32_t threshold = (0u - bound) % bound;
        for (;;) {
            std::uint32_t r = nextUint();
            if (r >= threshold) return r % bound;
        }
    }

    /// Uniform integer in [lo, hi] (inclusive).
    int between(int lo, int hi) {
        return lo + static_cast<int>(below(static_cast<std::uint32_t>(hi - lo + 1)));
    }

    /// True with probability p.
    bool chance(double p) { return uniform() < p; }

    /// Standard normal by Box-Muller (deterministic: uses only std::log, std::sqrt, std::cos,
    /// which are correctly rounded enough on every platform Marbler targets).
    double normal() {
        double u1 = uniform(), u2 = uniform();
        if (u1 < 1e-300) u1 = 1e-300;
        return std::sqrt(-2.0 * std::log(u1)) * std::cos(6.283185307179586 * u2);
    }

private:
    std::uint64_t mState = 0x853c49e6748fea9bULL;
    std::uint64_t mInc = 0xda3e39cb94b95bdbULL;
};

/// SplitMix64 (Steele, Lea and Flood 2014): spreads a 64-bit value over all 64 bits.
constexpr std::uint64_t splitMix64(std::uint64_t x) {
    x += 0x9e3779b97f4a7c15ULL;
    x = (x ^ (x >> 30)) * 0xbf58476d1ce4e5b9ULL;
    x = (x ^ (x >> 27)) * 0x94d049bb133111ebULL;
    return x ^ (x >> 31);
}

/// The `counter`th seed drawn from `seed` (the window's generations, the wildcard's draws): the
/// SplitMix64 sequence that starts at `seed`, so neighbouring counters give unrelated seeds.
constexpr std::uint64_t mixSeed(std::uint64_t seed, std::uint64_t counter) {
    return splitMix64(seed + 0x9e3779b97f4a7c15ULL * counter);
}

/// Child `index`'s own random stream: it depends on (seed, index) only, so children are
/// reproducible one by one and asking for more keeps the first ones. `salt` and `stream` keep
/// one kind of child (bred, colourway) apart from another of the same seed.
inline Pcg32 childRng(std::uint64_t seed, int index, std::uint64_t salt, std::uint64_t stream) {
    const auto i = static_cast<std::uint64_t>(index);
    return Pcg32(splitMix64(seed ^ splitMix64(i + salt)), stream + i);
}

/// Rounds to a tenth so generated files stay readable; only basic operations, so the result is
/// the same everywhere.
inline double tenth(double x) {
    return std::round(x * 10.0) / 10.0;
}

} // namespace marbler
