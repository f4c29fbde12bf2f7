#include "texture/perlin_noise.h"
#include <cmath>
#include <cstdint>

namespace photon {
namespace {

// Perlin's permutation of 0..255 (Perlin 2002's reference implementation).
constexpr uint8_t kPermutation[256] = {
    151, 160, 137, 91,  90,  15,  131, 13,  201, 95,  96,  53,  194, 233, 7,   225, 140, 36,  103, 30,  69,  142,
    8,   99,  37,  240, 21,  10,  23,  190, 6,   148, 247, 120, 234, 75,  0,   26,  197, 62,  94,  252, 219, 203,
    117, 35,  11,  32,  57,  177, 33,  88,  237, 149, 56,  87,  174, 20,  125, 136, 171, 168, 68,  175, 74,  165,
    71,  134, 139, 48,  27,  166, 77,  146, 158, 231, 83,  111, 229, 122, 60,  211, 133, 230, 220, 105, 92,  41,
    55,  46,  245, 40,  244, 102, 143, 54,  65,  25,  63,  161, 1,   216, 80,  73,  209, 76,  132, 187, 208, 89,
    18,  169, 200, 196, 135, 130, 116, 188, 159, 86,  164, 100, 109, 198, 173, 186, 3,   64,  52,  217, 226, 250,
    124, 123, 5,   202, 38,  147, 118, 126, 255, 82,  85,  212, 207, 206, 59,  227, 47,  16,  58,  17,  182, 189,
    28,  42,  223, 183, 170, 213, 119, 248, 152, 2,   44,  154, 163, 70,  221, 153, 101, 155, 167, 43,  172, 9,
    129, 22,  39,  253, 19,  98,  108, 110, 79,  113, 224, 232, 178, 185, 112, 104, 218, 246, 97,  228, 251, 34,
    242, 193, 238, 210, 144, 12,  191, 179, 162, 241, 81,  51,  145, 235, 249, 14,  239, 107, 49,  192, 214, 31,
    181, 199, 106, 157, 184, 84,  204, 176, 115, 121, 50,  45,  127, 4,   150, 254, 138, 236, 205, 93,  222, 114,
    67,  29,  24,  72,  243, 141, 128, 195, 78,  66,  215, 61,  156, 180};

int permuted(int i) { return kPermutation[i & 255]; }

// The gradient of lattice point (x, y, z), dotted with the offset d from it: one of twelve
// edge directions of a cube, picked by the hashed corner (pbrt's assignment of the 16
// hash values to them).
float gradient(int x, int y, int z, Vec3 d) {
    const int h = permuted(permuted(permuted(x) + y) + z) & 15;
    const float u = h < 8 || h == 12 || h == 13 ? d.x : d.y;
    const float v = h < 4 || h == 12 || h == 13 ? d.y : d.z;
    return ((h & 1) ? -u : u) + ((h & 2) ? -v : v);
}

// Perlin 2002's fade curve 6t^5 - 15t^4 + 10t^3: flat at both ends to second order.
float fade(float t) { return t * t * t * (t * (t * 6 - 15) + 10); }

float lerp(float t, float a, float b) { return a + t * (b - a); }

}  // namespace

float perlinNoise(Vec3 p) {
    // Far from the origin the offsets inside a cell would lose their precision and the
    // cell's index overflow an int: the pattern repeats every 256 units, so wrap first.
    constexpr float kWrap = 1 << 30;
    const float x = std::fmod(p.x, kWrap), y = std::fmod(p.y, kWrap), z = std::fmod(p.z, kWrap);
    if (!std::isfinite(x) || !std::isfinite(y) || !std::isfinite(z)) return 0;
    const float fx = std::floor(x), fy = std::floor(y), fz = std::floor(z);
    const Vec3 d{x - fx, y - fy, z - fz};
    const int ix = int(fx) & 255, iy = int(fy) & 255, iz = int(fz) & 255;
    const float w000 = gradient(ix, iy, iz, d);
    const float w100 = gradient(ix + 1, iy, iz, {d.x - 1, d.y, d.z});
    const float w010 = gradient(ix, iy + 1, iz, {d.x, d.y - 1, d.z});
    const float w110 = gradient(ix + 1, iy + 1, iz, {d.x - 1, d.y - 1, d.z});
    const float w001 = gradient(ix, iy, iz + 1, {d.x, d.y, d.z - 1});
    const float w101 = gradient(ix + 1, iy, iz + 1, {d.x - 1, d.y, d.z - 1});
    const float w011 = gradient(ix, iy + 1, iz + 1, {d.x, d.y - 1, d.z - 1});
    const float w111 = gradient(ix + 1, iy + 1, iz + 1, {d.x - 1, d.y - 1, d.z - 1});
    const float wx = fade(d.x), wy = fade(d.y), wz = fade(d.z);
    const float y0 = lerp(wy, lerp(wx, w000, w100), lerp(wx, w010, w110));
    const float y1 = lerp(wy, lerp(wx, w001, w101), lerp(wx, w011, w111));
    return lerp(wz, y0, y1);
}

// pbrt-v4 counts the octaves a pixel resolves from the ray's differentials and fades the
// last one in; photon's lookups carry no footprint, which is pbrt's limit of a footprint
// finer than the last octave: all `octaves` of them, in full.
float fractalBrownianMotion(Vec3 p, float omega, int octaves) {
    float sum = 0, lambda = 1, o = 1;
    for (int i = 0; i < octaves; ++i) {
        sum += o * perlinNoise(p * lambda);
        lambda *= 1.99f;
        o *= omega;
    }
    return sum;
}

float turbulence(Vec3 p, float omega, int octaves) {
    float sum = 0, lambda = 1, o = 1;
    for (int i = 0; i < octaves; ++i) {
        sum += o * std::abs(perlinNoise(p * lambda));
        lambda *= 1.99f;
        o *= omega;
    }
    // pbrt-v4 stands 0.2, about the mean of |noise|, for the octaves above those resolved.
    return sum + o * 0.2f;
}

}  // namespace photon
