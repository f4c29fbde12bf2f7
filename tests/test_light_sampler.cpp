// The shadow rays' light choice (render.light_sampler, engine/lights/direct_light_sampler.h):
// its bounds never rule out a light that can reach a point, its probabilities are the ones
// it picks with (exhaustively and through the tree), its estimate of point lights' irradiance
// is exact, and rendered images agree with the power sampler's while being less noisy.
#include <gtest/gtest.h>
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <photon/render.h>
#include "lights/direct_light_sampler.h"
#include "math/lanes.h"
#include "math/rng.h"
#include "scene/scene.h"
#include "scene_builders.h"
#include "test_support.h"

namespace photon {
namespace {

LightDescription pointLight(Vec3 position, float intensity) {
    LightDescription l;
    l.kind = LightDescription::Kind::Point;
    l.position = position;
    l.intensity = Color(intensity);
    return l;
}

LightDescription spotLight(Vec3 position, Vec3 direction, float intensity, float cone, float falloff) {
    LightDescription l = pointLight(position, intensity);
    l.kind = LightDescription::Kind::Spot;
    l.direction = direction;
    l.coneAngleDegrees = cone, l.falloffAngleDegrees = falloff;
    return l;
}

// The irradiance a point light brings to p on a surface facing n: I cos / d^2, from above n only.
double pointIrradiance(const LightDescription& l, Vec3 p, Vec3 n) {
    const Vec3 d = l.position - p;
    const double cosTheta = dot(normalize(d), n);
    return cosTheta > 0 ? average(l.intensity) * cosTheta / lengthSquared(d) : 0.0;
}

std::shared_ptr<const Scene> sceneWith(std::vector<LightDescription> lights, std::vector<ShapeDescription> emitters = {}) {
    SceneDescription d = test::pointLightPlane(0.5f, 1.0f, 1.0f, 8, 2.0f);
    d.lights = std::move(lights);
    for (ShapeDescription& s : emitters) d.shapes.push_back(std::move(s));
    return Scene::build(std::move(d));
}

Vec3 randomDirection(Rng& rng) { return sampleUniformSphere({rng.uniform(), rng.uniform()}); }

// With point lights, a light's importance is its irradiance at the point exactly, so one
// light sample, weighed by its pick probability, is the irradiance of all of them: the
// spatial sampler has no variance there, and lights below the surface are never picked.
TEST(DirectLightSampler, PointLightsIrradianceFromOneSampleIsExact) {
    std::vector<LightDescription> lights = {pointLight({0.3f, 1, 0.2f}, 5), pointLight({-2, 0.5f, 1}, 20),
                                            pointLight({1, 3, -1}, 40), pointLight({0, -1, 0}, 100),
                                            pointLight({0.1f, 0.05f, 0.1f}, 0.2f)};
    auto scene = sceneWith(lights);
    const DirectLightSampler& sampler = scene->directLights();
    const Vec3 n{0, 1, 0};
    for (Vec3 p : {Vec3(0, 0, 0), Vec3(0.7f, 0, -0.4f), Vec3(-1.5f, 0, 1.2f)}) {
        double exact = 0;
        for (const LightDescription& l : lights) exact += pointIrradiance(l, p, n);
        for (float u : {0.001f, 0.2f, 0.45f, 0.7f, 0.93f, 0.9999f}) {
            LightSampler::Pick pick = sampler.pick(u, p, n);
            ASSERT_NE(pick.light, nullptr);
            const LightDescription& l = lights[pick.index];
            EXPECT_GT(l.position.y, 0) << "a light below the surface was picked";
            EXPECT_NEAR(pointIrradiance(l, p, n) / pick.probability, exact, 1e-4 * exact) << "u " << u;
            EXPECT_EQ(pick.probability, sampler.probability(pick.index, p, n));
        }
        EXPECT_EQ(sampler.probability(3, p, n), 0.0f);  // the one below
    }
}

// Over u in [0, 1) the light picked is light i on a share p_i of the line, and the estimate
// of the irradiance is the irradiance on average over u. Where the tree's walk ends at a
// light whose own bound is zero there (its branch's was not), no light is picked: the
// probabilities then sum to less than 1, by the share of u that picks none.
void expectPicksFollowProbabilities(const std::vector<LightDescription>& lights, Vec3 p, Vec3 n) {
    auto scene = sceneWith(lights);
    const DirectLightSampler& sampler = scene->directLights();
    const int N = 1 << 18;
    std::vector<int> count(lights.size(), 0);
    int none = 0;
    double estimate = 0, exact = 0, total = 0;
    for (size_t i = 0; i < lights.size(); ++i) {
        exact += pointIrradiance(lights[i], p, n);
        total += sampler.probability(i, p, n);
    }
    for (int k = 0; k < N; ++k) {
        LightSampler::Pick pick = sampler.pick((k + 0.5f) / N, p, n);
        if (!pick.light) {
            ++none;
            continue;
        }
        ++count[pick.index];
        ASSERT_EQ(pick.probability, sampler.probability(pick.index, p, n));
        estimate += pointIrradiance(lights[pick.index], p, n) / pick.probability;
    }
    EXPECT_NEAR(total + none / double(N), 1.0, 1e-3);
    EXPECT_LE(total, 1.0 + 1e-5);
    for (size_t i = 0; i < lights.size(); ++i)
        EXPECT_NEAR(count[i] / double(N), sampler.probability(i, p, n), 4.0 / N + 1e-5) << "light " << i;
    EXPECT_NEAR(estimate / N, exact, 1e-3 * exact);
}

std::vector<LightDescription> scatteredPointLights(int count, uint64_t seed) {
    Rng rng(seed, 0, 0, StreamPurpose::Test);
    std::vector<LightDescription> lights;
    for (int i = 0; i < count; ++i)
        lights.push_back(pointLight({4 * rng.uniform() - 2, 3 * rng.uniform() - 0.5f, 4 * rng.uniform() - 2},
                                    0.1f + 10 * rng.uniform()));
    return lights;
}

TEST(DirectLightSampler, ExhaustivePicksFollowTheirProbabilities) {
    expectPicksFollowProbabilities(scatteredPointLights(12, 7), {0.2f, 0, -0.3f}, {0, 1, 0});
}

TEST(DirectLightSampler, TreePicksFollowTheirProbabilitiesAndEstimateTheIrradiance) {
    const auto lights = scatteredPointLights(500, 11);
    static_assert(DirectLightSampler::kMaxExhaustive < 500);
    expectPicksFollowProbabilities(lights, {0.2f, 0, -0.3f}, {0, 1, 0});
    expectPicksFollowProbabilities(lights, {-1.1f, 0.3f, 0.9f}, normalize(Vec3(1, 1, 0)));
}

// The environment keeps its power's share, wherever the point: what a BSDF sample that
// leaves the scene weighs itself against (Scene::environmentLights).
TEST(DirectLightSampler, InfiniteLightsKeepTheirShareOfPower) {
    LightDescription sky;
    sky.kind = LightDescription::Kind::Environment;
    sky.radiance = Color(0.3f);
    auto scene = sceneWith({pointLight({0, 1, 0}, 10), sky, pointLight({1, 2, 0}, 5)});
    const float share = scene->environmentLights().at(0).pickProbability;
    ASSERT_GT(share, 0.0f);
    for (Vec3 p : {Vec3(0, 0, 0), Vec3(1.5f, 0, 1)}) {
        EXPECT_EQ(scene->directLights().probability(1, p, {0, 1, 0}), share);
        EXPECT_NEAR(scene->directLights().probability(0, p, {0, 1, 0}) +
                        scene->directLights().probability(2, p, {0, 1, 0}), 1.0f - share, 1e-6f);
    }
}

// Bounds are conservative: wherever any sample of a light reaches p from above n (or at
// all, for n = 0), its importance there is above zero. Quads facing every way, one- and
// two-sided, a sphere, spots and points; points near, far and inside the lights' boxes.
TEST(DirectLightSampler, BoundsNeverRuleOutALightThatReachesThePoint) {
    Rng rng(3, 0, 0, StreamPurpose::Test);
    std::vector<ShapeDescription> emitters;
    for (int i = 0; i < 12; ++i) {
        const Vec3 origin{2 * rng.uniform() - 1, 2 * rng.uniform(), 2 * rng.uniform() - 1};
        const Vec3 u = randomDirection(rng) * (0.1f + rng.uniform()), v = randomDirection(rng) * (0.1f + rng.uniform());
        emitters.push_back(test::quad(origin, u, v, 0, Color(1.0f + i)));
        emitters.back().twoSidedEmission = i % 3 == 0;
    }
    emitters.push_back(test::sphere({0.5f, 1, 0.5f}, 0.3f, 0, Color(2.0f)));
    std::vector<LightDescription> lights = {spotLight({0, 1.5f, 0}, {0, -1, 0}, 10, 30, 20),
                                            spotLight({1, 0.5f, -1}, normalize(Vec3(-1, 0, 1)), 5, 60, 10),
                                            spotLight({-0.5f, 1, 0.5f}, normalize(Vec3(1, -1, 0)), 5, 25, 25),  // hard-edged
                                            pointLight({-1, 1, 1}, 3)};
    auto scene = sceneWith(lights, emitters);
    const LightSampler& all = scene->lights();
    int reaching = 0, ruledOut = 0;
    for (int trial = 0; trial < 400; ++trial) {
        const Vec3 p{3 * rng.uniform() - 1.5f, 3 * rng.uniform() - 0.5f, 3 * rng.uniform() - 1.5f};
        const Vec3 n = trial % 4 == 0 ? Vec3(0, 0, 0) : randomDirection(rng);
        for (size_t i = 0; i < all.size(); ++i) {
            const std::optional<LightBounds> bounds = all.light(i).bounds();
            ASSERT_TRUE(bounds);
            bool reaches = false;
            for (int k = 0; k < 256 && !reaches; ++k) {
                std::optional<LightSample> s = all.light(i).sampleIncident(p, n, {(k % 16 + 0.5f) / 16, (k / 16 + 0.5f) / 16});
                reaches = s && !isBlack(s->weight) && (lengthSquared(n) == 0 || dot(s->wi, n) > 1e-3f);
            }
            const float importance = photon::importance(*bounds, p, n);
            if (reaches) {
                ++reaching;
                EXPECT_GT(importance, 0.0f) << "light " << i << " at trial " << trial;
            } else if (importance == 0) {
                ++ruledOut;
            }
        }
    }
    // The test means something only if both happen often.
    EXPECT_GT(reaching, 1000);
    EXPECT_GT(ruledOut, 1000);
}

// Bounds asked eight at a time (LightImportances, what the sampler and the tree's nodes and
// leaves evaluate) give each light's figure to the bit as asked one at a time, on every
// instruction set the lanes compile for, from any first light and count (lanes part-filled,
// groups crossing the padding).
TEST(DirectLightSampler, BoundsInLanesAreTheBoundsOneAtATime) {
    Rng rng(11, 0, 0, StreamPurpose::Test);
    std::vector<LightBounds> bounds;
    for (int i = 0; i < 37; ++i) {
        LightBounds b;
        const Vec3 centre{4 * rng.uniform() - 2, 4 * rng.uniform() - 2, 4 * rng.uniform() - 2};
        const Vec3 half{i % 5 == 0 ? 0.0f : rng.uniform(), rng.uniform(), 0.5f * rng.uniform()};
        b.lo = centre - half, b.hi = centre + half;
        b.intensity = i % 9 == 0 ? 0.0f : 10 * rng.uniform();
        b.axis = randomDirection(rng);
        b.cosThetaO = i % 4 == 0 ? -1.0f : i % 4 == 1 ? 1.0f : 2 * rng.uniform() - 1;
        b.cosThetaE = i % 3 == 0 ? 0.0f : i % 3 == 1 ? 1.0f : rng.uniform();
        b.twoSided = i % 2 == 0;
        bounds.push_back(b);
    }
    const LightImportances inLanes(bounds);
    ASSERT_EQ(inLanes.size(), bounds.size());
    int positive = 0;
    for (LanesIsa isa : {LanesIsa::Baseline, LanesIsa::Avx2, LanesIsa::Avx512}) {
        if (isa > cpuLanesIsa()) continue;
        SCOPED_TRACE(static_cast<int>(isa));
        limitLanesIsa(isa);
        for (int trial = 0; trial < 300; ++trial) {
            // Points inside boxes too (the last light's centre), and n = 0.
            const Vec3 p = trial % 7 == 0 ? (bounds.back().lo + bounds.back().hi) * 0.5f
                                          : Vec3{6 * rng.uniform() - 3, 6 * rng.uniform() - 3, 6 * rng.uniform() - 3};
            const Vec3 n = trial % 5 == 0 ? Vec3(0, 0, 0) : randomDirection(rng);
            const size_t first = trial % bounds.size(), count = 1 + trial % (bounds.size() - first);
            float each[64];
            const float sum = inLanes.evaluate(first, count, p, n, each);
            float expectedSum = 0;
            for (size_t k = 0; k < count; ++k) {
                const float one = importance(bounds[first + k], p, n);
                EXPECT_EQ(each[k], one) << "light " << first + k << " at trial " << trial;
                expectedSum += one;
                positive += one > 0;
            }
            EXPECT_EQ(sum, expectedSum);
        }
        limitLanesIsa(LanesIsa::Avx512);
    }
    EXPECT_GT(positive, 1000);
}

// A floor under three quad lights facing different ways and a spot, rendered by the path
// tracer with direct light only: both samplers reach the same image (the spatial sampler's
// probabilities enter the multiple importance weights of BSDF samples that find a light),
// and the spatial one with less noise. With independent numbers: Sobol passes
// (render.sampler) stratify the light pick over a pixel's passes, so picking by power then
// gives every light its share of them, and the gap narrows.
SceneDescription floorUnderLights(LightSamplerKind kind, uint64_t seed) {
    SceneDescription d = test::directLitFloor(kind, seed, 256);
    d.render.sampler = SamplerKind::Independent;
    d.lights = {spotLight({-0.6f, 1.2f, 0.6f}, {0, -1, 0}, 3, 35, 25)};
    d.shapes.push_back(test::quad({0.6f, 0.4f, -0.6f}, {0.3f, 0, 0}, {0, 0.3f, 0}, 0, Color(4.0f)));   // faces +z
    d.shapes.push_back(test::quad({-0.9f, 0.3f, -0.2f}, {0, 0, 0.3f}, {0, 0.3f, 0}, 0, Color(4.0f)));  // faces -x
    d.shapes.push_back(test::quad({0.2f, 0.8f, 0.2f}, {0.4f, 0, 0}, {0, 0, 0.4f}, 0, Color(6.0f)));    // faces down
    return d;
}

// The pixels that neither see a light nor touch one that does: where the lights' edges
// cross a pixel its value follows where in the pixel each pass's camera ray went, the same
// for both samplers (their renders of a seed draw the same rays), and a few such pixels
// carried most of a pair's squared difference, so that the ratio of the samplers' noise
// ranged from 0.27 to 0.85 over seeds. The floor itself stays below luminance 1, the lights
// are 4 and 6.
std::vector<bool> awayFromLights(const test::RendersBySampler& r) {
    const int w = r.spatial.width, h = r.spatial.height;
    std::vector<bool> keep(size_t(w) * h, true);
    for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x) {
            const Color sum = r.spatial.at(x, y) + r.spatial2.at(x, y) + r.power.at(x, y) + r.power2.at(x, y);
            if (luminance(sum) < 4.0f) continue;
            for (int j = std::max(0, y - 1); j <= std::min(h - 1, y + 1); ++j)
                for (int i = std::max(0, x - 1); i <= std::min(w - 1, x + 1); ++i) keep[size_t(j) * w + i] = false;
        }
    return keep;
}

// 256 passes a render. Over 16 seeds the spatial sampler's noise away from the lights is
// 0.24-0.32 of the power sampler's (at 64 passes 0.25-0.29), held below 0.4; the 8 x 8
// blocks' means agree within 3%.
TEST(DirectLightSampler, SpatialAndPowerRenderTheSameImageTheSpatialWithLessNoise) {
    const test::RendersBySampler r = test::renderBySampler(floorUnderLights);
    const std::vector<bool> keep = awayFromLights(r);
    EXPECT_GT(std::count(keep.begin(), keep.end(), true), 400);  // of 576
    test::expectSameBlockMeans(r.spatial, r.spatial2, r.power, r.power2, 8, 0.03f);
    const double spatial = test::relativeNoiseOfLuminance(r.spatial, r.spatial2, keep);
    const double power = test::relativeNoiseOfLuminance(r.power, r.power2, keep);
    std::printf("  relative noise away from the lights: spatial %.4f, power %.4f (%.3f)\n", spatial, power, spatial / power);
    EXPECT_LT(spatial, 0.4 * power);
}

}  // namespace
}  // namespace photon
