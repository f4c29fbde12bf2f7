// The sampling warps against their closed forms.
#include <gtest/gtest.h>
#include <cmath>
#include <array>
#include "math/frame.h"
#include "math/rng.h"
#include "math/sampling.h"

namespace photon {
namespace {

TEST(Sampling, QuarterTurnSinCosMatchesLibm) {
    for (int i = -1000; i <= 1000; ++i) {
        float a = (kPi / 4.0f) * static_cast<float>(i) / 1000.0f;
        float c, s;
        cosSinQuarterTurn(a, c, s);
        EXPECT_NEAR(c, std::cos(a), 2e-7f) << a;
        EXPECT_NEAR(s, std::sin(a), 2e-7f) << a;
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

// The photon walk's lanes run the same templates on eight values at once: they must give
// exactly what the scalar calls give, lane by lane.
TEST(Sampling, LanesGiveTheScalarResults) {
    Rng rng(7, 0, 0, StreamPurpose::Test);
    for (int round = 0; round < 200; ++round) {
        FloatLanes ux, uy, nx, ny, nz;
        for (int i = 0; i < kLanes; ++i) {
            ux[i] = rng.uniform();
            uy[i] = rng.uniform();
            Vec3 n = normalize(Vec3(rng.uniform() - 0.5f, rng.uniform() - 0.5f, rng.uniform() - 0.5f));
            nx[i] = n.x, ny[i] = n.y, nz[i] = n.z;
        }
        FloatLanes x, y, z, sx, sy, sz, tx, ty, tz;
        cosineHemisphere(ux, uy, x, y, z);
        orthonormalBasis(nx, ny, nz, sx, sy, sz, tx, ty, tz);
        for (int i = 0; i < kLanes; ++i) {
            Vec3 w = sampleCosineHemisphere({ux[i], uy[i]});
            EXPECT_EQ(w.x, x[i]);
            EXPECT_EQ(w.y, y[i]);
            EXPECT_EQ(w.z, z[i]);
            Frame f = Frame::fromNormal({nx[i], ny[i], nz[i]});
            EXPECT_EQ(f.s.x, sx[i]);
            EXPECT_EQ(f.s.z, sz[i]);
            EXPECT_EQ(f.t.y, ty[i]);
        }
    }
    // The disc's centre (u = 1/2, 1/2) maps to the centre, not to 0/0.
    FloatLanes half = broadcast<FloatLanes>(0.5f), dx, dy;
    concentricDisk(half, half, dx, dy);
    EXPECT_EQ(dx[3], 0.0f);
    EXPECT_EQ(dy[3], 0.0f);
}

TEST(Sampling, RandomLanesContinueEachStreamAndAdvanceOnlyMaskedLanes) {
    std::array<Rng, kLanes> scalar{Rng(1, 0, 0, StreamPurpose::Test), Rng(1, 0, 1, StreamPurpose::Test),
                                   Rng(1, 0, 2, StreamPurpose::Test), Rng(1, 0, 3, StreamPurpose::Test),
                                   Rng(1, 0, 4, StreamPurpose::Test), Rng(1, 0, 5, StreamPurpose::Test),
                                   Rng(1, 0, 6, StreamPurpose::Test), Rng(1, 0, 7, StreamPurpose::Test)};
    uint64_t state[kLanes], increment[kLanes];
    for (int i = 0; i < kLanes; ++i) state[i] = scalar[i].state(), increment[i] = scalar[i].increment();
    for (int round = 0; round < 50; ++round) {
        IntLanes mask;
        for (int i = 0; i < kLanes; ++i) mask[i] = (round + i) % 3 == 0 ? 0 : -1;
        FloatLanes u = uniformLanes(state, increment, mask);
        for (int i = 0; i < kLanes; ++i) {
            if (!mask[i]) continue;
            EXPECT_EQ(u[i], scalar[i].uniform()) << "lane " << i << " round " << round;
        }
    }
    for (int i = 0; i < kLanes; ++i) {
        Rng resumed = Rng::resume(state[i], increment[i]);
        EXPECT_EQ(resumed.uniform(), scalar[i].uniform());
    }
}

}  // namespace
}  // namespace photon
