// Helpers shared by the engine tests.
#pragma once
#include <filesystem>
#include <string>
#include <string_view>

namespace photon::test {

// `bytes` compressed as one gzip member (zlib's deflate), as `gzip` writes a file.
std::string gzipped(std::string_view bytes);

// Absolute path of a file in the source tree, e.g. sourcePath("scenes/cornell-box.json").
inline std::filesystem::path sourcePath(const std::string& relative) {
    return std::filesystem::path(PHOTON_SOURCE_DIR) / relative;
}

}  // namespace photon::test

#include <cmath>
#include <functional>
#include <memory>
#include <vector>
#include <photon/image.h>
#include <photon/render.h>
#include "lights/light.h"
#include "scene/scene.h"
#include "scene/scene_loader.h"

namespace photon::test {

// An example scene from scenes/ at a small square resolution, with the render settings the
// tests vary most; other settings stay as the file has them.
inline SceneDescription exampleScene(const std::string& name, int resolution, int passes, int64_t photonsPerPass,
                                     uint64_t seed) {
    SceneDescription d = loadSceneFile(sourcePath("scenes/" + name + ".json"));
    d.camera.width = d.camera.height = resolution;
    d.render.passes = passes;
    d.render.photonsPerPass = photonsPerPass;
    d.render.seed = seed;
    return d;
}

// What PHOTON_TEST_SEED_SHIFT says (0 where unset): renderImage adds it to every scene's
// seed, so that a run of the suite under other seeds (scripts/seed-sweep.sh) finds the
// tests whose tolerance a seed's noise alone can cross.
uint64_t seedShift();

// Renders all the scene's passes (the seed shifted by seedShift()); the snapshot after the last.
Image renderImage(SceneDescription d);

// The small scene a material's SPPM image is held to the path tracer's on: the Cornell box
// (scenes/cornell-box.json) at `resolution` with its two blocks made of `material`, or,
// with `sphere`, the blocks replaced by one sphere of it (radius 0.3, on the floor).
SceneDescription cornellBoxWith(MaterialPtr material, int resolution, bool sphere = false);
// Where the camera ray through film point (x, y) meets the plane y = 0 (lightOverPlane's).
Vec3 planePointSeen(const Camera& camera, float x, float y);
// Each 4 x 4 block of `image` against the mean of `radiance` (film point to colour) over it,
// by 64 x 64 points a pixel (a sharp edge through a pixel is then placed within 1/128 of a
// pixel), per channel within `tolerance` of the expected value plus 1e-4. Returns how many
// blocks are lit (green above 1e-3) and how many dark.
struct LitAndDark {
    int lit = 0, dark = 0;
};
LitAndDark expectBlocksMatch(const Image& image, const std::function<Color(float, float)>& radiance, float tolerance);
// On lightOverPlane's plane, `light`'s photons (128 passes of 100k) draw what its shadow
// rays (64 passes) draw: in 16 x 16 blocks within 3.5% (smaller blocks show the gather
// discs' blur at sharp edges of the light's pattern). Over 12 seeds the blocks in the dim
// corners of the profiled and projection lights' images deviate by 0.9% a seed, their means
// up to 1% high (the blur at the pattern's edge), the bright middle ones by 0.1-0.5%: at the
// 2% this held before, one seed in twelve failed a corner.
void expectPhotonsDrawWhatShadowRaysDraw(const LightDescription& light, float rho, int resolution);
// Image means of the scene by the path tracer and by SPPM, with the passes and photons
// given, at maximum depth 64 (transport the two see alike).
struct PathAndSppmMeans {
    Color path, sppm;
};
PathAndSppmMeans renderPathAndSppm(SceneDescription d, int pathPasses, int sppmPasses, int64_t photonsPerPass);
// The same with at most `threads` oneTBB threads (determinism tests).
Image renderWithThreads(SceneDescription d, int threads);

// A render of `d` stopped after `passes` passes and checkpointed, then resumed from that
// checkpoint in a new renderer and run to its end (the seed shifted by seedShift()).
std::unique_ptr<Renderer> resumedAfter(SceneDescription d, int passes);

// Mean colour over the pixel rectangle [x0, x1) x [y0, y1).
inline Color meanOver(const Image& image, int x0, int y0, int x1, int y1) {
    Color sum(0.0f);
    for (int y = y0; y < y1; ++y)
        for (int x = x0; x < x1; ++x) sum += image.at(x, y);
    return sum / static_cast<float>((x1 - x0) * (y1 - y0));
}

// pointLightPlane's floor (2 m square, 24 x 24 pixels) with no light yet, path-traced with
// direct light only by the given light sampler and seed: where ways of sampling lights are
// compared.
SceneDescription directLitFloor(LightSamplerKind kind, uint64_t seed, int passes);

// A scene (made for a light sampler and a seed) rendered by the spatial and the power light
// samplers, each with seeds 1 and 2.
struct RendersBySampler {
    Image spatial, spatial2, power, power2;
};
RendersBySampler renderBySampler(const std::function<SceneDescription(LightSamplerKind, uint64_t)>& scene);

// Two ways of rendering one image agree: over each block x block pixels, the mean of a1
// and a2 (two seeds of one way) is within `tolerance` (relative) of b1 and b2's.
void expectSameBlockMeans(const Image& a1, const Image& a2, const Image& b1, const Image& b2, int block,
                          float tolerance);

// One render's relative noise from two with different seeds, in luminance: RMS of their
// difference / sqrt 2 over the mean, with lights seen directly and their neighbours left out
// (film/pixel_errors.h), whose edge pixels are as noisy for every method.
double relativeNoiseOfLuminance(const Image& a, const Image& b);
// The same over the pixels `keep` marks (row by row), for a test that knows which to leave out.
double relativeNoiseOfLuminance(const Image& a, const Image& b, const std::vector<bool>& keep);

// A render without and with a change that must not change its expectation (`render(with,
// seed)`, seeds 1 and 2 each): block means held to each other by expectSameBlockMeans, and
// each way's relative noise in luminance.
struct NoiseWithoutAndWith {
    double without, with;
};
NoiseWithoutAndWith expectSameMeansAndMeasureNoise(const std::function<Image(bool with, uint64_t seed)>& render, int block,
                                                   float tolerance);

// Irradiance at p (normal n) from a uniform polygon of radiance Le, all of it above p's
// horizon: Lambert's formula, Le / 2 sum over edges of the angle each subtends times n's
// component along the normal of the plane through p and the edge (Arvo 1995).
double polygonIrradiance(Vec3 p, Vec3 n, const std::vector<Vec3>& corners, double le);

// The ray from p along a light sample (the k-th) meets the light where the sample lies, and
// the light gives that point the density the sample was drawn with (what BSDF samples that
// find the light weigh themselves against).
void expectRayFindsLightSample(const Scene& scene, const Light& light, Vec3 p, ReceiverSide side, const LightSample& ls, int k);

// The irradiance at p (normal n) from the scene's light 0 by `samples` of its light samples:
// their mean, variance, and how many brought nothing (no sample, or one from behind p). With
// checkDensity, expectRayFindsLightSample for each.
struct LightSampleEstimate {
    double mean = 0, variance = 0;
    int nothing = 0;
};
LightSampleEstimate irradianceFromLightSamples(const Scene& scene, Vec3 p, ReceiverSide side, int samples, bool checkDensity);

// Component-wise closeness of two Vec3 (or Color) values, in a gtest test body; Vec3
// must name photon::Vec3 where it is used.
#define EXPECT_VEC3_NEAR(a, b, tol)       \
    do {                                  \
        Vec3 a_ = (a), b_ = (b);          \
        EXPECT_NEAR(a_.x, b_.x, tol);     \
        EXPECT_NEAR(a_.y, b_.y, tol);     \
        EXPECT_NEAR(a_.z, b_.z, tol);     \
    } while (0)


}  // namespace photon::test
