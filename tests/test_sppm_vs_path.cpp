// SPPM against an independent estimator: the unidirectional path tracer, on the diffuse
// Cornell box. Mean and every region of the image agree within 2%.
#include <gtest/gtest.h>
#include <tbb/global_control.h>
#include <photon/render.h>
#include "integrators/integrator.h"
#include "scene/scene.h"
#include "scene/scene_loader.h"
#include "test_support.h"

namespace photon {
namespace {

constexpr int kResolution = 64, kRegion = 16;

Image render(IntegratorKind kind, int passes, int64_t photons) {
    SceneDescription d = test::exampleScene("cornell-box", kResolution, passes, photons, 7);
    d.render.integrator = kind;
    d.render.maxDepth = 64;  // both methods see the same, practically untruncated, transport
    Renderer renderer(Scene::build(std::move(d)));
    CancelToken cancel;
    renderer.run(cancel);
    return renderer.snapshot();
}

TEST(SppmVsPath, CornellBoxAgreesInMeanAndPerRegion) {
    Image path = render(IntegratorKind::Path, 2048, 0);
    Image sppm = render(IntegratorKind::Sppm, 200, 100000);
    Color pathMean = test::meanOver(path, 0, 0, kResolution, kResolution);
    Color sppmMean = test::meanOver(sppm, 0, 0, kResolution, kResolution);
    for (int c = 0; c < 3; ++c) EXPECT_NEAR(sppmMean[c], pathMean[c], 0.02f * pathMean[c]) << "channel " << c;
    for (int y = 0; y < kResolution; y += kRegion)
        for (int x = 0; x < kResolution; x += kRegion) {
            Color p = test::meanOver(path, x, y, x + kRegion, y + kRegion);
            Color s = test::meanOver(sppm, x, y, x + kRegion, y + kRegion);
            EXPECT_NEAR(luminance(s), luminance(p), 0.02f * luminance(p)) << "region at " << x << "," << y;
        }
}

}  // namespace
}  // namespace photon
