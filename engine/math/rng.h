// Counter-based random numbers: every stream is keyed by (seed, pass, index, purpose),
// never by thread, so a render is bit-identical whatever the thread count.
#pragma once
#include <cstdint>

namespace photon {

// SplitMix64 finaliser (Steele et al. 2014): a strong 64-bit mixing function. A template
// so that lanes.h's eight 64-bit lanes seed eight streams with the same code; always
// inlined, as every helper the lanes' kernels use (lanes.h).
template <class U>
inline __attribute__((always_inline)) U mix64(U z) {
    z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ull;
    z = (z ^ (z >> 27)) * 0x94d049bb133111ebull;
    return z ^ (z >> 31);
}

// PCG32's state and increment for the path `index` of a stream keyed `streamKey`, as
// pcg32_srandom seeds them (two steps around the added key); U is uint64_t or lanes.
template <class U>
inline __attribute__((always_inline)) void seedPcg32(U streamKey, U index, U& state, U& increment) {
    constexpr uint64_t kMultiplier = 6364136223846793005ull;
    const U key = mix64<U>(streamKey ^ mix64<U>(index + 0x632be59bd9b4e019ull));
    increment = (mix64<U>(key + 0x1234567ull) << 1u) | 1u;
    // From state 0 one step gives the increment; the key is added, and one more step.
    state = (increment + key) * kMultiplier + increment;
}

enum class StreamPurpose : uint64_t { Camera = 1, Photon = 2, Test = 3, Setup = 4, Features = 5, Rounding = 6, Coverage = 7 };

// What a stream's paths share: the key made from (seed, pass, purpose). Built once per
// pass and handed to every path's Rng, it saves two of the five mixing rounds per path.
class RngStream {
public:
    RngStream(uint64_t seed, uint64_t pass, StreamPurpose purpose)
        : key_(mix64<uint64_t>(seed ^ mix64<uint64_t>(pass + 0x9e3779b97f4a7c15ull * static_cast<uint64_t>(purpose)))) {}
    uint64_t key() const { return key_; }

private:
    uint64_t key_;
};

// PCG32 (O'Neill 2014): small state, good statistical quality, cheap to seed per path.
class Rng {
public:
    Rng(uint64_t seed, uint64_t pass, uint64_t index, StreamPurpose purpose)
        : Rng(RngStream(seed, pass, purpose), index) {}
    Rng(const RngStream& stream, uint64_t index) { seedPcg32<uint64_t>(stream.key(), index, state_, inc_); }
    uint32_t next() {
        uint64_t old = state_;
        state_ = old * 6364136223846793005ull + inc_;
        uint32_t xorshifted = static_cast<uint32_t>(((old >> 18u) ^ old) >> 27u);
        uint32_t rot = static_cast<uint32_t>(old >> 59u);
        return (xorshifted >> rot) | (xorshifted << ((-rot) & 31));
    }
    // Uniform float in [0, 1): 24 random mantissa bits.
    float uniform() { return static_cast<float>(next() >> 8) * 0x1p-24f; }

    // The generator's state, for code that keeps many streams side by side (lanes.h's
    // uniformLanes continues them) and hands one back to an Rng.
    uint64_t state() const { return state_; }
    uint64_t increment() const { return inc_; }
    static Rng resume(uint64_t state, uint64_t increment) {
        Rng r;
        r.state_ = state;
        r.inc_ = increment;
        return r;
    }

private:
    Rng() = default;
    uint64_t state_ = 0, inc_ = 1;
};

}  // namespace photon
