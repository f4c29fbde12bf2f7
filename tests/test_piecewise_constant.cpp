// The piecewise-constant densities environment maps are sampled with: they integrate to 1,
// sampling returns the density it reports, and a histogram of samples follows the cell
// probabilities (Pearson's chi-square).
#include <gtest/gtest.h>
#include <cmath>
#include "math/piecewise_constant.h"
#include "math/rng.h"

namespace photon {
namespace {

// Weights with a bright cell, empty cells and an empty row (row 2), 8 x 5.
std::vector<float> testWeights() {
    std::vector<float> w(8 * 5);
    for (int y = 0; y < 5; ++y)
        for (int x = 0; x < 8; ++x) w[size_t(y * 8 + x)] = y == 2 ? 0.0f : 0.1f + float((x * 7 + y * 3) % 5);
    w[1 * 8 + 6] = 60.0f;  // a "sun"
    w[4 * 8 + 0] = 0.0f;
    return w;
}

TEST(PiecewiseConstant1D, IntegratesToOneAndSamplesItsOwnDensity) {
    PiecewiseConstant1D d({1, 0, 3, 0, 0, 4});
    double integral = 0;
    for (size_t i = 0; i < d.size(); ++i) integral += d.pdf(i) / double(d.size());
    EXPECT_NEAR(integral, 1.0, 1e-6);
    EXPECT_FLOAT_EQ(d.integral(), 8.0f / 6.0f);
    for (float u : {0.0f, 0.1f, 0.124999f, 0.125f, 0.5f, 0.9f, 0.99999994f}) {
        PiecewiseConstant1D::Sample s = d.sample(u);
        EXPECT_EQ(s.cell, std::min(size_t(s.x * 6), size_t(5))) << u;
        EXPECT_GT(s.pdf, 0) << u;  // never a cell of weight 0
        EXPECT_FLOAT_EQ(s.pdf, d.pdf(s.cell)) << u;
    }
    // Cells of weight 0 are skipped: u = 1/8 (all of cell 0's mass) starts cell 2, u = 1/2
    // cell 5; within a cell x grows linearly with u.
    EXPECT_NEAR(d.sample(0.125f).x, 2.0f / 6.0f, 1e-6f);
    EXPECT_NEAR(d.sample(0.3125f).x, 2.5f / 6.0f, 1e-6f);
    EXPECT_NEAR(d.sample(0.5f).x, 5.0f / 6.0f, 1e-6f);
}

TEST(PiecewiseConstant1D, AllZeroWeightsGiveTheUniformDensity) {
    PiecewiseConstant1D d({0, 0, 0, 0});
    EXPECT_TRUE(d.allZero());
    for (size_t i = 0; i < 4; ++i) EXPECT_FLOAT_EQ(d.pdf(i), 1.0f);
    EXPECT_NEAR(d.sample(0.3f).x, 0.3f, 1e-6f);
}

TEST(PiecewiseConstant2D, IntegratesToOne) {
    PiecewiseConstant2D d(testWeights(), 8, 5);
    double integral = 0;
    for (int y = 0; y < 5; ++y)
        for (int x = 0; x < 8; ++x) integral += d.pdf(x, y) / 40.0;
    EXPECT_NEAR(integral, 1.0, 1e-6);
    // The density is the weight over the mean weight.
    double mean = 0;
    for (float w : testWeights()) mean += w / 40.0;
    EXPECT_NEAR(d.pdf(6, 1), 60.0 / mean, 1e-3);
    EXPECT_EQ(d.pdf(3, 2), 0.0f);  // the empty row
    EXPECT_EQ(d.pdf(0, 4), 0.0f);
}

TEST(PiecewiseConstant2D, SampleHistogramMatchesTheDensity) {
    PiecewiseConstant2D d(testWeights(), 8, 5);
    const int n = 400000;
    std::vector<int> counts(40, 0);
    Rng rng(7, 0, 0, StreamPurpose::Test);
    for (int i = 0; i < n; ++i) {
        PiecewiseConstant2D::Sample s = d.sample({rng.uniform(), rng.uniform()});
        ASSERT_EQ(s.x, std::min(int(s.point.x * 8), 7));
        ASSERT_EQ(s.y, std::min(int(s.point.y * 5), 4));
        ASSERT_FLOAT_EQ(s.pdf, d.pdf(s.x, s.y));
        ASSERT_GT(s.pdf, 0);
        ++counts[size_t(s.y * 8 + s.x)];
    }
    // Pearson's chi-square over the cells with any probability; empty cells get no samples.
    double chi2 = 0;
    int dof = -1;
    for (int c = 0; c < 40; ++c) {
        double expected = n * double(d.cellProbability(c % 8, c / 8));
        if (expected == 0) {
            EXPECT_EQ(counts[size_t(c)], 0);
            continue;
        }
        chi2 += (counts[size_t(c)] - expected) * (counts[size_t(c)] - expected) / expected;
        ++dof;
    }
    // 31 cells, 30 degrees of freedom: the 0.999 quantile of chi-square is 59.7.
    EXPECT_EQ(dof, 30);
    EXPECT_LT(chi2, 59.7);
}

}  // namespace
}  // namespace photon
