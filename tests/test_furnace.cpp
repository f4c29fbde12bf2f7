// Furnace: inside a closed sphere of albedo rho emitting Le everywhere, the radiance in
// every direction is Le / (1 - rho) (the sum of the Neumann series Le sum rho^k).
#include <gtest/gtest.h>
#include <photon/render.h>
#include "integrators/integrator.h"
#include "scene/scene.h"
#include "scene/scene_loader.h"
#include "scene_builders.h"
#include "test_support.h"

namespace photon {
namespace {

struct FurnaceCase {
    IntegratorKind integrator;
    DirectLighting direct;
    float rho;
};

class Furnace : public ::testing::TestWithParam<FurnaceCase> {};

TEST_P(Furnace, ConvergesToEmissionOverOneMinusAlbedo) {
    const FurnaceCase& c = GetParam();
    const float le = 1.0f;
    SceneDescription d = test::furnace(c.rho, le, 16);
    d.render.integrator = c.integrator;
    d.render.direct = c.direct;
    d.render.maxDepth = 200;  // truncation error rho^200: nil
    d.render.passes = c.integrator == IntegratorKind::Path ? 256 : 32;
    d.render.photonsPerPass = 50000;
    Renderer renderer(Scene::build(std::move(d)));
    CancelToken cancel;
    renderer.run(cancel);
    Image image = renderer.snapshot();
    Color mean = test::meanOver(image, 0, 0, 16, 16);
    float expected = le / (1 - c.rho);
    for (int ch = 0; ch < 3; ++ch) EXPECT_NEAR(mean[ch], expected, 0.02f * expected);
    // Every pixel sees the same thing: no region may stray far either.
    for (int by = 0; by < 16; by += 8)
        for (int bx = 0; bx < 16; bx += 8)
            EXPECT_NEAR(test::meanOver(image, bx, by, bx + 8, by + 8).y, expected, 0.05f * expected);
}

INSTANTIATE_TEST_SUITE_P(Integrators, Furnace,
                         ::testing::Values(FurnaceCase{IntegratorKind::Sppm, DirectLighting::LightSampling, 0.5f},
                                           FurnaceCase{IntegratorKind::Sppm, DirectLighting::Photons, 0.5f},
                                           FurnaceCase{IntegratorKind::Sppm, DirectLighting::LightSampling, 0.8f},
                                           FurnaceCase{IntegratorKind::Path, DirectLighting::LightSampling, 0.8f}));

}  // namespace
}  // namespace photon
