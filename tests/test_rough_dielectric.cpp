// Rough and thin dielectrics: sample() against eval()/pdf() by an independent quadrature of
// the whole sphere, from outside and inside, for relative indices above and below 1;
// generalised reciprocity; energy; the smooth limit; the thin slab's summed
// inter-reflections; and SPPM against the path tracer on a scene with rough glass.
#include <gtest/gtest.h>
#include <cmath>
#include <cstdio>
#include <ostream>
#include <string>
#include <vector>
#include <photon/render.h>
#include "integrators/integrator.h"
#include "materials/fresnel.h"
#include "materials/material.h"
#include "materials/microfacet.h"
#include "math/rng.h"
#include "math/sampling.h"
#include "scene/scene.h"
#include "scene/scene_loader.h"
#include "bsdf_checks.h"
#include "test_support.h"

namespace photon {
namespace {

using namespace bsdf_checks;
const Color kWhite(1.0f);
const MaterialInputs kInputs{{}, kWhite};  // these materials read no texture
constexpr float kGlass = 1.5f;
constexpr float kIceInWater = 1.31f / 1.33f;  // relative index below 1

// Index of refraction on the side of the surface w points to (outside: 1, inside: eta).
float indexOn(Vec3 w, float eta) { return w.z > 0 ? 1.0f : eta; }

// Where the smooth boundary would send wo: the mirror direction, and the refracted one (or,
// under total internal reflection, where the microfacets tilted enough to let light through
// send it: along the surface, onward and just past the horizon).
Vec3 mirrorOf(Vec3 wo) { return {-wo.x, -wo.y, wo.z}; }
Vec3 refractedOf(Vec3 wo, float eta) {
    auto r = refract(wo, Vec3(0, 0, 1), eta);
    return r ? r->wt : normalize(Vec3(-wo.x, -wo.y, wo.z > 0 ? -0.01f : 0.01f));
}

// The mean direction of the material's samples on one side (reflected or transmitted), or
// `fallback` if it sends none there: the axis about which integrateSphere is finest. A
// rough lobe need not be centred on the smooth direction (with eta near 1 the transmitted
// one lies near -wo); this only decides where the quadrature looks closest, not what it
// adds up, which stays eval over the whole sphere.
Vec3 lobeAxis(const Material& m, Vec3 wo, bool reflected, Vec3 fallback) {
    Rng rng(3, 0, 0, StreamPurpose::Test);
    Vec3 sum(0.0f);
    for (int i = 0; i < 4096; ++i) {
        auto s = m.sample(wo, rng.uniform(), {rng.uniform(), rng.uniform()}, kInputs, TransportMode::Radiance);
        if (s && (s->wi.z * wo.z > 0) == reflected) sum += s->wi;
    }
    return lengthSquared(sum) > 0 ? normalize(sum) : fallback;
}

struct RoughCase {
    std::string name;
    float roughness;
    float eta;
};
void PrintTo(const RoughCase& c, std::ostream* os) { *os << c.name; }

std::vector<RoughCase> roughCases() {
    return {{"Glass01", 0.1f, kGlass},      {"Glass03", 0.3f, kGlass},      {"Glass07", 0.7f, kGlass},
            {"IceWater01", 0.1f, kIceInWater}, {"IceWater03", 0.3f, kIceInWater}, {"IceWater07", 0.7f, kIceInWater}};
}

class RoughDielectricAgreement : public testing::TestWithParam<RoughCase> {};

// The mean sample weight equals the quadrature of eval |cos| over the whole sphere
// (reflection and transmission), in both transport modes; pdf() integrates to the share of
// draws that return a direction (so <= 1); and no energy is gained in Importance mode,
// whose albedo is the fraction of a photon's power that survives the bounce.
TEST_P(RoughDielectricAgreement, SamplingMatchesQuadratureOfEval) {
    const RoughCase& tc = GetParam();
    MaterialPtr m = makeRoughDielectric(tc.eta, tc.roughness);
    ASSERT_EQ(m->lobes(), unsigned(kGlossyLobe));
    ASSERT_FALSE(m->twoSided());
    for (float side : {1.0f, -1.0f})
        for (float cosO : kCosines) {
            Vec3 wo = direction(side * cosO);
            SCOPED_TRACE("cos(theta_o) = " + std::to_string(wo.z));
            const uint64_t seed = uint64_t(cosO * 1000) + 17;  // the same draws in both modes
            auto radiance = estimateBySampling(*m, wo, kInputs, TransportMode::Radiance, seed);
            auto importance = estimateBySampling(*m, wo, kInputs, TransportMode::Importance, seed);
            // Channels: eval |cos| in Radiance mode, in Importance mode, and pdf; each
            // hemisphere about its own peak.
            auto integrand = [&](bool reflected) {
                return [&, reflected](Vec3 wi) {
                    if ((wi.z * wo.z > 0) != reflected) return Color(0.0f);
                    float cosI = std::abs(wi.z);
                    return Color(m->eval(wo, wi, kInputs, TransportMode::Radiance).x * cosI,
                                 m->eval(wo, wi, kInputs, TransportMode::Importance).x * cosI,
                                 m->pdf(wo, wi, kInputs));
                };
            };
            Channels r = integrateSphere(lobeAxis(*m, wo, true, mirrorOf(wo)), integrand(true));
            Channels t = integrateSphere(lobeAxis(*m, wo, false, refractedOf(wo, tc.eta)), integrand(false));
            double quadRadiance = r[0] + t[0], quadImportance = r[1] + t[1], pdfIntegral = r[2] + t[2];
            EXPECT_NEAR(radiance.mean[0], quadRadiance, tolerance(quadRadiance)) << "se " << radiance.stdError[0];
            EXPECT_NEAR(importance.mean[0], quadImportance, tolerance(quadImportance))
                << "se " << importance.stdError[0];
            EXPECT_LE(importance.mean[0], 1.0 + tolerance(1.0));
            EXPECT_LE(pdfIntegral, 1.0 + 0.005);
            EXPECT_NEAR(pdfIntegral, radiance.nonDeltaFraction, 0.005);
            EXPECT_EQ(radiance.nonDeltaFraction, importance.nonDeltaFraction);
            std::printf("  %-11s cos %+.2f  radiance MC %.4f quad %.4f (R %.4f T %.4f)  importance MC %.4f quad %.4f"
                        "  int pdf %.4f  returned %.4f\n",
                        tc.name.c_str(), wo.z, radiance.mean[0], quadRadiance, r[0], t[0], importance.mean[0],
                        quadImportance, pdfIntegral, radiance.nonDeltaFraction);
        }
}

// A sample's pdf is pdf(wo, wi), its weight eval |cos| / pdf, and it is not a delta.
TEST_P(RoughDielectricAgreement, SampleAgreesWithPdfAndEval) {
    const RoughCase& tc = GetParam();
    MaterialPtr m = makeRoughDielectric(tc.eta, tc.roughness);
    Rng rng(11, 0, 0, StreamPurpose::Test);
    int reflected = 0, transmitted = 0;
    for (float side : {1.0f, -1.0f})
        for (float cosO : kCosines) {
            Vec3 wo = direction(side * cosO, 2.1f);
            for (TransportMode mode : {TransportMode::Radiance, TransportMode::Importance})
                for (int i = 0; i < 10000; ++i) {
                    auto s = m->sample(wo, rng.uniform(), {rng.uniform(), rng.uniform()}, kInputs, mode);
                    if (!s) continue;
                    (s->wi.z * wo.z > 0 ? reflected : transmitted)++;
                    ASSERT_FALSE(s->delta);
                    ASSERT_EQ(s->lobeProbability, 1.0f);
                    ASSERT_NEAR(length(s->wi), 1.0f, 1e-4f);
                    float p = m->pdf(wo, s->wi, kInputs);
                    ASSERT_GT(s->pdf, 0.0f);
                    ASSERT_NEAR(s->pdf, p, 1e-4f * p);
                    float expected = m->eval(wo, s->wi, kInputs, mode).x * std::abs(s->wi.z) / p;
                    ASSERT_NEAR(s->weight.x, expected, 1e-4f * expected + 1e-7f);
                }
        }
    EXPECT_GT(reflected, 0);
    EXPECT_GT(transmitted, 0);
}

// Generalised reciprocity (Veach 1997, eq. 5.14, f_s(wi -> wo) / n_o^2 = f_s(wo -> wi) /
// n_i^2 with light flowing from wi to wo), in this interface's arguments:
//   eval(wo, wi) / n(wo)^2 == eval(wi, wo) / n(wi)^2   (Radiance mode),
// n(w) the index on w's side; for reflection both indices are the same, so f is symmetric.
// And Importance mode is the adjoint: eval_importance(wo, wi) == eval_radiance(wi, wo).
TEST_P(RoughDielectricAgreement, EvalObeysGeneralisedReciprocity) {
    const RoughCase& tc = GetParam();
    MaterialPtr m = makeRoughDielectric(tc.eta, tc.roughness);
    Rng rng(7, 0, 0, StreamPurpose::Test);
    int transmissions = 0;
    for (int i = 0; i < 20000; ++i) {
        Vec3 a = sampleUniformSphere({rng.uniform(), rng.uniform()});
        // b near where a's light would go, so that narrow lobes are exercised too.
        auto s = m->sample(a, rng.uniform(), {rng.uniform(), rng.uniform()}, kInputs, TransportMode::Radiance);
        Vec3 b = s && i % 2 ? s->wi : sampleUniformSphere({rng.uniform(), rng.uniform()});
        float fab = m->eval(a, b, kInputs, TransportMode::Radiance).x;
        float fba = m->eval(b, a, kInputs, TransportMode::Radiance).x;
        float na = indexOn(a, tc.eta), nb = indexOn(b, tc.eta);
        transmissions += a.z * b.z < 0 && fab > 0;
        float lhs = fab / (na * na), rhs = fba / (nb * nb);
        ASSERT_NEAR(lhs, rhs, 1e-3f * std::max(lhs, rhs) + 1e-9f) << "pair " << i << " a.z " << a.z << " b.z " << b.z;
        float adjoint = m->eval(a, b, kInputs, TransportMode::Importance).x;
        ASSERT_NEAR(adjoint, fba, 1e-3f * std::max(adjoint, fba) + 1e-9f) << "pair " << i;
    }
    EXPECT_GT(transmissions, 1000);
}

INSTANTIATE_TEST_SUITE_P(Materials, RoughDielectricAgreement, testing::ValuesIn(roughCases()),
                         [](const testing::TestParamInfo<RoughCase>& info) { return info.param.name; });

// What single scattering off GGX microfacets keeps of a photon arriving along wo
// (Importance mode), computed over microfacet normals from the microfacet model alone, not
// from eval() or pdf(): a facet h is seen with density D_wo(h) = G1(wo) |wo.h| D(h) / |wo.z|;
// it reflects F(wo.h) of the light, and refracts the rest unless `reflectOnly` (a mirror
// facet, F = 1); light leaving toward wi survives masking with probability G2(wo, wi) /
// G1(wo) and is lost if it leaves on the wrong side of the surface.
double singleScatteringAlbedo(float roughness, float eta, Vec3 wo, bool reflectOnly) {
    GGX ggx{roughnessToAlpha(roughness)};
    float side = wo.z > 0 ? 1.0f : -1.0f;
    Channels e = integrateSphere(Vec3(0, 0, 1), [&](Vec3 h) {
        float woDotH = dot(wo, h);
        if (h.z <= 0 || side * woDotH <= 0) return Color(0.0f);
        float seen = std::abs(woDotH) * ggx.D(h) / std::abs(wo.z);  // D_wo(h) / G1(wo)
        float F = reflectOnly ? 1.0f : fresnelDielectric(woDotH, eta);
        Vec3 r = reflect(wo, h);
        float kept = r.z * side > 0 ? F * ggx.G2(wo, r) : 0.0f;
        auto t = refract(wo, h, eta);
        if (F < 1 && t && t->wt.z * side < 0) kept += (1 - F) * ggx.G2(wo, t->wt);
        return Color(seen * kept);
    });
    return e[0];
}

// White furnace in Importance mode (the fraction of a photon's power a bounce keeps): never
// above 1 from either side, and the loss is only what single scattering loses, equal to
// singleScatteringAlbedo's; the same computation with mirror facets gives the conductor's
// albedo with F = 1 at the same roughness. The loss grows with roughness and toward
// grazing incidence: below 3.5% for roughness <= 0.3 at |cos| >= 0.5, below 50% even at
// roughness 0.7 and grazing ice-in-water; a nearly smooth surface keeps everything.
TEST(RoughDielectric, WhiteFurnaceLosesOnlySingleScatteringEnergy) {
    for (float roughness : {0.02f, 0.3f, 0.7f}) {
        MaterialPtr conductor = makeConductor(kWhite, roughness);
        for (float cosO : kCosines) {
            double expected = singleScatteringAlbedo(roughness, kGlass, direction(cosO), true);
            auto c = estimateBySampling(*conductor, direction(cosO), kInputs, TransportMode::Importance, 29);
            EXPECT_NEAR(c.mean[0], expected, tolerance(expected)) << "conductor, roughness " << roughness;
        }
        for (float eta : {kGlass, kIceInWater})
            for (float side : {1.0f, -1.0f})
                for (float cosO : kCosines) {
                    Vec3 wo = direction(side * cosO);
                    SCOPED_TRACE("roughness " + std::to_string(roughness) + " eta " + std::to_string(eta) +
                                 " cos(theta_o) " + std::to_string(wo.z));
                    MaterialPtr m = makeRoughDielectric(eta, roughness);
                    auto e = estimateBySampling(*m, wo, kInputs, TransportMode::Importance, 23);
                    double expected = singleScatteringAlbedo(roughness, eta, wo, false), loss = 1.0 - e.mean[0];
                    EXPECT_NEAR(e.mean[0], expected, tolerance(expected)) << "se " << e.stdError[0];
                    EXPECT_LE(e.mean[0], 1.0 + 3 * e.stdError[0]);
                    EXPECT_LT(loss, 0.5);
                    if (roughness <= 0.3f && cosO >= 0.5f) {
                        EXPECT_LT(loss, 0.035);
                    }
                    if (roughness < 0.05f) {
                        EXPECT_NEAR(e.mean[0], 1.0, 0.005);
                    }
                    std::printf("  roughness %.2f eta %.3f cos %+.2f  albedo %.4f (se %.4f)  single scattering %.4f"
                                "  loss %.4f\n",
                                roughness, eta, wo.z, e.mean[0], e.stdError[0], expected, loss);
                }
    }
}

// As roughness -> 0 the rough boundary becomes the smooth one: roughness 0 is the smooth
// dielectric itself, and at roughness 0.02 (alpha 4e-4, still microfacets) reflection is
// chosen with the smooth boundary's Fresnel F(cos_o), refracted radiance is scaled by
// (n_o / n_i)^2 so the mean radiance weight is F + (1 - F)(n_o / n_i)^2, and the directions
// are the mirror and Snell ones.
TEST(RoughDielectric, SmoothLimitMatchesSmoothDielectricFresnelSplit) {
    for (float eta : {kGlass, kIceInWater}) {
        MaterialPtr smooth = makeRoughDielectric(eta, 0.0f);
        ASSERT_TRUE(smooth->isDeltaOnly());
        ASSERT_TRUE(smooth->smoothSpecular());
        EXPECT_EQ(smooth->smoothSpecular()->ior, eta);
        MaterialPtr m = makeRoughDielectric(eta, 0.02f);
        ASSERT_EQ(m->lobes(), unsigned(kGlossyLobe));
        for (float side : {1.0f, -1.0f})
            for (float cosO : kCosines) {
                Vec3 wo = direction(side * cosO);
                SCOPED_TRACE("eta " + std::to_string(eta) + " cos(theta_o) " + std::to_string(wo.z));
                float F = fresnelDielectric(wo.z, eta);
                float nO = indexOn(wo, eta), nI = indexOn(-wo, eta);
                Vec3 mirror = mirrorOf(wo), refracted = refractedOf(wo, eta);
                Rng rng(5, 0, 0, StreamPurpose::Test);
                int reflected = 0, returned = 0, offPeak = 0;
                double radianceSum = 0, importanceSum = 0;
                for (int i = 0; i < kSamples; ++i) {
                    float uLobe = rng.uniform();
                    Vec2 u{rng.uniform(), rng.uniform()};
                    auto rad = m->sample(wo, uLobe, u, kInputs, TransportMode::Radiance);
                    auto imp = m->sample(wo, uLobe, u, kInputs, TransportMode::Importance);
                    if (!rad) continue;
                    ++returned;
                    bool isReflection = rad->wi.z * wo.z > 0;
                    reflected += isReflection;
                    radianceSum += rad->weight.x;
                    importanceSum += imp->weight.x;
                    offPeak += dot(rad->wi, isReflection ? mirror : refracted) < 0.9999f;  // 0.8 degrees
                }
                EXPECT_LT(offPeak, returned / 100);  // GGX's long tails, nothing more
                double share = double(reflected) / returned, stdErr = std::sqrt(F * (1 - F) / kSamples);
                EXPECT_NEAR(share, F, 4 * stdErr + 0.002);
                double expectedRadiance = F + (1 - F) * (nO * nO) / (nI * nI);
                EXPECT_NEAR(radianceSum / kSamples, expectedRadiance, 0.005 * expectedRadiance);
                EXPECT_NEAR(importanceSum / kSamples, 1.0, 0.005);
                std::printf("  eta %.3f cos %+.2f  F %.4f reflected share %.4f  radiance %.4f vs %.4f"
                            "  importance %.4f\n",
                            eta, wo.z, F, share, radianceSum / kSamples, expectedRadiance, importanceSum / kSamples);
            }
    }
}

// Any direction and any random numbers give finite, non-negative values and unit directions.
TEST(RoughDielectric, FiniteForAllInputs) {
    std::vector<MaterialPtr> all = {makeRoughDielectric(kGlass, 0.02f), makeRoughDielectric(kGlass, 1.0f),
                                    makeRoughDielectric(kIceInWater, 0.3f), makeRoughDielectric(3.0f, 0.5f),
                                    makeThinDielectric(kGlass), makeThinDielectric(kIceInWater)};
    Rng rng(13, 0, 0, StreamPurpose::Test);
    auto draw = [&] { return rng.uniform() < 0.05f ? 0.0f : rng.uniform(); };
    for (const MaterialPtr& m : all)
        for (int i = 0; i < 20000; ++i) {
            float cosO = i % 7 == 0 ? 1e-4f * (rng.uniform() - 0.5f) : 2 * rng.uniform() - 1;
            Vec3 wo = i % 11 == 0 ? Vec3(0, 0, i % 22 ? 1.0f : -1.0f) : direction(cosO, 2 * kPi * rng.uniform());
            Vec3 wi = i % 13 == 0 ? -wo : sampleUniformSphere({rng.uniform(), rng.uniform()});
            for (TransportMode mode : {TransportMode::Radiance, TransportMode::Importance}) {
                Color f = m->eval(wo, wi, kInputs, mode);
                float p = m->pdf(wo, wi, kInputs);
                ASSERT_TRUE(isFinite(f) && minComponent(f) >= 0 && std::isfinite(p) && p >= 0) << "wo.z " << wo.z;
                auto s = m->sample(wo, draw(), {draw(), draw()}, kInputs, mode);
                if (!s) continue;
                ASSERT_TRUE(isFinite(s->weight) && minComponent(s->weight) >= 0) << "wo.z " << wo.z;
                ASSERT_TRUE(std::isfinite(s->pdf) && s->pdf > 0) << "wo.z " << wo.z;
                ASSERT_NEAR(length(s->wi), 1.0f, 1e-4f);
            }
        }
}

// The thin slab's reflectance, summed term by term: R, then T R T, T R^3 T, ... (each
// further term two more bounces inside), independently of the closed form in the material.
double slabReflectanceBySeries(float cosO, float eta) {
    double R = fresnelDielectric(cosO, eta), T = 1 - R, sum = R, term = T * T * R;
    for (int k = 0; k < 200 && R < 1; ++k, term *= R * R) sum += term;
    return R < 1 ? sum : 1.0;
}

// R' + T' = 1; R' at normal incidence for eta 1.5 is 2 R0 / (1 + R0) = 0.0769 with
// R0 = 0.04; reflection is the mirror direction and transmission straight through, both
// delta, weight 1 in both modes; both sides alike.
TEST(ThinDielectric, SlabSumsInterReflections) {
    MaterialPtr m = makeThinDielectric(kGlass);
    EXPECT_TRUE(m->isDeltaOnly());
    EXPECT_TRUE(m->twoSided());
    EXPECT_FALSE(m->smoothSpecular());  // not a single refracting boundary
    auto reflection = m->sample(Vec3(0, 0, 1), 0.0f, {0.5f, 0.5f}, kInputs, TransportMode::Radiance);
    ASSERT_TRUE(reflection && reflection->delta);
    EXPECT_NEAR(fresnelDielectric(1.0f, kGlass), 0.04f, 1e-6f);
    EXPECT_NEAR(reflection->pdf, 2 * 0.04 / 1.04, 1e-5);
    EXPECT_NEAR(reflection->pdf, 0.0769, 1e-4);
    for (float eta : {kGlass, kIceInWater, 2.4f})
        for (float side : {1.0f, -1.0f})
            for (float cosO : {0.05f, 0.1f, 0.5f, 0.95f, 1.0f}) {
                Vec3 wo = direction(side * cosO);
                SCOPED_TRACE("eta " + std::to_string(eta) + " cos(theta_o) " + std::to_string(wo.z));
                MaterialPtr slab = makeThinDielectric(eta);
                for (TransportMode mode : {TransportMode::Radiance, TransportMode::Importance}) {
                    auto r = slab->sample(wo, 0.0f, {0.5f, 0.5f}, kInputs, mode);
                    auto t = slab->sample(wo, std::nextafter(1.0f, 0.0f), {0.5f, 0.5f}, kInputs, mode);
                    ASSERT_TRUE(r && t && r->delta && t->delta);
                    EXPECT_EQ(r->weight, kWhite);
                    EXPECT_EQ(r->wi, mirrorOf(wo));
                    double expectedR = slabReflectanceBySeries(cosO, eta);
                    EXPECT_NEAR(r->pdf, expectedR, 1e-5);
                    if (expectedR < 1) {
                        EXPECT_EQ(t->weight, kWhite);
                        EXPECT_EQ(t->wi, -wo);
                        EXPECT_NEAR(r->pdf + t->pdf, 1.0f, 1e-6f);  // R' + T' = 1
                    }
                }
            }
}

// SPPM against the path tracer on the example scene with a rough glass sphere and a thin
// pane in a Cornell box: camera paths go through the glossy glass by sampling, photons
// through it one by one. Image means agree within 2%.
Image renderRoughGlass(IntegratorKind kind, int passes, int64_t photons) {
    SceneDescription d = test::exampleScene("rough-glass", 32, passes, photons, 3);
    d.render.integrator = kind;
    d.render.maxDepth = 32;
    return test::renderImage(std::move(d));
}

TEST(RoughDielectricSppmVsPath, ImageMeansAgree) {
    Image path = renderRoughGlass(IntegratorKind::Path, 1024, 0);
    Image sppm = renderRoughGlass(IntegratorKind::Sppm, 100, 50000);
    Color pathMean = test::meanOver(path, 0, 0, 32, 32);
    Color sppmMean = test::meanOver(sppm, 0, 0, 32, 32);
    for (int c = 0; c < 3; ++c) EXPECT_NEAR(sppmMean[c], pathMean[c], 0.02f * pathMean[c]) << "channel " << c;
    std::printf("  path %.4f %.4f %.4f  sppm %.4f %.4f %.4f\n", pathMean.x, pathMean.y, pathMean.z, sppmMean.x,
                sppmMean.y, sppmMean.z);
}

}  // namespace
}  // namespace photon
