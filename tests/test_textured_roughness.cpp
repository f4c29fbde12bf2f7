// Coated materials and dielectrics with a roughness map (materials/textured_roughness.cpp): exact at the
// precomputed levels, a consistent BSDF between them (sampling against quadrature, pdf and
// weight, reciprocity, the white furnace), close to the material at that roughness, and
// the scene format's "roughness" texture and "remap_roughness".
#include <gtest/gtest.h>
#include <cmath>
#include <cstdio>
#include "bsdf_checks.h"
#include "materials/fresnel.h"
#include "materials/material.h"
#include "materials/microfacet.h"
#include "scene_loader_fixture.h"
#include "test_support.h"
#include "texture/image_texture.h"

namespace photon {
namespace {

using namespace bsdf_checks;
constexpr float kIor = 1.5f;
const Color kWhite(1.0f), kColour(0.8f, 0.3f, 0.05f);
MaterialInputs tinted(Color tint) { return {{Vec2{0.3f, 0.6f}}, tint}; }

// A roughness map that reads `r` everywhere (one texel).
FloatParam uniformMap(float r) { return FloatParam(std::make_shared<ImageTexture>(1, 1, std::vector<Color>{Color(r)})); }

MaterialPtr mapped(Color albedo, float r, float exponent = 1) {
    static const auto levels = makeRoughnessLevels([](float level) { return makeCoatedDiffuse(Color(0.5f), kIor, level); });
    return makeTexturedRoughness(albedo, uniformMap(r), exponent, levels);
}

// On a level (0.01, the first above the smooth one) the map gives that level's material
// exactly; a map read with pbrt's remaproughness off (exponent 1/2) turns 0.0001 into 0.01.
TEST(TexturedRoughness, OnALevelIsThatMaterial) {
    const Vec3 wo = direction(0.6f), wi = direction(0.8f, 2.5f);
    const MaterialPtr exact = makeCoatedDiffuse(kColour, kIor, 0.01f);
    for (const MaterialPtr& m : {mapped(kColour, 0.01f), mapped(kColour, 0.0001f, 0.5f)}) {
        const Color a = m->eval(wo, wi, tinted(kColour), TransportMode::Radiance);
        const Color b = exact->eval(wo, wi, tinted(kColour), TransportMode::Radiance);
        for (int c = 0; c < 3; ++c) EXPECT_NEAR(a[c], b[c], 1e-4f * b[c]);
        EXPECT_NEAR(m->pdf(wo, wi, tinted(kColour)), exact->pdf(wo, wi, tinted(kColour)), 1e-4f * exact->pdf(wo, wi, tinted(kColour)));
    }
}

// Between levels (0.3; 0.005, halfway from the smooth coat to 0.01):
// the mean sample weight is the quadrature of eval cos (plus the smooth level's mirror in
// its share), pdf() integrates to the non-delta draws, a white base keeps everything,
// and eval is reciprocal and agrees with sample()'s weights and pdf.
TEST(TexturedRoughness, BetweenLevelsIsAConsistentBsdf) {
    for (float r : {0.3f, 0.005f}) {
        for (Color albedo : {kWhite, kColour}) {
            SCOPED_TRACE("roughness " + std::to_string(r) + (albedo == kWhite ? ", white" : ", colour"));
            const MaterialPtr m = mapped(albedo, r);
            for (float cosO : {0.1f, 0.5f, 0.95f}) {
                const Vec3 wo = direction(cosO);
                const auto mc = estimateBySampling(*m, wo, tinted(albedo), TransportMode::Radiance, uint64_t(cosO * 100));
                const float width = roughnessToAlpha(std::max(r * 0.8f, 0.01f));
                const Channels quad = integrateHemisphere(wo, width, [&](Vec3 wi) {
                    return m->eval(wo, wi, tinted(albedo), TransportMode::Radiance) * wi.z;
                });
                const double pdfIntegral =
                    integrateHemisphere(wo, width, [&](Vec3 wi) { return Color(m->pdf(wo, wi, tinted(albedo))); })[0];
                // The smooth level's mirror carries F(cos) in its share 1 - t.
                const double mirror = r < 0.01f ? (1.0 - r / 0.01f) * fresnelDielectric(cosO, kIor) : 0.0;
                for (int c = 0; c < 3; ++c) {
                    const double expected = quad[c] + mirror;
                    EXPECT_NEAR(mc.mean[c], expected, tolerance(expected)) << "cos " << cosO << ", channel " << c;
                    if (albedo == kWhite) EXPECT_NEAR(expected, 1.0, 0.006) << "white furnace, cos " << cosO;
                }
                EXPECT_NEAR(pdfIntegral, mc.nonDeltaFraction, 0.006) << "cos " << cosO;
            }
            expectReciprocal(*m, tinted(albedo));
            expectSamplesAgreeWithPdfAndEval(*m, tinted(albedo));
        }
    }
}

// A rough dielectric (index 1.5) with a roughness map reading 0.3: sampling's mean weight
// is the quadrature of eval |cos| over the sphere (reflection and refraction), and each
// sample's weight and pdf are eval |cos| / pdf and pdf().
TEST(TexturedRoughness, DielectricBetweenLevelsIsConsistent) {
    static const auto levels = makeRoughnessLevels([](float r) { return makeRoughDielectric(kIor, r); });
    const MaterialPtr m = makeTexturedRoughness(kWhite, uniformMap(0.3f), 1, levels);
    EXPECT_FALSE(m->twoSided());
    const MaterialInputs in = tinted(kWhite);
    Rng rng(5, 0, 0, StreamPurpose::Test);
    for (float cosO : {0.3f, 0.8f, -0.6f}) {
        SCOPED_TRACE("cos " + std::to_string(cosO));
        const Vec3 wo = direction(cosO);
        const auto mc = estimateBySampling(*m, wo, in, TransportMode::Importance, 17);
        const Channels quad = integrateSphere(wo.z > 0 ? wo : Vec3(wo.x, wo.y, -wo.z), roughnessToAlpha(0.25f), [&](Vec3 wi) {
            const Vec3 w = wo.z > 0 ? wi : Vec3(wi.x, wi.y, -wi.z);
            return m->eval(wo, w, in, TransportMode::Importance) * std::abs(w.z);
        });
        EXPECT_NEAR(mc.mean[0], quad[0], tolerance(quad[0]));
        for (int i = 0; i < 20000; ++i) {
            const float uLobe = rng.uniform();
            auto sample = m->sample(wo, uLobe, {rng.uniform(), rng.uniform()}, in, TransportMode::Radiance);
            if (!sample) continue;
            const float p = m->pdf(wo, sample->wi, in);
            ASSERT_NEAR(sample->pdf, p, 1e-4f * p);
            const Color f = m->eval(wo, sample->wi, in, TransportMode::Radiance) * (std::abs(sample->wi.z) / p);
            ASSERT_NEAR(sample->weight[0], f[0], 1e-4f * f[0] + 1e-7f);
        }
    }
}

// The blend against the material made at that roughness: albedo and lobe shape (binned
// by 200k samples each; L1 summed over bins, over the albedo). Measured at 0.05, 0.1 and
// 0.3, coloured base: albedos within 0.002, L1 at most 0.03 (the bins' own noise ~0.02).
TEST(TexturedRoughness, BlendIsCloseToTheMaterialAtThatRoughness) {
    for (float r : {0.05f, 0.1f, 0.3f}) {
        const MaterialPtr blend = mapped(kColour, r), exact = makeCoatedDiffuse(kColour, kIor, r);
        for (float cosO : {0.2f, 0.7f}) {
            const Vec3 wo = direction(cosO);
            const BinComparison cmp = compareBins(binBySampling(*blend, wo, tinted(kColour), 200000, 3),
                                                  binBySampling(*exact, wo, tinted(kColour), 200000, 4));
            std::printf("  roughness %.2f cos %.1f: albedo %.4f vs %.4f, L1 %.4f\n", r, cosO, cmp.model[0],
                        cmp.reference[0], cmp.l1[0]);
            for (int c = 0; c < 3; ++c) {
                EXPECT_NEAR(cmp.model[c], cmp.reference[c], 0.01 * cmp.reference[c] + 0.002);
                EXPECT_LT(cmp.l1[c], 0.04) << "roughness " << r << ", cos " << cosO << ", channel " << c;
            }
        }
    }
}

// The Cornell box with its blocks in a coated colour whose roughness map reads 0.15 (between
// levels): SPPM (its camera paths choosing between the levels' coats and bases) and the
// path tracer agree in the image mean within 2% per channel.
TEST(TexturedRoughness, SppmAgreesWithThePathTracer) {
    const test::PathAndSppmMeans means = test::renderPathAndSppm(test::cornellBoxWith(mapped(kColour, 0.15f), 32), 512, 256, 40000);
    std::printf("  path %.4f %.4f %.4f  sppm %.4f %.4f %.4f\n", means.path.x, means.path.y, means.path.z, means.sppm.x,
                means.sppm.y, means.sppm.z);
    for (int c = 0; c < 3; ++c) EXPECT_NEAR(means.sppm[c], means.path[c], 0.02f * means.path[c]) << "channel " << c;
}

// ---- the scene file ----

TEST(TexturedRoughnessScene, RoughnessTextureAndRemap) {
    // A texture for the roughness: a textured material; remap_roughness on a constant:
    // pbrt's meaning, 0.0625 with remap true being photon's 0.5.
    const Material& textured = test::loadedMaterial(
        {{"type", "coated_diffuse"}, {"albedo", {0.5, 0.5, 0.5}}, {"roughness", {{"texture", "textures/wood.png"}}}});
    EXPECT_TRUE(textured.textured());
    const Material& remapped = test::loadedMaterial(
        {{"type", "coated_diffuse"}, {"albedo", {0.5, 0.5, 0.5}}, {"roughness", 0.0625}, {"remap_roughness", true}});
    const MaterialPtr half = makeCoatedDiffuse(Color(0.5f), kIor, 0.5f);
    const Vec3 wo = direction(0.6f), wi = direction(0.8f, 2.5f);
    EXPECT_FLOAT_EQ(remapped.pdf(wo, wi, tinted(Color(0.5f))), half->pdf(wo, wi, tinted(Color(0.5f))));
    // A dielectric takes a roughness map too; a thin one, whose faces are smooth, none.
    EXPECT_TRUE(test::loadedMaterial({{"type", "dielectric"}, {"roughness", {{"texture", "textures/wood.png"}}}}).textured());
    test::expectError(
        [](Json& doc) { doc["materials"]["glass"] = {{"type", "dielectric"}, {"thin", true}, {"roughness", 0.2}}; },
        "materials.glass.roughness", "must be 0 for a thin dielectric (its faces are smooth)");
    test::expectError(
        [](Json& doc) { doc["materials"]["gloss"]["roughness"] = 1.5; }, "materials.gloss.roughness", "must be in [0, 1]");
}

}  // namespace
}  // namespace photon
