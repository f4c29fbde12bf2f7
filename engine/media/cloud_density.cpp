#include "media/cloud_density.h"
#include <algorithm>
#include <cmath>
#include <tbb/parallel_for.h>
#include "texture/perlin_noise.h"

namespace photon {

namespace {

// pbrt-v4's DNoise: the noise's gradient by forward differences of 0.01.
Vec3 noiseGradient(Vec3 p) {
    constexpr float kDelta = 0.01f;
    const float n = perlinNoise(p);
    return Vec3(perlinNoise(p + Vec3(kDelta, 0, 0)) - n, perlinNoise(p + Vec3(0, kDelta, 0)) - n,
                perlinNoise(p + Vec3(0, 0, kDelta)) - n) *
           (1.0f / kDelta);
}

}  // namespace

float cloudDensity(Vec3 p, const CloudParameters& cloud) {
    Vec3 pp = p * cloud.frequency;
    if (cloud.wispiness > 0) {
        // Two octaves of the noise's gradient push the lookup point about.
        float omega = 0.05f * cloud.wispiness, lambda = 10.0f;
        for (int i = 0; i < 2; ++i) {
            pp += noiseGradient(pp * lambda) * omega;
            omega *= 0.5f;
            lambda *= 1.99f;
        }
    }
    float d = 0, omega = 0.5f, lambda = 1.0f;
    for (int i = 0; i < 5; ++i) {
        d += omega * perlinNoise(pp * lambda);
        omega *= 0.5f;
        lambda *= 1.99f;
    }
    d = std::clamp((1 - p.y) * 4.5f * cloud.density * d, 0.0f, 1.0f);
    d += 2 * std::max(0.0f, 0.5f - p.y);
    return std::clamp(d, 0.0f, 1.0f);
}

int cloudResolution(const CloudParameters& cloud, float extent) {
    const float periods = std::abs(cloud.frequency) * 1.99f * 1.99f * 1.99f * extent;
    return std::clamp(int(std::ceil(4.0f * periods)), 8, 256);
}

std::vector<float> sampleCloud(const CloudParameters& cloud, const std::array<int, 3>& n, Vec3 p0, Vec3 p1) {
    std::vector<float> values(size_t(n[0]) * n[1] * n[2]);
    const Vec3 cell((p1.x - p0.x) / n[0], (p1.y - p0.y) / n[1], (p1.z - p0.z) / n[2]);
    tbb::parallel_for(0, n[2], [&](int k) {
        for (int j = 0; j < n[1]; ++j)
            for (int i = 0; i < n[0]; ++i) {
                const Vec3 p(p0.x + (i + 0.5f) * cell.x, p0.y + (j + 0.5f) * cell.y, p0.z + (k + 0.5f) * cell.z);
                values[(size_t(k) * n[1] + j) * n[0] + i] = cloudDensity(p, cloud);
            }
    });
    return values;
}

}  // namespace photon
