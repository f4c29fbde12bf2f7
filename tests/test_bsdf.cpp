// Material tests: sample() against eval()/pdf() by independent quadrature, analytic
// reflectances, reciprocity, energy conservation and sample/pdf consistency.
#include <gtest/gtest.h>
#include <array>
#include <cmath>
#include <cstdio>
#include <ostream>
#include <string>
#include <vector>
#include "materials/fresnel.h"
#include "materials/material.h"
#include "math/rng.h"
#include "math/sampling.h"
#include "bsdf_checks.h"

namespace photon {
namespace {

using namespace bsdf_checks;
constexpr float kIor = 1.5f;
const Color kWhite(1.0f);
// Inputs with the given tint at an arbitrary uv (these materials read no texture).
MaterialInputs tinted(Color tint) { return {{}, tint}; }

// A material under test: `width` is the GGX alpha the quadrature resolves (1 if broad);
// `deltaAlbedo` the known reflectance of its delta lobe at a given cos(theta_o), if any;
// `lambertian` says the albedo is exactly the tint at every angle.
struct Case {
    std::string name;
    MaterialPtr material;
    Color tint;
    float width;
    MaterialInputs inputs() const { return tinted(tint); }
    float (*deltaAlbedo)(float cosO) = nullptr;
    bool lambertian = false;
};

float smoothCoatAlbedo(float cosO) { return fresnelDielectric(cosO, kIor); }

std::vector<Case> nonDeltaCases() {
    const Color colour(0.8f, 0.3f, 0.05f);
    return {
        {"DiffuseWhite", makeDiffuse(kWhite), kWhite, 1.0f, nullptr, true},
        {"DiffuseColour", makeDiffuse(colour), colour, 1.0f, nullptr, true},
        {"DiffuseDark", makeDiffuse(Color(0.1f, 0.9f, 0.0f)), Color(0.1f, 0.9f, 0.0f), 1.0f, nullptr, true},
        {"Conductor01", makeConductor(kWhite, 0.1f), kWhite, 0.01f},
        {"Conductor03", makeConductor(kWhite, 0.3f), kWhite, 0.09f},
        {"Conductor07", makeConductor(kWhite, 0.7f), kWhite, 0.49f},
        {"Conductor03Gold", makeConductor(Color(1.0f, 0.78f, 0.34f), 0.3f), Color(1.0f, 0.78f, 0.34f), 0.09f},
        {"Plastic0", makePlastic(kWhite, kIor, 0.0f), kWhite, 1.0f, smoothCoatAlbedo},
        {"Plastic005", makePlastic(kWhite, kIor, 0.05f), kWhite, 0.0025f},
        {"Plastic03", makePlastic(kWhite, kIor, 0.3f), kWhite, 0.09f},
        {"Plastic0Colour", makePlastic(colour, kIor, 0.0f), colour, 1.0f, smoothCoatAlbedo},
        {"Plastic03Colour", makePlastic(colour, kIor, 0.3f), colour, 0.09f},
    };
}

// gtest prints parameters in failure messages and test lists; the name says it all.
void PrintTo(const Case& c, std::ostream* os) { *os << c.name; }

class BsdfAgreement : public testing::TestWithParam<Case> {};

// Tests 1, 2 and 4: the mean sample weight equals the quadrature of eval |cos| (plus the
// delta lobe's known albedo), and both equal rho for Lambertian materials; pdf()
// integrates to the share of draws that yield a non-delta direction (so <= 1, and 1 for
// Lambertian); white materials never gain energy.
TEST_P(BsdfAgreement, SamplingMatchesQuadratureOfEval) {
    const Case& tc = GetParam();
    for (float cosO : kCosines) {
        SCOPED_TRACE("cos(theta_o) = " + std::to_string(cosO));
        Vec3 wo = direction(cosO);
        auto mc = estimateBySampling(*tc.material, wo, tc.inputs(), TransportMode::Radiance, uint64_t(cosO * 1000));
        Channels quad = integrateHemisphere(wo, tc.width, [&](Vec3 wi) {
            return tc.material->eval(wo, wi, tc.inputs(), TransportMode::Radiance) * wi.z;
        });
        float pdfIntegral = float(integrateHemisphere(wo, tc.width, [&](Vec3 wi) {
            return Color(tc.material->pdf(wo, wi, tc.inputs()));
        })[0]);
        float delta = tc.deltaAlbedo ? tc.deltaAlbedo(cosO) : 0.0f;
        for (int c = 0; c < 3; ++c) {
            double expected = quad[c] + delta;
            EXPECT_NEAR(mc.mean[c], expected, tolerance(expected))
                << "channel " << c << ", MC standard error " << mc.stdError[c];
            if (tc.tint == kWhite) {
                EXPECT_LE(mc.mean[c], 1.0 + tolerance(1.0)) << "energy gain, channel " << c;
            }
            if (tc.lambertian) {
                EXPECT_NEAR(mc.mean[c], tc.tint[c], 1e-6);  // every weight is exactly rho
                EXPECT_NEAR(quad[c], tc.tint[c], 1e-3);
            }
        }
        EXPECT_LE(pdfIntegral, 1.0f + 0.005f);
        EXPECT_NEAR(pdfIntegral, mc.nonDeltaFraction, 0.005);
        if (tc.lambertian) {
            EXPECT_NEAR(pdfIntegral, 1.0f, 1e-3f);
        }
        std::printf("  %-16s cos %.2f  MC %.4f %.4f %.4f (se %.4f)  quad+delta %.4f %.4f %.4f"
                    "  int pdf %.4f  non-delta share %.4f\n",
                    tc.name.c_str(), cosO, mc.mean[0], mc.mean[1], mc.mean[2], mc.stdError[0], quad[0] + delta,
                    quad[1] + delta, quad[2] + delta, pdfIntegral, mc.nonDeltaFraction);
    }
}

// Test 3: reciprocity f(wo, wi) == f(wi, wo), and no reflection into the lower hemisphere.
TEST_P(BsdfAgreement, EvalIsReciprocal) { expectReciprocal(*GetParam().material, GetParam().inputs()); }

// Test 5: a non-delta sample's pdf is pdf(wo, wi) and its weight is eval |cos| / pdf (only the
// smooth coat is delta here).
TEST_P(BsdfAgreement, SampleAgreesWithPdfAndEval) {
    expectSamplesAgreeWithPdfAndEval(*GetParam().material, GetParam().inputs());
}

INSTANTIATE_TEST_SUITE_P(Materials, BsdfAgreement, testing::ValuesIn(nonDeltaCases()),
                         [](const testing::TestParamInfo<Case>& info) { return info.param.name; });

// Test 2: analytic albedos of the mirror and the smooth limit of the conductor.
TEST(Bsdf, MirrorReflectsWithItsReflectance) {
    Color r(0.9f, 0.5f, 0.2f);
    auto m = makeMirror(r);
    EXPECT_TRUE(m->isDeltaOnly());
    for (float cosO : kCosines) {
        Vec3 wo = direction(cosO);
        auto s = m->sample(wo, 0.5f, {0.5f, 0.5f}, tinted(r), TransportMode::Radiance);
        ASSERT_TRUE(s);
        EXPECT_TRUE(s->delta);
        EXPECT_EQ(s->weight, r);
        EXPECT_EQ(s->wi, Vec3(-wo.x, -wo.y, wo.z));
        EXPECT_TRUE(isBlack(m->eval(wo, s->wi, tinted(r), TransportMode::Radiance)));
        EXPECT_EQ(m->pdf(wo, s->wi, tinted(r)), 0.0f);
    }
}

TEST(Bsdf, ConductorSmoothLimitIsSchlick) {
    Color f0(1.0f, 0.78f, 0.34f);
    auto smooth = makeConductor(f0, 0.0f);
    auto nearlySmooth = makeConductor(f0, 0.02f);  // alpha 4e-4: still the microfacet path
    EXPECT_EQ(smooth->lobes(), unsigned(kDeltaLobe));
    EXPECT_EQ(nearlySmooth->lobes(), unsigned(kGlossyLobe));
    for (float cosO : kCosines) {
        SCOPED_TRACE("cos(theta_o) = " + std::to_string(cosO));
        Vec3 wo = direction(cosO);
        Color schlick = fresnelSchlick(f0, cosO);
        auto s = smooth->sample(wo, 0.5f, {0.3f, 0.6f}, tinted(f0), TransportMode::Radiance);
        ASSERT_TRUE(s && s->delta);
        EXPECT_EQ(s->weight, schlick);
        auto mc = estimateBySampling(*nearlySmooth, wo, tinted(f0), TransportMode::Radiance, 3);
        for (int c = 0; c < 3; ++c) EXPECT_NEAR(mc.mean[c], schlick[c], tolerance(schlick[c]));
        std::printf("  Conductor r=0.02 cos %.2f  MC %.4f %.4f %.4f  Schlick %.4f %.4f %.4f\n", cosO, mc.mean[0],
                    mc.mean[1], mc.mean[2], schlick.x, schlick.y, schlick.z);
    }
}

// Fresnel against closed forms: normal incidence ((n-1)/(n+1))^2, Brewster's angle (the
// p-polarised part vanishes), Stokes symmetry across the boundary and the TIR cut-off.
TEST(Bsdf, DielectricFresnelMatchesClosedForms) {
    float n = kIor;
    EXPECT_NEAR(fresnelDielectric(1.0f, n), (n - 1) * (n - 1) / ((n + 1) * (n + 1)), 1e-6f);
    float cosBrewster = 1.0f / std::sqrt(1.0f + n * n);
    float rs = (n * n - 1) / (n * n + 1);
    EXPECT_NEAR(fresnelDielectric(cosBrewster, n), 0.5f * rs * rs, 1e-5f);
    float cosI = 0.5f, sinT = std::sqrt(1 - cosI * cosI) / n;
    EXPECT_NEAR(fresnelDielectric(cosI, n), fresnelDielectric(-std::sqrt(1 - sinT * sinT), n), 1e-5f);
    float cosCritical = std::sqrt(1 - 1 / (n * n));
    EXPECT_EQ(fresnelDielectric(-(cosCritical - 1e-3f), n), 1.0f);
    EXPECT_LT(fresnelDielectric(-(cosCritical + 1e-3f), n), 1.0f);
}

// Tests 1, 2 and 4 for glass from both sides: Importance weights are exactly 1 (R + T = 1),
// reflection is chosen with probability F, Radiance scales refraction by (n_o / n_i)^2,
// and refracted directions obey Snell's law.
TEST(Bsdf, DielectricSplitsByFresnel) {
    auto m = makeDielectric(kIor);
    EXPECT_TRUE(m->isDeltaOnly());
    for (float side : {1.0f, -1.0f}) {
        for (float cosO : kCosines) {
            SCOPED_TRACE("cos(theta_o) = " + std::to_string(side * cosO));
            Vec3 wo = direction(side * cosO);
            float F = fresnelDielectric(wo.z, kIor);
            float nO = side > 0 ? 1.0f : kIor, nI = side > 0 ? kIor : 1.0f;
            Rng rng(5, 0, 0, StreamPurpose::Test);
            int reflected = 0;
            double radianceSum = 0;
            for (int i = 0; i < kSamples; ++i) {
                float uLobe = rng.uniform();
                auto imp = m->sample(wo, uLobe, {0.5f, 0.5f}, tinted(kWhite), TransportMode::Importance);
                auto rad = m->sample(wo, uLobe, {0.5f, 0.5f}, tinted(kWhite), TransportMode::Radiance);
                ASSERT_TRUE(imp && rad && imp->delta);
                ASSERT_EQ(imp->weight, kWhite);
                bool isReflection = imp->wi.z * wo.z > 0;
                reflected += isReflection;
                radianceSum += rad->weight.x;
                if (isReflection) continue;
                float sinO = std::sqrt(1 - wo.z * wo.z), sinI = std::sqrt(1 - imp->wi.z * imp->wi.z);
                ASSERT_NEAR(nO * sinO, nI * sinI, 1e-5f);
                ASSERT_LT(dot(Vec3(wo.x, wo.y, 0), Vec3(imp->wi.x, imp->wi.y, 0)), 0.0f);
                ASSERT_NEAR(imp->pdf, 1 - F, 1e-6f);
            }
            double share = double(reflected) / kSamples, stdErr = std::sqrt(F * (1 - F) / kSamples);
            EXPECT_NEAR(share, F, std::max(4 * stdErr, 1e-6));
            double expectedRadiance = F + (1 - F) * (nO * nO) / (nI * nI);
            EXPECT_NEAR(radianceSum / kSamples, expectedRadiance, tolerance(expectedRadiance));
            std::printf("  Dielectric cos %+.2f  F %.4f  reflected share %.4f (se %.4f)  radiance mean %.4f vs %.4f\n",
                        wo.z, F, share, stdErr, radianceSum / kSamples, expectedRadiance);
        }
    }
}

// Robustness: any direction (grazing, below the surface, along the normal) and any
// random numbers (including 0) give finite, non-negative values and unit directions;
// reflection-only materials sample nothing for wo below the surface.
TEST(Bsdf, FiniteForAllInputs) {
    MaterialPtr glass = makeDielectric(kIor);  // the only material that transmits
    std::vector<MaterialPtr> all = {makeDiffuse(kWhite), makeMirror(kWhite), glass, makeConductor(kWhite, 0),
                                    makeConductor(kWhite, 0.01f), makeConductor(kWhite, 0.7f),
                                    makePlastic(kWhite, kIor, 0), makePlastic(kWhite, kIor, 0.01f),
                                    makePlastic(kWhite, kIor, 0.5f), makeCoatedDiffuse(kWhite, kIor, 0),
                                    makeCoatedDiffuse(kWhite, kIor, 0.01f), makeCoatedDiffuse(kWhite, kIor, 0.5f)};
    Rng rng(13, 0, 0, StreamPurpose::Test);
    auto draw = [&] { return rng.uniform() < 0.05f ? 0.0f : rng.uniform(); };
    for (const MaterialPtr& m : all) {
        for (int i = 0; i < 20000; ++i) {
            float cosO = i % 7 == 0 ? 1e-4f * (rng.uniform() - 0.5f) : 2 * rng.uniform() - 1;
            Vec3 wo = i % 11 == 0 ? Vec3(0, 0, 1) : direction(cosO, 2 * kPi * rng.uniform());
            Vec3 wi = sampleUniformSphere({rng.uniform(), rng.uniform()});
            Color f = m->eval(wo, wi, tinted(kWhite), TransportMode::Radiance);
            float p = m->pdf(wo, wi, tinted(kWhite));
            ASSERT_TRUE(isFinite(f) && minComponent(f) >= 0 && std::isfinite(p) && p >= 0) << "wo.z " << wo.z;
            auto s = m->sample(wo, draw(), {draw(), draw()}, tinted(kWhite), TransportMode::Radiance);
            if (wo.z <= 0 && m != glass) {
                ASSERT_FALSE(s) << "sample below a reflector";
            }
            if (!s) continue;
            ASSERT_TRUE(isFinite(s->weight) && minComponent(s->weight) >= 0) << "wo.z " << wo.z;
            ASSERT_TRUE(std::isfinite(s->pdf) && s->pdf > 0) << "wo.z " << wo.z;
            ASSERT_NEAR(length(s->wi), 1.0f, 1e-4f);
        }
    }
}

}  // namespace
}  // namespace photon
