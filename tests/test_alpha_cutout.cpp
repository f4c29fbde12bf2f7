// Alpha cutouts against hand-built geometry: a quad whose left half is cut away by its
// alpha texture renders as the right half alone (camera, shadow and photon rays all pass
// the cut), and a constant alpha a lets 1 - a of the light through.
#include <gtest/gtest.h>
#include <photon/render.h>
#include "integrators/integrator.h"
#include "scene_builders.h"
#include "scene_loader_fixture.h"
#include "test_support.h"
#include "texture/textures.h"

namespace photon {
namespace {

constexpr int kResolution = 48;

// A floor under a point light, with a 1 x 1 occluder halfway between (u along +x, v along -z).
SceneDescription occludedFloor(ShapeDescription occluder, IntegratorKind kind) {
    SceneDescription d = test::pointLightPlane(0.5f, 10.0f, 1.0f, kResolution, 2.0f);
    d.materials.push_back(makeDiffuse(Color(0.6f, 0.3f, 0.2f)));
    occluder.material = 1;
    d.shapes.push_back(std::move(occluder));
    d.render.integrator = kind;
    d.render.passes = 16;
    d.render.photonsPerPass = 20000;
    d.render.seed = 5;
    return d;
}

double meanLuminance(const Image& image) { return luminance(test::meanOver(image, 0, 0, image.width, image.height)); }

// Mean over pixels of |a - b|, relative to b's mean.
double relativeDifference(const Image& a, const Image& b) {
    double sum = 0;
    for (int y = 0; y < a.height; ++y)
        for (int x = 0; x < a.width; ++x) sum += std::abs(luminance(a.at(x, y)) - luminance(b.at(x, y)));
    return sum / (a.width * a.height) / meanLuminance(b);
}

class CutoutVsGeometry : public testing::TestWithParam<IntegratorKind> {};

TEST_P(CutoutVsGeometry, HalfCutQuadRendersAsTheOtherHalf) {
    ShapeDescription cut = test::quad({-0.5f, 0.5f, 0.5f}, {1, 0, 0}, {0, 0, -1}, 0);
    cut.alpha = FloatParam(makeCheckerboardTexture(Color(0.0f), Color(1.0f), UvMapping{{2, 1}, {0, 0}}));
    ShapeDescription half = test::quad({0, 0.5f, 0.5f}, {0.5f, 0, 0}, {0, 0, -1}, 0);
    ShapeDescription whole = test::quad({-0.5f, 0.5f, 0.5f}, {1, 0, 0}, {0, 0, -1}, 0);
    Image withCut = test::renderImage(occludedFloor(cut, GetParam()));
    Image withHalf = test::renderImage(occludedFloor(half, GetParam()));
    Image withWhole = test::renderImage(occludedFloor(whole, GetParam()));
    double cutVsHalf = relativeDifference(withCut, withHalf), wholeVsHalf = relativeDifference(withWhole, withHalf);
    std::printf("  mean |cut - half| %.5f, |whole - half| %.5f of the mean\n", cutVsHalf, wholeVsHalf);
    // The same random numbers meet the same surfaces except along the cut's edge.
    EXPECT_LT(cutVsHalf, 0.01);
    EXPECT_NEAR(meanLuminance(withCut), meanLuminance(withHalf), 0.003 * meanLuminance(withHalf));
    EXPECT_GT(wholeVsHalf, 20 * cutVsHalf);  // the comparison can tell the shapes apart
}

INSTANTIATE_TEST_SUITE_P(Integrators, CutoutVsGeometry, testing::Values(IntegratorKind::Path, IntegratorKind::Sppm),
                         [](const testing::TestParamInfo<IntegratorKind>& info) {
                             return info.param == IntegratorKind::Path ? std::string("Path") : std::string("Sppm");
                         });

// A solid texture is read at the point the ray meets (Embree's filter computes it from the
// ray): a solid checkerboard whose cells split the quad at x = 0 cuts its left half away as
// the uv checkerboard above does, for camera, shadow and photon rays alike.
TEST(AlphaCutout, ASolidTextureCutsWhereTheRayMeetsTheSurface) {
    // Texture space: x as it is; y and z squashed into the cell [0, 1) over the quad.
    Transform textureFromWorld;
    textureFromWorld.m = {1, 0, 0, 0, 0, 0, 0, 0.5f, 0, 0, 0.01f, 0.5f};
    ShapeDescription cut = test::quad({-0.5f, 0.5f, 0.5f}, {1, 0, 0}, {0, 0, -1}, 0);
    cut.alpha = FloatParam(makeSolidCheckerboardTexture(Color(1.0f), Color(0.0f), textureFromWorld));
    ShapeDescription half = test::quad({0, 0.5f, 0.5f}, {0.5f, 0, 0}, {0, 0, -1}, 0);
    for (IntegratorKind kind : {IntegratorKind::Path, IntegratorKind::Sppm}) {
        Image withCut = test::renderImage(occludedFloor(cut, kind));
        Image withHalf = test::renderImage(occludedFloor(half, kind));
        const double cutVsHalf = relativeDifference(withCut, withHalf);
        std::printf("  mean |solid cut - half| %.5f of the mean\n", cutVsHalf);
        EXPECT_LT(cutVsHalf, 0.01);
        EXPECT_NEAR(meanLuminance(withCut), meanLuminance(withHalf), 0.003 * meanLuminance(withHalf));
    }
}

// A black occluder of constant alpha 0.3 over the floor's centre: the floor under it gets
// 0.7 of the light it gets without the occluder (the occluder reflects nothing).
TEST(AlphaCutout, ConstantAlphaTransmitsTheRest) {
    ShapeDescription veil = test::quad({-1.5f, 0.5f, 1.5f}, {3, 0, 0}, {0, 0, -3}, 0);
    veil.alpha = 0.3f;
    auto render = [&](bool withVeil) {
        SceneDescription d = occludedFloor(veil, IntegratorKind::Path);
        d.materials[1] = makeDiffuse(Color(0.0f));
        if (!withVeil) d.shapes.pop_back();
        d.render.passes = 256;
        return test::renderImage(std::move(d));
    };
    // The camera sees the floor through the veil too: (0.7 of the light) x (0.7 of the view).
    Color veiled = test::meanOver(render(true), 16, 16, 32, 32), open = test::meanOver(render(false), 16, 16, 32, 32);
    EXPECT_NEAR(veiled.x, 0.49f * open.x, 0.01f * open.x);
    std::printf("  veiled / open %.4f (expected 0.49)\n", veiled.x / open.x);
}

TEST(AlphaCutout, SceneJsonReadsTheAlphaChannel) {
    using namespace test;
    const fs::path dir = fixture().scene / "textures";
    writeImage<uint8_t>(dir / "leaf.png", 2, 1, 4, {0, 255, 0, 0, 0, 255, 0, 255});
    Json doc = fullScene();
    doc["shapes"][0]["alpha"] = Json::parse(R"({"texture": "textures/leaf.png"})");
    doc["shapes"][1]["alpha"] = 0.25;
    SceneDescription s = load(doc);
    EXPECT_FLOAT_EQ(s.shapes[0].alpha.eval({0.25f, 0.5f}), 0.0f);
    EXPECT_FLOAT_EQ(s.shapes[0].alpha.eval({0.75f, 0.5f}), 1.0f);
    EXPECT_FLOAT_EQ(s.shapes[1].alpha.eval({0.5f, 0.5f}), 0.25f);
    EXPECT_FLOAT_EQ(s.shapes[2].alpha.eval({0.5f, 0.5f}), 1.0f);
    expectError([](Json& d) { d["shapes"][5]["alpha"] = 0.5; }, "shapes[5].alpha",
                "an emissive shape cannot have an alpha below 1");
    expectError([](Json& d) { d["shapes"][1]["alpha"] = 1.5; }, "shapes[1].alpha", "must be in [0, 1]");
}

}  // namespace
}  // namespace photon
