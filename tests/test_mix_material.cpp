// The mix material: eval is the blend of its parts, sampling agrees with eval and pdf by
// independent quadrature, delta parts keep their weights, and SPPM agrees with the path
// tracer on a scene that uses it.
#include <gtest/gtest.h>
#include "bsdf_checks.h"
#include "materials/material.h"
#include "test_support.h"
#include "texture/textures.h"

namespace photon {
namespace {

using namespace bsdf_checks;

const MaterialInputs kAnywhere{{{0.3f, 0.6f}}, Color(1.0f)};
const Color kRed(0.8f, 0.2f, 0.1f);

TEST(MixMaterial, EvalAndPdfBlendTheParts) {
    MaterialPtr a = makeDiffuse(kRed), b = makeConductor(Color(0.9f), 0.3f);
    MaterialPtr mix = makeMix(a, b, 0.3f);
    Rng rng(3, 0, 0, StreamPurpose::Test);
    for (int i = 0; i < 1000; ++i) {
        Vec3 wo = sampleCosineHemisphere({rng.uniform(), rng.uniform()});
        Vec3 wi = sampleCosineHemisphere({rng.uniform(), rng.uniform()});
        Color expected = a->eval(wo, wi, a->inputsAt(kAnywhere.at), TransportMode::Radiance) * 0.7f +
                         b->eval(wo, wi, b->inputsAt(kAnywhere.at), TransportMode::Radiance) * 0.3f;
        EXPECT_VEC3_NEAR(mix->eval(wo, wi, kAnywhere, TransportMode::Radiance), expected, 1e-6f * maxComponent(expected));
        float p = 0.7f * a->pdf(wo, wi, kAnywhere) + 0.3f * b->pdf(wo, wi, kAnywhere);
        EXPECT_NEAR(mix->pdf(wo, wi, kAnywhere), p, 1e-6f * p);
    }
    EXPECT_EQ(mix->lobes(), unsigned(kDiffuseLobe | kGlossyLobe));
    EXPECT_FALSE(mix->textured());
    EXPECT_THROW(makeMix(a, makeDielectric(1.5f), 0.5f), std::invalid_argument);
}

// Mean sample weight = quadrature of eval |cos| (1%); pdf integrates to 1; weights agree.
TEST(MixMaterial, SamplingMatchesQuadratureOfEval) {
    MaterialPtr mix = makeMix(makeDiffuse(kRed), makeConductor(Color(0.9f, 0.6f, 0.3f), 0.3f), 0.4f);
    for (float cosO : kCosines) {
        SCOPED_TRACE("cos(theta_o) = " + std::to_string(cosO));
        Vec3 wo = direction(cosO);
        SampleEstimate mc = estimateBySampling(*mix, wo, kAnywhere, TransportMode::Radiance, 5);
        Channels quad = integrateHemisphere(wo, 0.09f, [&](Vec3 wi) {
            return mix->eval(wo, wi, kAnywhere, TransportMode::Radiance) * wi.z;
        });
        double pdfIntegral = integrateHemisphere(wo, 0.09f, [&](Vec3 wi) { return Color(mix->pdf(wo, wi, kAnywhere)); })[0];
        for (int c = 0; c < 3; ++c) EXPECT_NEAR(mc.mean[c], quad[c], tolerance(quad[c])) << "channel " << c;
        EXPECT_NEAR(pdfIntegral, mc.nonDeltaFraction, 0.005);
    }
}

// A mirror mixed with a diffuse surface: the delta part keeps its weight, so the albedo is
// (1 - t) R + t rho exactly in expectation.
TEST(MixMaterial, DeltaPartKeepsItsShare) {
    const float t = 0.25f;
    MaterialPtr mix = makeMix(makeMirror(Color(0.9f)), makeDiffuse(Color(0.5f)), t);
    Vec3 wo = direction(0.6f);
    SampleEstimate mc = estimateBySampling(*mix, wo, kAnywhere, TransportMode::Radiance, 9);
    EXPECT_NEAR(mc.mean[0], (1 - t) * 0.9 + t * 0.5, 4 * mc.stdError[0] + 1e-6);
    EXPECT_NEAR(mc.nonDeltaFraction, t, 0.005);
}

// A textured amount: the blend follows the texture at the hit's uv.
TEST(MixMaterial, TexturedAmountFollowsTheTexture) {
    auto checker = makeCheckerboardTexture(Color(0.0f), Color(1.0f), UvMapping{{2, 2}, {0, 0}});
    MaterialPtr mix = makeMix(makeDiffuse(Color(0.2f)), makeDiffuse(Color(0.7f)), FloatParam(checker));
    EXPECT_TRUE(mix->textured());
    Vec3 up(0, 0, 1);
    EXPECT_NEAR(mix->eval(up, up, {{0.1f, 0.1f}, Color(1.0f)}, TransportMode::Radiance).x, 0.2f * kInvPi, 1e-7);
    EXPECT_NEAR(mix->eval(up, up, {{0.6f, 0.1f}, Color(1.0f)}, TransportMode::Radiance).x, 0.7f * kInvPi, 1e-7);
}

// SPPM (visible points split between the diffuse part and the glossy one) against the path
// tracer on the Cornell box with blocks of half diffuse, half rough metal.
TEST(MixMaterial, SppmAgreesWithThePathTracer) {
    MaterialPtr mix = makeMix(makeDiffuse(Color(0.7f, 0.7f, 0.5f)), makeConductor(Color(0.9f, 0.7f, 0.4f), 0.35f), 0.5f);
    test::PathAndSppmMeans m = test::renderPathAndSppm(test::cornellBoxWith(mix, 32), 512, 64, 100000);
    for (int c = 0; c < 3; ++c) EXPECT_NEAR(m.sppm[c], m.path[c], 0.02f * m.path[c]) << "channel " << c;
    std::printf("  path %.5f %.5f %.5f  sppm %.5f %.5f %.5f\n", m.path.x, m.path.y, m.path.z, m.sppm.x, m.sppm.y, m.sppm.z);
}

}  // namespace
}  // namespace photon
