// DensityGrid: a density sampled at the centres of a box's cells, trilinear between samples
// and toward zeros beyond them, zero outside the box; its integral along a line and the distance at
// which that integral reaches a depth, both exact, against integrals done by hand.
#include <gtest/gtest.h>
#include <cmath>
#include <limits>
#include "math/density_grid.h"

namespace photon::density_grid_tests {
namespace {

// Samples f(i, j, k) on an nx * ny * nz lattice, which is world space.
template <class F>
DensityGrid latticeOf(int nx, int ny, int nz, F f) {
    std::vector<float> values;
    for (int k = 0; k < nz; ++k)
        for (int j = 0; j < ny; ++j)
            for (int i = 0; i < nx; ++i) values.push_back(f(i, j, k));
    return DensityGrid(nx, ny, nz, std::move(values), Transform());
}

// Inside the lattice, trilinear interpolation reproduces any function linear in each
// coordinate, so the integral along a line is that function's.
TEST(DensityGrid, IntegratesAMultilinearDensityExactly) {
    const DensityGrid grid = latticeOf(6, 5, 7, [](int i, int j, int k) { return float((1 + i) * (1 + 0.5 * j) * (2 + k)); });
    auto density = [](double x, double y, double z) { return (1 + x) * (1 + 0.5 * y) * (2 + z); };
    EXPECT_NEAR(grid.at({2.25f, 1.5f, 3.75f}), density(2.25, 1.5, 3.75), 1e-4);
    // Along x from (0.5, 1.2, 1.7) for 3: the integral of a linear function.
    EXPECT_NEAR(grid.integral({0.5f, 1.2f, 1.7f}, {1, 0, 0}, 3.0f), 1.6 * 3.7 * (1.5 * 3 + 4.5), 1e-4);
    // Along a diagonal, a cubic in t, integrated by many midpoints.
    const Vec3 o{0.3f, 0.4f, 0.2f}, d = normalize(Vec3{1.0f, 0.8f, 1.1f});
    const float length = 4.5f;
    double expected = 0;
    constexpr int kSteps = 200000;
    for (int s = 0; s < kSteps; ++s) {
        const double t = (s + 0.5) * length / kSteps;
        expected += density(o.x + d.x * t, o.y + d.y * t, o.z + d.z * t) * length / kSteps;
    }
    EXPECT_NEAR(grid.integral(o, d, length), expected, 1e-6 * expected);
}

// One sample of 2, its box the lattice unit cube around it: toward the faces the density
// falls as toward a 0 one unit away, to 1 on them, and is 0 outside. Along the axis through
// it, 2 (1 - |x|) over [-1/2, 1/2] integrates to 1.5.
TEST(DensityGrid, FallsTowardZeroInsideItsBoxAndIsZeroOutside) {
    const DensityGrid grid = latticeOf(1, 1, 1, [](int, int, int) { return 2.0f; });
    EXPECT_NEAR(grid.integral({-3, 0, 0}, {1, 0, 0}, 10.0f), 1.5, 1e-6);
    EXPECT_NEAR(grid.integral({-3, 0, 0}, {1, 0, 0}, std::numeric_limits<float>::infinity()), 1.5, 1e-6);
    EXPECT_NEAR(grid.integral({-3, 0.25f, 0}, {1, 0, 0}, 10.0f), 1.5 * 0.75, 1e-6);
    EXPECT_EQ(grid.integral({-3, 0.75f, 0}, {1, 0, 0}, 10.0f), 0.0);
    EXPECT_EQ(grid.integral({3, 0, 0}, {1, 0, 0}, 10.0f), 0.0);
    EXPECT_NEAR(grid.at({0.25f, 0, 0}), 1.5f, 1e-6f);
    EXPECT_NEAR(grid.at({0.5f, 0, 0}), 1.0f, 1e-6f);
    EXPECT_EQ(grid.at({0.75f, 0, 0}), 0.0f);
}

// A box's samples sit at the centres of its cells: a 4-sample grid over [0, 2] has them at
// 0.25, 0.75, 1.25 and 1.75 (pbrt-v4's SampledGrid).
TEST(DensityGrid, ABoxPutsItsSamplesAtItsCellsCentres) {
    const Transform lattice = DensityGrid::latticeFromBox(4, 1, 1, {0, -1, -1}, {2, 1, 1});
    const DensityGrid grid(4, 1, 1, {1, 2, 3, 4}, lattice);
    EXPECT_NEAR(grid.at({0.75f, 0, 0}), 2.0f, 1e-6f);
    EXPECT_NEAR(grid.at({1.0f, 0, 0}), 2.5f, 1e-6f);
    EXPECT_NEAR(grid.at({0.0f, 0, 0}), 0.5f, 1e-6f);
    // Along x through the box: from 0 to 0.25 the ramp 0.5 -> 1, between the samples the
    // trapezoids' means times 0.5, from 1.75 to 2 the ramp 4 -> 2; nothing outside.
    const double inside = 0.25 * (0.5 + 1.0) / 2 + 0.5 * (1.5 + 2.5 + 3.5) + 0.25 * (4.0 + 2.0) / 2;
    EXPECT_NEAR(grid.integral({0, 0, 0}, {1, 0, 0}, 2.0f), inside, 1e-6);
    EXPECT_NEAR(grid.integral({-1, 0, 0}, {1, 0, 0}, 4.0f), inside, 1e-6);
}

// The distance at which the integral reaches a depth is where integral() says it does; past
// the whole segment's integral there is none, and the whole integral is reported.
TEST(DensityGrid, ReachesADepthWhereItsIntegralDoes) {
    const DensityGrid grid = latticeOf(5, 5, 5, [](int i, int j, int k) { return float((i * 7 + j * 3 + k * 5) % 4); });
    const Vec3 o{-0.7f, 0.6f, 1.3f}, d = normalize(Vec3{1.0f, 0.3f, 0.45f});
    const double total = grid.integral(o, d, 8.0f);
    ASSERT_GT(total, 1.0);
    for (double depth : {0.01, 0.3, 1.0, total * 0.5, total * 0.999}) {
        const DensityGrid::Reach r = grid.reach(o, d, 8.0f, depth);
        ASSERT_LT(r.t, 8.0f) << depth;
        EXPECT_EQ(r.depth, depth);
        EXPECT_NEAR(grid.integral(o, d, r.t), depth, 1e-5 * std::max(1.0, depth)) << depth;
    }
    const DensityGrid::Reach beyond = grid.reach(o, d, 8.0f, total * 1.01);
    EXPECT_TRUE(std::isinf(beyond.t));
    EXPECT_NEAR(beyond.depth, total, 1e-9 * total);
}

}  // namespace
}  // namespace photon::density_grid_tests
