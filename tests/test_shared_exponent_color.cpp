// SharedExponentColor (math/shared_exponent_color.h): a colour in 32 bits whose dithered
// rounding keeps sums over many passes free of bias, and bfloat16 (math/bfloat16.h).
#include <gtest/gtest.h>
#include <cmath>
#include <limits>
#include "math/bfloat16.h"
#include "math/shared_exponent_color.h"

namespace photon {
namespace {

TEST(SharedExponentColor, ErrorWithinOne127thOfTheLargestChannel) {
    static_assert(sizeof(SharedExponentColor) == 4);
    for (const Color c : {Color(1.0f, 0.5f, 0.25f), Color(3e5f, 7.0f, 0.0f), Color(1e-30f, 2e-31f, 5e-32f),
                          Color(0.0123f, 0.0124f, 0.0125f), Color(255.9f, 0.001f, 128.0f)}) {
        const float largest = std::max(c[0], std::max(c[1], c[2]));
        for (float u : {0.0f, 0.3f, 0.7f, 0.99999994f}) {
            const Color back = SharedExponentColor::of(c, u).color();
            // A step of 2^(e - 8) for a largest channel of at least 2^(e - 1); where rounding
            // carries into the next exponent, 2^(e - 7) for one of at least 2^e 255 / 256.
            for (int k = 0; k < 3; ++k) EXPECT_LE(std::abs(back[k] - c[k]), largest / 127) << k << " " << u;
        }
    }
}

TEST(SharedExponentColor, DitheredRoundingHasTheColourAsItsMean) {
    // A channel 1/1000 of the largest has a mantissa of 0.17: rounded to the nearest it
    // would always be 0. Over u uniform in [0, 1) its mean is its value.
    const Color c(0.7f, 0.0007f, 0.31f);
    Color sum(0.0f);
    const int n = 4096;
    for (int i = 0; i < n; ++i) sum += SharedExponentColor::of(c, (i + 0.5f) / n).color();
    for (int k = 0; k < 3; ++k) EXPECT_NEAR(sum[k] / n, c[k], 1e-4f * c[k]) << k;
}

TEST(SharedExponentColor, ZeroNegativeTinyAndInfinite) {
    EXPECT_EQ(SharedExponentColor::of(Color(0.0f), 0.5f).color(), Color(0.0f));
    EXPECT_EQ(SharedExponentColor::of(Color(-1.0f, 0.0f, -2.0f), 0.5f).color(), Color(0.0f));
    EXPECT_EQ(SharedExponentColor::of(Color(1e-38f), 0.5f).color(), Color(0.0f));
    const float inf = std::numeric_limits<float>::infinity();
    EXPECT_EQ(SharedExponentColor::of(Color(inf, 1.0f, 1.0f), 0.5f).color()[1], inf);
    EXPECT_EQ(SharedExponentColor::of(Color(1e38f), 0.5f).color()[0], inf);
    EXPECT_EQ(SharedExponentColor::of(Color(std::nanf(""), 1.0f, 1.0f), 0.5f).color()[0], inf);
    // The largest mantissa rounded up to 256 carries into the exponent.
    EXPECT_EQ(SharedExponentColor::of(Color(255.9f, 0.0f, 0.0f), 0.99f).color()[0], 256.0f);
}

TEST(Bfloat16, RoundsToTheNearestOfEightSignificantBits) {
    for (float v : {1.0f, 3.14159f, 1e-20f, 6.02e23f, -2.5f}) EXPECT_NEAR(fromBfloat16(toBfloat16(v)), v, std::abs(v) / 256);
    // Steps of 1/128 at 1: ties go to the even mantissa, the rest to the nearest.
    EXPECT_EQ(fromBfloat16(toBfloat16(1.0f + 1.0f / 256)), 1.0f);
    EXPECT_EQ(fromBfloat16(toBfloat16(1.0f + 3.0f / 256)), 1.0f + 2.0f / 128);
    EXPECT_EQ(fromBfloat16(toBfloat16(1.0f + 3.0f / 512)), 1.0f + 1.0f / 128);
}

}  // namespace
}  // namespace photon
