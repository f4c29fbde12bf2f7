// The sampling warps against their closed forms.
#include <gtest/gtest.h>
#include <cmath>
#include "math/sampling.h"

namespace photon {
namespace {

TEST(Sampling, QuarterTurnSinCosMatchesLibm) {
    for (int i = -1000; i <= 1000; ++i) {
        float a = (kPi / 4.0f) * static_cast<float>(i) / 1000.0f;
        Vec2 cs = cosSinQuarterTurn(a);
        EXPECT_NEAR(cs.x, std::cos(a), 2e-7f) << a;
        EXPECT_NEAR(cs.y, std::sin(a), 2e-7f) << a;
    }
}

// Shirley & Chiu's map written with libm's trigonometry, as the reference.
Vec2 concentricReference(Vec2 u) {
    double ox = 2.0 * u.x - 1.0, oy = 2.0 * u.y - 1.0;
    if (ox == 0 && oy == 0) return {0, 0};
    double r, theta;
    if (std::abs(ox) > std::abs(oy)) {
        r = ox;
        theta = M_PI / 4 * (oy / ox);
    } else {
        r = oy;
        theta = M_PI / 2 - M_PI / 4 * (ox / oy);
    }
    return {static_cast<float>(r * std::cos(theta)), static_cast<float>(r * std::sin(theta))};
}

TEST(Sampling, ConcentricDiskMatchesClosedFormAndIsUniform) {
    constexpr int n = 256;
    double meanR2 = 0;
    for (int j = 0; j < n; ++j)
        for (int i = 0; i < n; ++i) {
            Vec2 u{(static_cast<float>(i) + 0.5f) / n, (static_cast<float>(j) + 0.5f) / n};
            Vec2 d = sampleUniformDiskConcentric(u), ref = concentricReference(u);
            EXPECT_NEAR(d.x, ref.x, 3e-7f);
            EXPECT_NEAR(d.y, ref.y, 3e-7f);
            ASSERT_LE(d.x * d.x + d.y * d.y, 1.0f + 1e-6f);
            meanR2 += d.x * d.x + d.y * d.y;
        }
    // Uniform on the unit disc: E[r^2] = 1/2 (stratified, so the error is tiny).
    EXPECT_NEAR(meanR2 / (n * n), 0.5, 1e-4);
}

TEST(Sampling, CosineHemisphereHasUnitLengthAndMeanCosineTwoThirds) {
    constexpr int n = 256;
    double meanCos = 0;
    for (int j = 0; j < n; ++j)
        for (int i = 0; i < n; ++i) {
            Vec3 w = sampleCosineHemisphere({(static_cast<float>(i) + 0.5f) / n, (static_cast<float>(j) + 0.5f) / n});
            EXPECT_NEAR(length(w), 1.0f, 1e-6f);
            meanCos += w.z;
        }
    // E[cos] under the density cos/pi over the hemisphere is 2/3.
    EXPECT_NEAR(meanCos / (n * n), 2.0 / 3.0, 1e-3);
}

}  // namespace
}  // namespace photon
