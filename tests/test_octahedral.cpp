// Octahedral normal packing: round trips stay within the stated angular error.
#include <gtest/gtest.h>
#include <cmath>
#include "math/octahedral.h"
#include "math/sampling.h"

namespace photon {
namespace {

TEST(Octahedral, RoundTripErrorBelowOneTenThousandthRadian) {
    constexpr int n = 200;
    float worst = 0;
    for (int j = 0; j < n; ++j)
        for (int i = 0; i < n; ++i) {
            Vec3 v = sampleUniformSphere({(static_cast<float>(i) + 0.5f) / n, (static_cast<float>(j) + 0.5f) / n});
            Vec3 back = OctahedralVector(v).decode();
            EXPECT_NEAR(length(back), 1.0f, 1e-6f);
            worst = std::max(worst, std::atan2(length(cross(v, back)), dot(v, back)));  // exact near 0, unlike acos
        }
    EXPECT_LT(worst, 1e-4f);
    // The axes, including the folded lower pole, come back exactly.
    for (Vec3 axis : {Vec3(1, 0, 0), Vec3(-1, 0, 0), Vec3(0, 1, 0), Vec3(0, -1, 0), Vec3(0, 0, 1), Vec3(0, 0, -1)}) {
        Vec3 back = OctahedralVector(axis).decode();
        EXPECT_NEAR(dot(back, axis), 1.0f, 1e-6f);
    }
}

}  // namespace
}  // namespace photon
