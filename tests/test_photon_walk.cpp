// The photon walk in lanes (sixteen photons side by side, Lambertian bounces in SIMD,
// with each instruction set the kernels are compiled for)
// against the plain definition of the walk, photon after photon: emit, intersect, hand the
// arrival over, sample the BSDF, Russian roulette, next ray. Both draw each photon's random
// numbers from the same stream, so they must land the same photons in the same places
// with the same flux, whatever the lanes' order.
#include <gtest/gtest.h>
#include <algorithm>
#include <iterator>
#include <tuple>
#include <vector>
#include "integrators/common/photon_paths.h"
#include "integrators/common/photon_roulette.h"
#include "math/lanes.h"
#include "scene/scene.h"
#include "test_support.h"

namespace photon {
namespace {

struct Landing {
    Vec3 p, ns, wi;
    Color flux;
    int depth;
    bool onlySpecular;
};

bool before(const Landing& a, const Landing& b) {
    return std::tie(a.p.x, a.p.y, a.p.z, a.depth) < std::tie(b.p.x, b.p.y, b.p.z, b.depth);
}

struct Recorder final : PhotonArrivalSink {
    std::vector<Landing> landings;
    void arrive(const PhotonArrival& a) override {
        landings.push_back({a.p, a.ns, a.wi, a.flux, a.depth, a.onlySpecular});
    }
};

// The walk as the integrators define it, one photon at a time.
void referenceWalk(const Scene& scene, const PhotonEmitter& emitter, const PhotonPathSettings& settings, int64_t count,
                   Recorder& out, PhotonPathCounters& counters) {
    const RngStream stream(settings.seed, settings.stream, StreamPurpose::Photon);
    for (int64_t index = 0; index < count; ++index) {
        Rng rng(stream, static_cast<uint64_t>(index));
        std::optional<EmittedPhoton> emitted = emitter.emit(rng);
        if (!emitted) continue;
        Color beta = emitted->beta;
        Ray ray = emitted->ray;
        bool onlySpecular = true;
        for (int depth = 0; depth < settings.maxDepth; ++depth) {
            SurfaceHit hit;
            ++counters.rays;
            if (!scene.intersect(ray, hit)) break;
            ++counters.segments;
            Vec3 wi = -ray.d;
            ShadingPoint sp = makeShadingPoint(scene, hit, wi);
            if (!sp.material->isDeltaOnly() && depth >= settings.firstArrivalDepth)
                out.arrive({sp.hit.p, sp.hit.ns, wi, beta, depth, onlySpecular});
            if (depth + 1 == settings.maxDepth) break;
            float uLobe = rng.uniform();
            Vec2 u{rng.uniform(), rng.uniform()};
            std::optional<BSDFSample> s =
                sp.material->sample(sp.frame.toLocal(wi), uLobe, u, sp.inputs, TransportMode::Importance);
            if (!s) break;
            onlySpecular = onlySpecular && s->delta;
            if (settings.specularOnly && !onlySpecular) break;
            std::optional<Color> next = photonAfterRoulette(beta, s->weight, rng);
            if (!next) break;
            beta = *next;
            ray = spawnRay(hit.p, hit.ng, sp.frame.toWorld(s->wi));
        }
    }
}

// Walks `photons` both ways with the kernels as they are and checks they agree.
void expectSameWalkIn(const std::string& sceneName, PhotonPathSettings settings, int64_t photons,
                      std::vector<Landing>& landings) {
    SceneDescription d = test::exampleScene(sceneName, 64, 1, photons, 1);
    std::shared_ptr<const Scene> scene = Scene::build(std::move(d));
    PhotonEmitter emitter(*scene, false);
    Recorder lanes, reference;
    PhotonPathCounters lanesCount, referenceCount;
    // In two calls, as the integrators' chunks do: a walk starts and ends within its range.
    tracePhotonPaths(*scene, emitter, settings, 0, photons / 3, lanes, lanesCount);
    tracePhotonPaths(*scene, emitter, settings, photons / 3, photons, lanes, lanesCount);
    referenceWalk(*scene, emitter, settings, photons, reference, referenceCount);

    EXPECT_EQ(lanesCount.rays, referenceCount.rays);
    EXPECT_EQ(lanesCount.segments, referenceCount.segments);
    ASSERT_EQ(lanes.landings.size(), reference.landings.size());
    ASSERT_GT(reference.landings.size(), static_cast<size_t>(photons / 2));
    std::sort(lanes.landings.begin(), lanes.landings.end(), before);
    std::sort(reference.landings.begin(), reference.landings.end(), before);
    for (size_t i = 0; i < reference.landings.size(); ++i) {
        const Landing& a = lanes.landings[i];
        const Landing& b = reference.landings[i];
        ASSERT_EQ(a.p, b.p) << i;
        ASSERT_EQ(a.ns, b.ns) << i;
        ASSERT_EQ(a.wi, b.wi) << i;
        ASSERT_EQ(a.flux, b.flux) << i;
        ASSERT_EQ(a.depth, b.depth) << i;
        ASSERT_EQ(a.onlySpecular, b.onlySpecular) << i;
    }
    landings = reference.landings;
}

// Walks `photons` both ways and checks they agree, once with each instruction set the
// lanes' kernels are compiled for that this CPU runs; `landings` receives them.
void expectSameWalk(const std::string& sceneName, PhotonPathSettings settings, int64_t photons,
                    std::vector<Landing>& landings) {
    for (LanesIsa isa : {LanesIsa::Baseline, LanesIsa::Avx2, LanesIsa::Avx512}) {
        if (isa > cpuLanesIsa()) continue;
        SCOPED_TRACE(static_cast<int>(isa));
        limitLanesIsa(isa);
        expectSameWalkIn(sceneName, settings, photons, landings);
        limitLanesIsa(LanesIsa::Avx512);
        if (::testing::Test::HasFatalFailure()) return;
    }
}

double indirectShare(const std::vector<Landing>& landings) {
    return static_cast<double>(std::count_if(landings.begin(), landings.end(), [](const Landing& l) { return l.depth > 0; })) /
           static_cast<double>(landings.size());
}

// Diffuse walls, a mirror and a glass sphere: Lambertian bounces in lanes, the others one by one.
TEST(PhotonWalk, LanesLandPhotonsExactlyWhereTheDefinitionDoes) {
    // Most landings come after bounces, so the lanes' Lambertian bounce was exercised.
    std::vector<Landing> landings;
    expectSameWalk("cornell-glass", {3, 0, 8, false}, 20000, landings);
    EXPECT_GT(indirectShare(landings), 0.5);
}

// Textured Lambertian surfaces (their colour looked up per lane) and plastic.
TEST(PhotonWalk, TexturedAndGlossySurfacesToo) {
    std::vector<Landing> landings;
    expectSameWalk("textured-mesh", {5, 2, 8, false}, 20000, landings);
    EXPECT_GT(indirectShare(landings), 0.05);  // an open scene: most photons leave after one bounce
}

// A short maximum depth ends walks in the middle of the lanes' bounces.
TEST(PhotonWalk, MaximumDepthEndsPathsAlike) {
    std::vector<Landing> landings;
    expectSameWalk("cornell-box", {7, 1, 2, false}, 20000, landings);
    EXPECT_GT(indirectShare(landings), 0.2);
    for (const Landing& l : landings) ASSERT_LT(l.depth, 2);
}

// SPPM with direct light from light sampling: no arrivals straight from the lights, and
// every later one as before.
TEST(PhotonWalk, ArrivalsBeforeTheFirstArrivalDepthAreNotHandedOn) {
    std::vector<Landing> all, later;
    expectSameWalk("cornell-glass", {3, 0, 8, false, 0}, 20000, all);
    expectSameWalk("cornell-glass", {3, 0, 8, false, 1}, 20000, later);
    std::vector<Landing> expected;
    std::copy_if(all.begin(), all.end(), std::back_inserter(expected), [](const Landing& l) { return l.depth >= 1; });
    ASSERT_EQ(later.size(), expected.size());
    ASSERT_LT(later.size(), all.size() * 3 / 4);  // the lights' own photons were many
    for (size_t i = 0; i < later.size(); ++i) {
        ASSERT_EQ(later[i].p, expected[i].p) << i;
        ASSERT_EQ(later[i].flux, expected[i].flux) << i;
    }
}

// The caustic map's walk (delta bounces only) ends at the first Lambertian surface.
TEST(PhotonWalk, SpecularOnlyWalksStopAtTheFirstDiffuseSurface) {
    std::vector<Landing> landings;
    expectSameWalk("cornell-glass", {9, 0, 8, true}, 20000, landings);
    EXPECT_GT(indirectShare(landings), 0.02);  // the caustics under the spheres
    for (const Landing& l : landings) ASSERT_TRUE(l.onlySpecular);
}

}  // namespace
}  // namespace photon
