// coated_conductor: a metal under a clear coat. The white furnace (a perfect reflector under
// any coat keeps everything), sampling against quadrature, pdf and weight consistency,
// reciprocity, the brute-force layered random walk (albedo and lobe shape), the scene
// file's fields and errors.
#include <gtest/gtest.h>
#include <cmath>
#include <cstdio>
#include <ostream>
#include <string>
#include <vector>
#include "bsdf_checks.h"
#include "layered_random_walk.h"
#include "materials/fresnel.h"
#include "materials/material.h"
#include "materials/named_metals.h"
#include "scene_loader_fixture.h"
#include "test_support.h"

namespace photon::coated_conductor_tests {
namespace {

using namespace bsdf_checks;
constexpr float kIor = 1.5f;
const MaterialInputs kInputs{{}, Color(1.0f)};

// Gold as it is inside a coat of index 1.5: its index relative to the coat's.
ComplexIor goldInCoat() {
    const ComplexIor gold = *findMetal("Au");
    return {gold.eta / kIor, gold.k / kIor};
}

struct Layers {
    float coatRoughness, metalRoughness;
    bool perfect;  // a perfect reflector (Fresnel 1 at every angle) instead of gold
    std::string name;
    MaterialPtr metal() const {
        const float a = roughnessToAlpha(metalRoughness);
        if (perfect) return makeConductor(ColorParam(Color(1.0f)), GgxAlpha{a, a});
        return makeConductor(goldInCoat(), GgxAlpha{a, a});
    }
    MaterialPtr material() const { return makeCoatedConductor(metal(), kIor, coatRoughness); }
    // The narrowest glossy lobe, for the quadrature to resolve (the metal's seen through the
    // coat is wider than its own by about the coat's index).
    float width() const {
        float w = 1.0f;
        if (coatRoughness > 0) w = std::min(w, roughnessToAlpha(coatRoughness));
        if (metalRoughness > 0) w = std::min(w, roughnessToAlpha(metalRoughness));
        return w;
    }
};
void PrintTo(const Layers& l, std::ostream* os) { *os << l.name; }

std::vector<Layers> layers() {
    std::vector<Layers> all;
    for (float coat : {0.0f, 0.3f})
        for (float metal : {0.0f, 0.2f, 0.5f})
            for (bool perfect : {false, true}) {
                std::string name = "Coat" + std::to_string(int(std::lround(coat * 100))) + "Metal" +
                                   std::to_string(int(std::lround(metal * 100))) + (perfect ? "Perfect" : "Gold");
                all.push_back({coat, metal, perfect, name});
            }
    return all;
}

class CoatedConductorChecks : public testing::TestWithParam<Layers> {};

// The mean weight of sample()'s non-delta draws equals the quadrature of eval |cos| (1% or
// 0.005), and its delta draws' the mirror's reflectance: F(cos) for a smooth coat's, (1 -
// E)^2 R / (1 - E R) for a smooth metal's seen through the coat (E the coat's albedo, R the
// metal's Fresnel at the refracted angle), their sum for both smooth.
TEST_P(CoatedConductorChecks, SamplingMatchesQuadratureAndTheMirrors) {
    const Layers& l = GetParam();
    MaterialPtr m = l.material();
    MaterialPtr metal = l.metal();
    // The coat alone: over a black base its eval is the coat's GGX lobe.
    MaterialPtr coatOnly = makeCoatedDiffuse(Color(0.0f), kIor, l.coatRoughness);
    for (float cosO : {0.1f, 0.5f, 0.95f}) {
        SCOPED_TRACE("cos(theta_o) = " + std::to_string(cosO));
        const Vec3 wo = direction(cosO);
        Rng rng(uint64_t(cosO * 1000), 0, 0, StreamPurpose::Test);
        Channels glossy{}, delta{};
        for (int i = 0; i < kSamples; ++i) {
            const float uLobe = rng.uniform();
            auto s = m->sample(wo, uLobe, {rng.uniform(), rng.uniform()}, kInputs, TransportMode::Radiance);
            if (!s) continue;
            for (int c = 0; c < 3; ++c) (s->delta ? delta : glossy)[c] += double(s->weight[c]) / kSamples;
        }
        Channels quad = integrateHemisphere(wo, l.width(), [&](Vec3 wi) {
            return m->eval(wo, wi, kInputs, TransportMode::Radiance) * wi.z;
        });
        // The mirrors' reflectance: the coat's F (or, rough, no mirror) plus the metal's.
        Color mirrors(0.0f);
        const float E = l.coatRoughness > 0 ? 0.0f : fresnelDielectric(cosO, kIor);
        mirrors += Color(E);
        if (l.metalRoughness == 0) {
            // A rough coat's albedo from the coat over a black metal, by quadrature.
            float coatE = E;
            if (l.coatRoughness > 0) {
                Channels q = integrateHemisphere(wo, roughnessToAlpha(l.coatRoughness), [&](Vec3 wi) {
                    return coatOnly->eval(wo, wi, coatOnly->inputsAt({}), TransportMode::Radiance) * wi.z;
                });
                coatE = float(q[0]);
            }
            const float sinIn = std::sqrt(1.0f - cosO * cosO) / kIor;
            auto s = metal->sample(Vec3(sinIn, 0, std::sqrt(1 - sinIn * sinIn)), 0.5f, {0.5f, 0.5f}, kInputs,
                                   TransportMode::Radiance);
            ASSERT_TRUE(s && s->delta);
            const Color R = s->weight;
            mirrors += R * ((1 - coatE) * (1 - coatE)) / (Color(1.0f) - R * coatE);
        }
        for (int c = 0; c < 3; ++c) {
            EXPECT_NEAR(glossy[c], quad[c], tolerance(quad[c])) << "channel " << c;
            EXPECT_NEAR(delta[c], mirrors[c], tolerance(mirrors[c])) << "channel " << c;
        }
    }
}

// A perfect reflector (Fresnel 1 at every angle) under a coat keeps all the light at every
// angle when it is mirror-smooth: E + (1 - E)^2 / (1 - E) = 1, to float precision under a
// smooth coat, within the noise of the glossy coat's draws under a rough one. A rough one
// loses only what its single-scattering GGX lobe loses on each bounce: never more than 1.
TEST(CoatedConductor, PerfectReflectorUnderACoatKeepsTheLight) {
    for (float coat : {0.0f, 0.3f})
        for (float metal : {0.0f, 0.2f, 0.5f}) {
            const float a = roughnessToAlpha(metal);
            MaterialPtr m = makeCoatedConductor(makeConductor(ColorParam(Color(1.0f)), GgxAlpha{a, a}), kIor, coat);
            for (float cosO : {0.05f, 0.3f, 0.7f, 1.0f}) {
                SCOPED_TRACE("coat " + std::to_string(coat) + ", metal " + std::to_string(metal) + ", cos " +
                             std::to_string(cosO));
                auto mc = estimateBySampling(*m, direction(cosO), kInputs, TransportMode::Radiance, 3);
                if (metal == 0) {
                    EXPECT_NEAR(mc.mean[0], 1.0, coat == 0 ? 1e-5 : 0.01);
                } else {
                    EXPECT_LE(mc.mean[0], 1.0 + 3 * mc.stdError[0]);
                }
            }
        }
}

TEST_P(CoatedConductorChecks, EvalIsReciprocalAndReflectsOnly) { expectReciprocal(*GetParam().material(), kInputs); }

TEST_P(CoatedConductorChecks, SampleAgreesWithPdfAndEval) {
    expectSamplesAgreeWithPdfAndEval(*GetParam().material(), kInputs);
}

INSTANTIATE_TEST_SUITE_P(Layers, CoatedConductorChecks, testing::ValuesIn(layers()),
                         [](const testing::TestParamInfo<Layers>& info) { return info.param.name; });

// Against the layered random walk (tests/support/layered_random_walk.h: light enters the
// coat, reflects on the metal by the metal's own sampling, meets the coat from inside, and so
// on until it leaves; a rough coat walked on its microsurface), 250000 paths and 250000
// material samples per case, exit directions in 32 bins (4 rings of equal projected solid
// angle x 8 azimuth sectors); L1 = sum over the bins of |model - walk| / walk albedo. Measured
// at eta 1.5 and cos(theta_i) 0.2, 0.45, 0.9, gold and a perfect reflector:
//   smooth coat, smooth metal: albedo within 0.0002, L1 <= 0.001 (exact but for the noise).
//   smooth coat, metal roughness 0.2 / 0.5: albedo within 0.02 (the walk at construction
//     that finds the held-in light, 256 paths a node, is most of that); L1 up to 0.44 / 0.16 at
//     grazing light (0.06 at cos 0.9): the light the coat holds in comes out here in a broad
//     lobe, where the walk sends it on near the critical angle's cone, forward.
//   coat roughness 0.3 over roughness 0.3: albedo within 0.03, L1 <= 0.29.
//   coat roughness 0.3 over a mirror-smooth metal: a perfect reflector keeps its albedo
//     (within 0.0006), but gold comes out too bright, +0.21 at cos 0.2, +0.13 at 0.45, +0.01
//     at 0.9, and the reflection sharp where the walk's is blurred (L1 up to 1.42): the
//     model refracts through the coat's mean plane, where a rough coat's facets turn the light
//     and hold more of it in, to be absorbed by the metal on later bounces.
struct WalkCase {
    float coatRoughness, metalRoughness, cosO;
    bool perfect;  // a perfect reflector instead of gold
    double albedoTolerance, shapeTolerance;  // absolute; L1 as above
};

TEST(CoatedConductor, AgreesWithLayeredRandomWalk) {
    constexpr int kPaths = 250000;
    std::vector<WalkCase> cases;
    // cos 0.45 rather than 0.5: a mirror at cos 0.5 falls on the line between two rings.
    for (float cosO : {0.2f, 0.45f, 0.9f})
        for (bool perfect : {false, true}) {
            cases.push_back({0.0f, 0.0f, cosO, perfect, 0.001, 0.01});
            cases.push_back({0.0f, 0.2f, cosO, perfect, 0.025, cosO < 0.5f ? 0.5 : 0.1});
            cases.push_back({0.0f, 0.5f, cosO, perfect, 0.025, cosO < 0.5f ? 0.2 : 0.1});
            cases.push_back({0.3f, 0.0f, cosO, perfect, perfect ? 0.002 : 0.23, 1.5});
            cases.push_back({0.3f, 0.3f, cosO, perfect, 0.04, 0.33});
        }
    for (const WalkCase& wc : cases) {
        SCOPED_TRACE("coat " + std::to_string(wc.coatRoughness) + ", metal " + std::to_string(wc.metalRoughness) +
                     ", cos " + std::to_string(wc.cosO) + (wc.perfect ? ", perfect" : ", gold"));
        const float a = roughnessToAlpha(wc.metalRoughness);
        MaterialPtr metal = wc.perfect ? makeConductor(ColorParam(Color(1.0f)), GgxAlpha{a, a})
                                       : makeConductor(goldInCoat(), GgxAlpha{a, a});
        const Vec3 wi = direction(wc.cosO, 0.0f);
        test::LayeredRandomWalk walk(metal, kInputs, kIor, wc.coatRoughness);
        Rng rng(31, uint64_t(wc.cosO * 100), uint64_t(wc.coatRoughness * 100 + wc.metalRoughness * 10 + wc.perfect), StreamPurpose::Test);
        const BinnedAlbedo reference = test::binWalk(walk, wi, kPaths, rng);
        MaterialPtr m = makeCoatedConductor(metal, kIor, wc.coatRoughness);
        const BinComparison r = compareBins(binBySampling(*m, wi, kInputs, kPaths, 37), reference);
        double worstAlbedo = 0, worstShape = 0;
        for (int c = 0; c < 3; ++c) {
            EXPECT_NEAR(r.model[c], r.reference[c], wc.albedoTolerance) << "albedo, channel " << c;
            EXPECT_LE(r.l1[c], wc.shapeTolerance) << "lobe shape, channel " << c;
            worstAlbedo = std::max(worstAlbedo, std::abs(r.model[c] - r.reference[c]));
            worstShape = std::max(worstShape, r.l1[c]);
        }
        std::printf("  walk %-7s coat %.1f metal %.1f cos %.2f  model %.4f %.4f %.4f  walk %.4f %.4f %.4f  |diff| %.4f  L1 %.4f\n",
                    wc.perfect ? "perfect" : "gold", wc.coatRoughness, wc.metalRoughness, wc.cosO, r.model[0], r.model[1],
                    r.model[2], r.reference[0], r.reference[1], r.reference[2], worstAlbedo, worstShape);
    }
}

// ---- in a scene ----

// The Cornell box with its blocks in coated gold, a smooth coat over a rough metal (photons
// scatter through the trapped light's lobe as well as the others): SPPM and the path tracer
// agree in the image mean within 2% per channel.
TEST(CoatedConductorSppmVsPath, CoatedGoldBlocksAgreeInMean) {
    const float a = roughnessToAlpha(0.3f);
    MaterialPtr paint = makeCoatedConductor(makeConductor(goldInCoat(), GgxAlpha{a, a}), kIor, 0.0f);
    test::PathAndSppmMeans means = test::renderPathAndSppm(test::cornellBoxWith(paint, 32), 512, 256, 40000);
    std::printf("  path %.4f %.4f %.4f  sppm %.4f %.4f %.4f\n", means.path.x, means.path.y, means.path.z,
                means.sppm.x, means.sppm.y, means.sppm.z);
    for (int c = 0; c < 3; ++c) EXPECT_NEAR(means.sppm[c], means.path[c], 0.02f * means.path[c]) << "channel " << c;
}

// ---- the scene file ----

using test::expectError;
using test::load;


TEST(CoatedConductorScene, FieldsAndTheIndexRelativeToTheCoat) {
    // Gold's eta and k are divided by the coat's index: F + (1 - F)^2 R / (1 - F R) at normal
    // incidence with R gold's Fresnel against index 1.5.
    const ComplexIor gold = *findMetal("Au");
    const float ior = 1.6f, F = fresnelDielectric(1.0f, ior);
    const Color R = fresnelConductor(1.0f, gold.eta / ior, gold.k / ior);
    const Color expected = Color(F) + R * ((1 - F) * (1 - F)) / (Color(1.0f) - R * F);
    const Json coat = {{"type", "coated_conductor"}, {"ior", ior}, {"conductor", {{"metal", "Au"}, {"roughness", 0}}}};
    const Color got = test::mirrorReflectance(test::loadedMaterial(coat));
    for (int c = 0; c < 3; ++c) EXPECT_NEAR(got[c], expected[c], 1e-6f) << c;
    // The same through eta and k given as numbers.
    const Json byIndex = {{"type", "coated_conductor"},
                          {"ior", ior},
                          {"conductor", {{"eta", {gold.eta.x, gold.eta.y, gold.eta.z}}, {"k", {gold.k.x, gold.k.y, gold.k.z}}, {"roughness", 0}}}};
    const Color got2 = test::mirrorReflectance(test::loadedMaterial(byIndex));
    for (int c = 0; c < 3; ++c) EXPECT_NEAR(got2[c], expected[c], 1e-6f) << c;
    // A rough coat or metal makes glossy lobes; the conductor's own roughness default (0.2).
    EXPECT_EQ(test::loadedMaterial({{"type", "coated_conductor"}, {"conductor", {{"metal", "Cu"}}}}).lobes(),
              unsigned(kDeltaLobe | kGlossyLobe));
    EXPECT_EQ(test::loadedMaterial({{"type", "coated_conductor"}, {"roughness", 0.2}, {"conductor", {{"metal", "Cu"}}}}).lobes(),
              unsigned(kGlossyLobe));
}

TEST(CoatedConductorScene, Errors) {
    const std::string path = "materials.paint.";  // expectError edits "paint" in the full scene
    expectError([](Json& d) { d["materials"]["paint"] = {{"type", "coated_conductor"}}; }, path + "conductor",
                "missing required field");
    expectError([](Json& d) { d["materials"]["paint"] = {{"type", "coated_conductor"}, {"conductor", {{"metal", "Xx"}}}}; },
                path + "conductor.metal", "unknown metal \"Xx\" (expected one of " + metalSymbols() + ")");
    expectError([](Json& d) { d["materials"]["paint"] = {{"type", "coated_conductor"}, {"conductor", {{"type", "conductor"}}}}; },
                path + "conductor.type", "unknown field");
    expectError([](Json& d) { d["materials"]["paint"] = {{"type", "coated_conductor"}, {"roughness", 1.5}, {"conductor", Json::object()}}; },
                path + "roughness", "must be in [0, 1]");
}

}  // namespace
}  // namespace photon::coated_conductor_tests
