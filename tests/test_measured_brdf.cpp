// Measured BRDFs (materials/measured.cpp) and the warp their tables are stored in
// (math/bilinear_warp.h): the warp's samples against its density and its inverse, a file
// written from GGX against GGX's formula, sampling against eval() and pdf() by quadrature,
// and SPPM against the path tracer on a box of it.
#include <gtest/gtest.h>
#include <cmath>
#include <cstdio>
#include <vector>
#include "materials/measured_brdf.h"
#include "math/bilinear_warp.h"
#include "math/rng.h"
#include "scene/measured_brdf_file.h"
#include "bsdf_checks.h"
#include "measured_brdf_tables.h"
#include "test_support.h"

namespace photon::measured_brdf_tests {
namespace {

using namespace bsdf_checks;

// A 5 x 4 density with a zero corner and a steep ramp, in two slices along one parameter.
BilinearWarp2D unevenWarp() {
    std::vector<float> v;
    for (int s = 0; s < 2; ++s)
        for (int j = 0; j < 4; ++j)
            for (int i = 0; i < 5; ++i) v.push_back(s == 0 ? float(i * i + j) : float((4 - i) + 3 * j * j + 1));
    return BilinearWarp2D(5, 4, v);
}

TEST(BilinearWarp, SampleAndInvertAreInverses) {
    const BilinearWarp2D warp = unevenWarp();
    const SliceAxes axes({{0.0f, 1.0f}});
    const float params[] = {0.3f};
    const SliceBlend blend = axes.blend(params);
    Rng rng(3, 0, 0, StreamPurpose::Test);
    for (int k = 0; k < 20000; ++k) {
        const Vec2 u{rng.uniform(), rng.uniform()};
        const auto s = warp.sample(u, blend);
        const auto back = warp.invert(s.p, blend);
        ASSERT_NEAR(back.p.x, u.x, 2e-4f) << k;
        ASSERT_NEAR(back.p.y, u.y, 2e-4f) << k;
        ASSERT_NEAR(s.pdf, warp.density(s.p, blend), 1e-4f * s.pdf) << k;
        ASSERT_NEAR(back.pdf, s.pdf, 1e-4f * s.pdf) << k;
    }
}

// Samples fall in each cell of an 8 x 8 grid as often as the blended density's integral
// over it (by a fine midpoint rule) says.
TEST(BilinearWarp, SamplesFollowTheBlendedDensity) {
    const BilinearWarp2D warp = unevenWarp();
    const SliceAxes axes({{0.0f, 1.0f}});
    const float params[] = {0.3f};
    const SliceBlend blend = axes.blend(params);
    ASSERT_EQ(blend.count, 2);
    EXPECT_NEAR(blend.weight[1], 0.3f, 1e-6f);
    constexpr int kCells = 8, kDraws = 400000, kFine = 32;
    std::vector<double> counted(kCells * kCells, 0.0), expected(kCells * kCells, 0.0);
    Rng rng(5, 0, 0, StreamPurpose::Test);
    for (int k = 0; k < kDraws; ++k) {
        const Vec2 p = warp.sample({rng.uniform(), rng.uniform()}, blend).p;
        counted[std::min(kCells - 1, int(p.y * kCells)) * kCells + std::min(kCells - 1, int(p.x * kCells))] += 1.0 / kDraws;
    }
    double total = 0;
    for (int j = 0; j < kCells * kFine; ++j)
        for (int i = 0; i < kCells * kFine; ++i) {
            const Vec2 p{(i + 0.5f) / (kCells * kFine), (j + 0.5f) / (kCells * kFine)};
            const double mass = warp.density(p, blend) / double(kCells * kFine * kCells * kFine);
            expected[(j / kFine) * kCells + i / kFine] += mass;
            total += mass;
        }
    EXPECT_NEAR(total, 1.0, 1e-3);
    for (int c = 0; c < kCells * kCells; ++c) {
        const double sd = std::sqrt(expected[c] / kDraws);
        EXPECT_NEAR(counted[c], expected[c], 4 * sd + 1e-5) << "cell " << c;
    }
}

std::shared_ptr<const MeasuredBrdf> ggxBrdf(const test::GgxTableOptions& o = {}) {
    return readMeasuredBrdf(TensorFile(test::ggxTableFile(o), "ggx.bsdf"));
}

// The file's BRDF is R D(wm) / (4 sigma(wo) cos theta_i) with GGX's D and sigma: the
// tables' interpolation keeps it within 2% at angles between the tables' samples.
TEST(MeasuredBrdf, AGgxTableEvaluatesToGgxsFormula) {
    test::GgxTableOptions o;
    o.spectral = false;
    const MaterialPtr m = makeMeasured(ggxBrdf(o));
    const MaterialInputs in;
    int checked = 0;
    for (float cosO : {0.2f, 0.55f, 0.9f})
        for (float cosI : {0.3f, 0.7f, 0.97f})
            for (float dPhi : {0.4f, 2.0f, 3.0f}) {
                const Vec3 wo = direction(cosO, 1.1f), wi = direction(cosI, 1.1f + dPhi);
                const Vec3 wm = normalize(wo + wi);
                const double expected = test::ggxD(o.alpha, std::acos(wm.z)) /
                                        (4 * test::ggxSigma(o.alpha, std::acos(cosO)) * cosI);
                const Color f = m->eval(wo, wi, in, TransportMode::Radiance);
                for (int c = 0; c < 3; ++c)
                    EXPECT_NEAR(f[c], o.reflectance[c] * expected, 0.02 * o.reflectance[c] * expected)
                        << "cos_o " << cosO << " cos_i " << cosI << " dphi " << dPhi << " channel " << c;
                ++checked;
            }
    EXPECT_EQ(checked, 27);
    EXPECT_TRUE(isBlack(m->eval(direction(0.5f), direction(-0.5f), in, TransportMode::Radiance)));
}

// A flat spectrum projects to grey of the same value (the projection is white-balanced).
TEST(MeasuredBrdf, AFlatSpectrumIsGrey) {
    test::GgxTableOptions o;
    const MaterialPtr spectral = makeMeasured(ggxBrdf(o));
    o.spectral = false;
    o.reflectance = Color(luminance(o.reflectance));
    const MaterialPtr rgb = makeMeasured(ggxBrdf(o));
    const Vec3 wo = direction(0.6f, 0.2f), wi = direction(0.8f, 2.5f);
    const Color a = spectral->eval(wo, wi, {}, TransportMode::Radiance), b = rgb->eval(wo, wi, {}, TransportMode::Radiance);
    for (int c = 0; c < 3; ++c) EXPECT_NEAR(a[c], b[c], 1e-3f * b[c]) << c;
}

TEST(MeasuredBrdf, SamplesAgreeWithPdfAndEval) {
    const MaterialPtr m = makeMeasured(ggxBrdf());
    expectSamplesAgreeWithPdfAndEval(*m, {});
}

// The albedo by sampling (the luminance and the visible normals' warp) equals the albedo by
// quadrature of eval(), and the density integrates to the share of samples kept above the
// horizon, at most 1.
TEST(MeasuredBrdf, SamplingAgreesWithQuadrature) {
    const test::GgxTableOptions o;
    const MaterialPtr m = makeMeasured(ggxBrdf(o));
    const MaterialInputs in;
    for (float cosO : kCosines) {
        const Vec3 wo = direction(cosO, 0.9f);
        const Channels quadrature = integrateHemisphere(wo, float(o.alpha), [&](Vec3 wi) {
            return m->eval(wo, wi, in, TransportMode::Radiance) * wi.z;
        });
        const SampleEstimate sampled = estimateBySampling(*m, wo, in, TransportMode::Radiance, 17);
        for (int c = 0; c < 3; ++c)
            EXPECT_NEAR(sampled.mean[c], quadrature[c], 4 * sampled.stdError[c] + 0.005 * quadrature[c])
                << "cos_o " << cosO << " channel " << c;
        const Channels density = integrateHemisphere(wo, float(o.alpha), [&](Vec3 wi) { return Color(m->pdf(wo, wi, in)); });
        int kept = 0;
        Rng rng(23, 0, 0, StreamPurpose::Test);
        for (int k = 0; k < 100000; ++k) kept += bool(m->sample(wo, 0, {rng.uniform(), rng.uniform()}, in, TransportMode::Radiance));
        std::printf("  cos_o %.2f: albedo %.4f (sampled %.4f), pdf integral %.4f, kept %.4f\n", cosO, quadrature[1],
                    sampled.mean[1], density[0], kept / 1e5);
        EXPECT_LE(density[0], 1.005);
        EXPECT_NEAR(density[0], kept / 1e5, 0.01);
    }
}

// On the Cornell box with both blocks of the GGX table, SPPM's image mean is the path
// tracer's: the measured lobe is sampled, evaluated and weighted alike by both.
TEST(MeasuredBrdf, SppmAgreesWithPathTracer) {
    test::GgxTableOptions o;
    o.spectral = false;
    const test::PathAndSppmMeans means =
        test::renderPathAndSppm(test::cornellBoxWith(makeMeasured(ggxBrdf(o)), 32), 512, 256, 40000);
    std::printf("  path %.4f %.4f %.4f  sppm %.4f %.4f %.4f\n", means.path.x, means.path.y, means.path.z, means.sppm.x,
                means.sppm.y, means.sppm.z);
    for (int c = 0; c < 3; ++c) EXPECT_NEAR(means.sppm[c], means.path[c], 0.02f * means.path[c]) << "channel " << c;
}

}  // namespace
}  // namespace photon::measured_brdf_tests
