// Owen-scrambled Sobol points, padded: every 1D or 2D draw of a path is its own sequence
// over the sample index, stratified within itself and independent of the others.
//
// A 2D draw takes the first two Sobol dimensions (a (0,2)-sequence in base 2: any aligned
// block of 2^m consecutive points has one point in every elementary interval of area
// 2^-m), with the index shuffled and each coordinate scrambled by hash-based Owen
// scrambling, keyed by the draw's own seed (Burley 2020, "Practical Hash-based Owen
// Scrambling", JCGT 9(4); the hash is Vegdahl's 2021 improvement of Laine & Karras 2011's).
// The shuffle is a nested uniform scramble of the index, which maps each aligned block of
// 2^m indices onto another, so the first 2^m samples of a draw still form a net; it
// decorrelates draws, which share the same two Sobol dimensions.
#pragma once
#include <array>
#include <cstdint>
#include <photon/vec.h>

namespace photon::sobol {

inline uint32_t reverseBits(uint32_t x) {
    x = __builtin_bswap32(x);
    x = ((x & 0x0f0f0f0fu) << 4) | ((x >> 4) & 0x0f0f0f0fu);
    x = ((x & 0x33333333u) << 2) | ((x >> 2) & 0x33333333u);
    return ((x & 0x55555555u) << 1) | ((x >> 1) & 0x55555555u);
}

// A permutation of 32-bit words in which each bit of the result depends on that bit and
// the ones below it only (additions and multiplications carry upward), keyed by `seed`.
inline uint32_t laineKarrasPermutation(uint32_t x, uint32_t seed) {
    x ^= x * 0x3d20adeau;
    x += seed;
    x *= (seed >> 16) | 1u;
    x ^= x * 0x05526c56u;
    x ^= x * 0x53a22864u;
    return x;
}

// Owen scrambling of a fraction's 32 bits (most significant first): each bit flipped by a
// random function of the bits above it.
inline uint32_t owenScramble(uint32_t x, uint32_t seed) {
    return reverseBits(laineKarrasPermutation(reverseBits(x), seed));
}

// Sobol's second dimension (primitive polynomial x + 1, m_1 = 1): direction numbers
// v_0 = 2^31, v_k = v_{k-1} ^ (v_{k-1} >> 1), the point at index i the XOR of v_k over i's
// set bits k (the first dimension is i's bits reversed, van der Corput). Held bit-reversed,
// as the scrambles read them, and by the index's bytes: four look-ups instead of a loop over
// the (shuffled, so 32 significant) bits.
inline constexpr std::array<std::array<uint32_t, 256>, 4> kSecondDimensionReversed = [] {
    std::array<uint32_t, 32> v{};
    v[0] = 1u << 31;
    for (int k = 1; k < 32; ++k) v[k] = v[k - 1] ^ (v[k - 1] >> 1);
    std::array<std::array<uint32_t, 256>, 4> table{};
    for (int byte = 0; byte < 4; ++byte)
        for (uint32_t b = 0; b < 256; ++b) {
            uint32_t x = 0;
            for (int k = 0; k < 8; ++k)
                if (b >> k & 1u) x ^= v[8 * byte + k];
            uint32_t reversed = 0;  // x's bits in reverse order (reverseBits is not constexpr)
            for (int k = 0; k < 32; ++k) reversed |= (x >> k & 1u) << (31 - k);
            table[byte][b] = reversed;
        }
    return table;
}();

inline uint32_t secondDimensionReversed(uint32_t index) {
    const auto& t = kSecondDimensionReversed;
    return t[0][index & 255u] ^ t[1][index >> 8 & 255u] ^ t[2][index >> 16 & 255u] ^ t[3][index >> 24];
}

// 32 bits of a fraction to a float in [0, 1): the top 24 (the Rng's resolution).
inline float toUnit(uint32_t x) { return static_cast<float>(x >> 8) * 0x1p-24f; }

// The draw's index shuffled: nested uniform scrambling, which maps each aligned block of 2^m
// indices onto another.
inline uint32_t shuffle(uint32_t index, uint32_t seed) { return owenScramble(index, seed); }

// The first dimension at (shuffled) index i, i reversed, Owen-scrambled:
// reverse(LK(reverse(reverse(i)))).
inline float firstDimension(uint32_t i, uint32_t seed) { return toUnit(reverseBits(laineKarrasPermutation(i, seed))); }

// Sample `index` of the 1D draw whose seeds are `key`'s two halves.
inline float sample1D(uint32_t index, uint64_t key) {
    return firstDimension(shuffle(index, static_cast<uint32_t>(key)), static_cast<uint32_t>(key >> 32));
}

// Sample `index` of the 2D draw whose seeds are `key`'s two halves and `seed2`.
inline Vec2 sample2D(uint32_t index, uint64_t key, uint32_t seed2) {
    const uint32_t i = shuffle(index, static_cast<uint32_t>(key));
    return {firstDimension(i, static_cast<uint32_t>(key >> 32)),
            toUnit(reverseBits(laineKarrasPermutation(secondDimensionReversed(i), seed2)))};
}

}  // namespace photon::sobol
