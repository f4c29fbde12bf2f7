// Lightweight photon mapping (render.lightweight): path-traced camera paths, photons for the
// caustics only. Held to the independent path tracer on the glass-sphere Cornell box, whose
// caustic under the sphere the path tracer finds only by chance, and to it in noise.
#include <gtest/gtest.h>
#include <cmath>
#include <cstdio>
#include <photon/render.h>
#include "integrators/integrator.h"
#include "scene/scene.h"
#include "test_support.h"

namespace photon::lightweight_tests {
namespace {

constexpr int kResolution = 64, kRegion = 16;

Image render(IntegratorKind kind, bool lightweight, int passes, uint64_t seed) {
    SceneDescription d = test::exampleScene("cornell-glass", kResolution, passes, 50000, seed);
    d.render.integrator = kind;
    d.render.lightweight = lightweight;
    d.render.maxDepth = 64;  // both see the same, practically untruncated, transport
    return test::renderImage(std::move(d));
}

TEST(Lightweight, GlassCornellBoxAgreesWithThePathTracerInMeanAndPerRegion) {
    const Image path = render(IntegratorKind::Path, false, 2048, 7);
    const Image lightweight = render(IntegratorKind::Sppm, true, 256, 7);
    const Color p = test::meanOver(path, 0, 0, kResolution, kResolution);
    const Color l = test::meanOver(lightweight, 0, 0, kResolution, kResolution);
    for (int c = 0; c < 3; ++c) EXPECT_NEAR(l[c], p[c], 0.01f * p[c]) << "channel " << c;
    for (int y = 0; y < kResolution; y += kRegion)
        for (int x = 0; x < kResolution; x += kRegion) {
            const float rp = luminance(test::meanOver(path, x, y, x + kRegion, y + kRegion));
            const float rl = luminance(test::meanOver(lightweight, x, y, x + kRegion, y + kRegion));
            std::printf("region %d,%d: path %.4f lightweight %.4f\n", x, y, rp, rl);
            // Seeds 7 to 10 put the region at the ceiling's far corner (48, 0) at 0.0485 to
            // 0.0517 (either render.sampler), a 3% spread: the sphere's caustics on the ceiling.
            EXPECT_NEAR(rl, rp, 0.05f * rp) << "region at " << x << "," << y;
        }
}

TEST(Lightweight, PhotonsTakeTheCausticsNoiseAway) {
    constexpr int kPasses = 256;
    const double path = test::relativeNoiseOfLuminance(render(IntegratorKind::Path, false, kPasses, 1),
                                      render(IntegratorKind::Path, false, kPasses, 2));
    const double lightweight = test::relativeNoiseOfLuminance(render(IntegratorKind::Sppm, true, kPasses, 1),
                                             render(IntegratorKind::Sppm, true, kPasses, 2));
    std::printf("relative noise at %d passes: path %.4f, lightweight %.4f\n", kPasses, path, lightweight);
    // Measured: 0.171 against 0.211 (GCC) and 0.220 (clang). The caustic under the sphere is
    // a small part of the image; elsewhere both are the same path tracer.
    EXPECT_LT(lightweight, 0.9 * path);
}

// In a scene without a delta lobe no photon could carry a caustic: none are traced, and
// the passes cost what the path tracer's do.
TEST(Lightweight, TracesNoPhotonsWhereNoMaterialHasADeltaLobe) {
    SceneDescription d = test::exampleScene("cornell-box", 16, 2, 20000, 3);
    d.render.lightweight = true;
    Renderer renderer(Scene::build(std::move(d)));
    CancelToken cancel;
    renderer.run(cancel);
    EXPECT_EQ(renderer.integrator().lastPassStats().photons, 0);
    EXPECT_EQ(renderer.integrator().lastPassStats().photonRays, 0);
    // Every pixel's path casts its first ray, and on the box's walls goes on (rays counted at
    // each vertex and light sample).
    EXPECT_GT(renderer.integrator().lastPassStats().cameraRays, 2 * 16 * 16);
    EXPECT_GT(test::meanOver(renderer.snapshot(), 0, 0, 16, 16).x, 0.0f);

    SceneDescription glass = test::exampleScene("cornell-glass", 16, 2, 20000, 3);
    glass.render.lightweight = true;
    Renderer withGlass(Scene::build(std::move(glass)));
    withGlass.run(cancel);
    EXPECT_EQ(withGlass.integrator().lastPassStats().photons, 20000);
}

TEST(Lightweight, IsBitIdenticalForASeedAtAnyThreadCount) {
    SceneDescription d = test::exampleScene("cornell-glass", 24, 4, 20000, 3);
    d.render.lightweight = true;
    const Image one = test::renderWithThreads(d, 1), two = test::renderWithThreads(d, 2);
    EXPECT_EQ(one.rgb, two.rgb);
    EXPECT_GT(test::meanOver(one, 0, 0, 24, 24).x, 0.0f);
}

}  // namespace
}  // namespace photon::lightweight_tests
