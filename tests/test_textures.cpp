// Texture kinds against their definitions: uv mapping, checkerboard, product, mix, alpha
// channels, float parameters, and the scene JSON that nests them.
#include "scene_loader_fixture.h"
#include "texture/float_param.h"
#include "texture/textures.h"

namespace photon::test {
namespace {

// A 2x2 image, row 0 at the top: red green / blue white (linear values).
std::shared_ptr<const ImageTexture> quadrants() {
    return std::make_shared<ImageTexture>(
        2, 2, std::vector<Color>{Color(1, 0, 0), Color(0, 1, 0), Color(0, 0, 1), Color(1, 1, 1)});
}

TEST(Textures, UvMappingScalesAndShiftsTheLookup) {
    auto image = quadrants();
    UvMapping tiled{{2, 2}, {0, 0}};
    auto t = makeMappedTexture(image, tiled);
    for (Vec2 uv : {Vec2{0.1f, 0.1f}, Vec2{0.3f, 0.8f}, Vec2{0.77f, 0.42f}})
        EXPECT_VEC3_NEAR(t->lookup({uv}), image->lookup({2 * uv.x, 2 * uv.y}), 1e-6);
    // Two whole repeats keep the mean; the identity is the image itself, not a wrapper.
    EXPECT_VEC3_NEAR(t->average(), image->average(), 1e-4);
    EXPECT_EQ(makeMappedTexture(image, UvMapping{}), image);
    auto shifted = makeMappedTexture(image, UvMapping{{1, 1}, {0.5f, 0}});
    EXPECT_VEC3_NEAR(shifted->lookup({0.25f, 0.75f}), Color(0, 1, 0), 1e-6);  // top right texel's centre
}

// Outside the unit square: the image's repeats, its edge texels, or black; the filter keeps
// to the same rule at the edges. Inverted: max(0, 1 - value) (pbrt-v4's "wrap", "invert").
TEST(Textures, WrapModesAndInversion) {
    auto image = quadrants();
    const Vec2 right{1.25f, 0.25f};  // a quarter past the right edge, in the bottom row
    EXPECT_VEC3_NEAR(makeImageLookupTexture(image, ImageWrap::Repeat, false)->lookup({right}), Color(0, 0, 1), 1e-6);
    EXPECT_VEC3_NEAR(makeImageLookupTexture(image, ImageWrap::Clamp, false)->lookup({right}), Color(1, 1, 1), 1e-6);
    EXPECT_VEC3_NEAR(makeImageLookupTexture(image, ImageWrap::Black, false)->lookup({right}), Color(0.0f), 0);
    // At the edge itself the repeat blends with the far side, the clamp does not.
    EXPECT_VEC3_NEAR(image->lookup({0.0f, 0.25f}, ImageWrap::Repeat), Color(1, 1, 1) * 0.5f + Color(0, 0, 1) * 0.5f, 1e-6);
    EXPECT_VEC3_NEAR(image->lookup({0.0f, 0.25f}, ImageWrap::Clamp), Color(0, 0, 1), 1e-6);
    EXPECT_VEC3_NEAR(image->lookup({0.0f, 0.25f}, ImageWrap::Black), Color(0, 0, 1), 1e-6);
    auto inverted = makeImageLookupTexture(image, ImageWrap::Repeat, true);
    EXPECT_VEC3_NEAR(inverted->lookup({{0.25f, 0.25f}}), Color(1, 1, 0), 1e-6);   // blue
    EXPECT_VEC3_NEAR(inverted->lookup({{0.75f, 0.25f}}), Color(0.0f), 1e-6);      // white
    EXPECT_VEC3_NEAR(inverted->average(), Color(1.0f) - image->average(), 1e-4);
    EXPECT_EQ(makeImageLookupTexture(image, ImageWrap::Repeat, false), image);  // no wrapper

    Json doc = fullScene();
    doc["materials"]["white"]["albedo"] =
        Json::parse(R"({"type": "image", "file": "textures/wood.png", "wrap": "clamp", "invert": true})");
    auto wood = ImageTexture::load(fixture().scene / "textures/wood.png");
    const Color edge = wood->lookup({1.0f, 0.4f}, ImageWrap::Clamp);
    EXPECT_VEC3_NEAR(load(doc).materials[0]->tint().eval({{3.0f, 0.4f}}), Color(1.0f) - edge, 1e-6);
    expectError([](Json& d) { d["materials"]["white"]["albedo"] = Json::parse(R"({"texture": "textures/wood.png", "wrap": "mirror"})"); },
                "materials.white.albedo.wrap", "unknown wrap \"mirror\" (expected one of repeat, clamp, black)");
}

TEST(Textures, CheckerboardAlternatesByCellParity) {
    auto t = makeCheckerboardTexture(Color(0.8f), Color(0.1f, 0.2f, 0.3f), UvMapping{{4, 4}, {0, 0}});
    EXPECT_VEC3_NEAR(t->lookup({0.1f, 0.1f}), Color(0.8f), 0);                // cell (0, 0)
    EXPECT_VEC3_NEAR(t->lookup({0.3f, 0.1f}), Color(0.1f, 0.2f, 0.3f), 0);    // cell (1, 0)
    EXPECT_VEC3_NEAR(t->lookup({0.3f, 0.3f}), Color(0.8f), 0);                // cell (1, 1)
    EXPECT_VEC3_NEAR(t->lookup({-0.1f, 0.1f}), Color(0.1f, 0.2f, 0.3f), 0);   // cell (-1, 0)
    EXPECT_VEC3_NEAR(t->lookup({1e12f, 3e11f}), Color(0.8f), 0);              // far away: even cells, no overflow
    // An even number of cells each way: exactly half of each.
    EXPECT_VEC3_NEAR(t->average(), Color(0.45f, 0.5f, 0.55f), 1e-5);
    // The inputs are read at the surface's own uv, not the pattern's.
    auto image = quadrants();
    auto patterned = makeCheckerboardTexture(ColorParam(image), Color(0.0f), UvMapping{{4, 4}, {0, 0}});
    EXPECT_VEC3_NEAR(patterned->lookup({0.1f, 0.1f}), image->lookup({0.1f, 0.1f}), 0);
}

TEST(Textures, ProductAndMix) {
    auto image = quadrants();
    auto product = makeProductTexture(ColorParam(image), Color(0.5f, 2.0f, 1.0f));
    EXPECT_VEC3_NEAR(product->lookup({0.25f, 0.75f}), Color(0.5f, 0, 0), 1e-6);
    EXPECT_VEC3_NEAR(product->average(), image->average() * Color(0.5f, 2.0f, 1.0f), 1e-6);
    // Image times itself: the mean of squares (1/2 in each channel), not the square of the mean (1/4).
    auto square = makeProductTexture(ColorParam(image), ColorParam(image));
    EXPECT_VEC3_NEAR(square->lookup({0.75f, 0.25f}), Color(1, 1, 1), 1e-6);
    // Its mean is the mean of squares, here by an independent 1000 x 1000 grid of the image.
    double sum = 0;
    for (int j = 0; j < 1000; ++j)
        for (int i = 0; i < 1000; ++i) {
            float r = image->lookup({(i + 0.5f) / 1000, (j + 0.5f) / 1000}).x;
            sum += double(r) * r;
        }
    EXPECT_NEAR(square->average().x, sum / 1e6, 1e-4);
    EXPECT_GT(square->average().x, 0.25f + 0.02f);  // not the square of the mean
    auto mix = makeMixTexture(Color(1.0f), Color(0.0f, 0.5f, 1.0f), FloatParam(0.25f));
    EXPECT_VEC3_NEAR(mix->lookup({0.3f, 0.3f}), Color(0.75f, 0.875f, 1.0f), 1e-6);
    EXPECT_VEC3_NEAR(mix->average(), Color(0.75f, 0.875f, 1.0f), 1e-6);
    // A textured amount: the blue (0) and white (1) quadrants of the image's mean.
    auto byImage = makeMixTexture(Color(0.0f), Color(1.0f), FloatParam(std::shared_ptr<const Texture>(image)));
    EXPECT_NEAR(byImage->lookup({0.25f, 0.25f}).x, 1.0f / 3.0f, 1e-6);  // blue: channel mean 1/3
    EXPECT_NEAR(byImage->lookup({0.75f, 0.25f}).x, 1.0f, 1e-6);         // white
    EXPECT_NEAR(byImage->average().x, 0.5f, 1e-3);  // channel means 1/3, 1/3, 1/3, 1
}

TEST(Textures, AlphaChannelReadLinearly) {
    const fs::path dir = fixture().scene / "textures";
    writeImage<uint8_t>(dir / "cutout.png", 2, 1, 4, {255, 0, 0, 0, 0, 255, 0, 128});
    auto alpha = ImageTexture::load(dir / "cutout.png", ImageChannels::Alpha);
    EXPECT_VEC3_NEAR(alpha->lookup({0.25f, 0.5f}), Color(0.0f), 0);
    EXPECT_VEC3_NEAR(alpha->lookup({0.75f, 0.5f}), Color(128 / 255.0f), 1e-6);  // linear, not sRGB
    EXPECT_VEC3_NEAR(ImageTexture::load(dir / "cutout.png")->lookup({0.75f, 0.5f}), Color(0, 1, 0), 0);
    // Without an alpha channel, an alpha parameter reads the grey level.
    writeImage<uint8_t>(dir / "mask.png", 1, 1, 3, {255, 255, 0});
    EXPECT_NEAR(ImageTexture::load(dir / "mask.png", ImageChannels::Alpha)->average().x, 2.0f / 3.0f, 1e-6);
}

TEST(Textures, SceneJsonNestsTextures) {
    Json doc = fullScene();
    doc["materials"]["white"]["albedo"] = Json::parse(R"({"type": "checkerboard", "uv_scale": [2, 2],
        "even": [0.8, 0.8, 0.8], "odd": {"type": "mix", "a": [0, 0, 0], "b": {"texture": "textures/wood.png"},
                                        "amount": 0.5}})");
    doc["materials"]["metal"]["reflectance"] = Json::parse(
        R"({"type": "product", "a": {"type": "image", "file": "textures/wood.png", "uv_scale": [3, 1]},
            "b": [0.5, 0.5, 0.5]})");
    SceneDescription s = load(doc);
    const ColorParam& checker = s.materials[0]->tint();
    ASSERT_TRUE(checker.textured());
    auto wood = ImageTexture::load(fixture().scene / "textures/wood.png");
    EXPECT_VEC3_NEAR(checker.eval({0.1f, 0.1f}), Color(0.8f), 0);
    EXPECT_VEC3_NEAR(checker.eval({0.6f, 0.1f}), wood->lookup({0.6f, 0.1f}) * 0.5f, 1e-6);
    const ColorParam& metal = s.materials[4]->tint();
    EXPECT_VEC3_NEAR(metal.eval({0.1f, 0.4f}), wood->lookup({0.3f, 0.4f}) * 0.5f, 1e-6);
    EXPECT_TRUE(s.materials[4]->textured());
    // The image is read once for both uses (the scene's texture cache).
    EXPECT_EQ(std::count(s.files.begin(), s.files.end(), "textures/wood.png"), 1);

    expectError([](Json& d) { d["materials"]["white"]["albedo"] = Json::parse(R"({"type": "noise"})"); },
                "materials.white.albedo.type",
                "unknown texture type \"noise\" (expected one of image, checkerboard, bilerp, dots, fbm, wrinkled, windy, marble, "
                "product, mix, direction_mix)");
    expectError([](Json& d) { d["materials"]["white"]["albedo"] = Json::parse(R"({"type": "checkerboard", "even": [2, 0, 0], "odd": [0, 0, 0]})"); },
                "materials.white.albedo.even[0]", "must be in [0, 1]");
    expectError([](Json& d) { d["materials"]["white"]["albedo"] = Json::parse(R"({"type": "mix", "a": [0, 0, 0], "b": [1, 1, 1], "amount": [1, 1, 1]})"); },
                "materials.white.albedo.amount", "must be a number or a texture object");
}

}  // namespace
}  // namespace photon::test
