// The part of a volume photon estimate's ball inside a medium cut by a plane behind the
// point and one ahead (math/ball_in_half_spaces.h): against wedges whose share is known
// and against counting random points of the ball.
#include <gtest/gtest.h>
#include <cmath>
#include <numbers>
#include "math/ball_in_half_spaces.h"
#include "math/rng.h"

namespace photon {
namespace {

Vec3 unitFrom(Rng& rng) {
    const float z = 1.0f - 2.0f * rng.uniform(), phi = 2.0f * std::numbers::pi_v<float> * rng.uniform();
    const float s = std::sqrt(std::max(0.0f, 1.0f - z * z));
    return {s * std::cos(phi), s * std::sin(phi), z};
}

// One plane through the centre halves the ball; two through it leave the wedge between
// them, of dihedral angle pi - phi for outward directions phi apart: (pi - phi) / 2 pi.
TEST(BallInHalfSpaces, PlanesThroughTheCentreLeaveWedges) {
    const CuttingPlane none{};
    EXPECT_NEAR(ballShareInside({{0, 0, 1}, 0.0f}, none, 1.0f), 0.5f, 1e-6f);
    EXPECT_NEAR(ballShareInside(none, {{1, 0, 0}, 2.0f}, 1.0f), 1.0f, 1e-6f);
    for (float phi : {0.3f, 1.0f, 1.5707963f, 2.2f, 3.0f}) {
        const CuttingPlane a{{1, 0, 0}, 0.0f}, b{{std::cos(phi), std::sin(phi), 0}, 0.0f};
        const float expected = (std::numbers::pi_v<float> - phi) / (2 * std::numbers::pi_v<float>);
        EXPECT_NEAR(ballShareInside(a, b, 0.7f), expected, 1e-4f) << "phi " << phi;
    }
}

// Planes at random distances (a fifth of them beyond the ball) and angles, parallel ones
// facing the same way and opposite ways among them: the share of 400,000 random points of
// the ball inside both, within 4 standard errors and 2e-4.
TEST(BallInHalfSpaces, ShareMatchesPointsCounted) {
    Rng rng(7, 0, 0, StreamPurpose::Test);
    for (int c = 0; c < 60; ++c) {
        const float r = 0.5f + rng.uniform();
        CuttingPlane a{unitFrom(rng), 1.2f * r * rng.uniform()}, b{unitFrom(rng), 1.2f * r * rng.uniform()};
        if (c % 10 == 0) b.outward = a.outward;
        if (c % 10 == 1) b.outward = -a.outward;
        const float share = ballShareInside(a, b, r);
        constexpr int kPoints = 400000;
        int inside = 0, inBall = 0;
        while (inBall < kPoints) {
            const Vec3 p{r * (2 * rng.uniform() - 1), r * (2 * rng.uniform() - 1), r * (2 * rng.uniform() - 1)};
            if (dot(p, p) > r * r) continue;
            ++inBall;
            inside += dot(p, a.outward) <= a.distance && dot(p, b.outward) <= b.distance;
        }
        const double counted = double(inside) / kPoints;
        const double sigma = std::sqrt(counted * (1 - counted) / kPoints);
        EXPECT_NEAR(share, counted, 4 * sigma + 2e-4) << "case " << c << ": r " << r << ", planes at " << a.distance
                                                      << " and " << b.distance << ", cos "
                                                      << dot(a.outward, b.outward);
    }
}

}  // namespace
}  // namespace photon
