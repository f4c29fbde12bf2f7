// One channel of an image ("channel": "r", "g", "b" or "a", read as stored, never through
// the sRGB curve) and alpha masks ("alpha_cutoff": opaque exactly where the alpha reaches
// the cutoff), through the JSON loader and Embree's ray queries.
#include <gtest/gtest.h>
#include <cmath>
#include <photon/errors.h>
#include "import/pbrt/pbrt_import.h"
#include "scene/scene.h"
#include "scene/scene_loader.h"
#include "scene_loader_fixture.h"

namespace photon {
namespace {

using test::Json;

struct Folder {
    test::fs::path dir = test::fs::temp_directory_path() / ("photon-channels-" + std::to_string(::getpid()));
    Folder() {
        // One RGBA texel (51, 102, 153, 204): 0.2, 0.4, 0.6, 0.8 as stored.
        test::writeImage<uint8_t>(dir / "packed.png", 1, 1, 4, {51, 102, 153, 204});
        test::writeImage<uint8_t>(dir / "rgb.png", 1, 1, 3, {51, 102, 153});
        test::writeImage<uint8_t>(dir / "packed.tga", 1, 1, 4, {51, 102, 153, 204});
        test::writeImage<uint8_t>(dir / "packed.tif", 1, 1, 4, {51, 102, 153, 204});
        // Red on the left half (u < 0.5), blue on the right.
        test::writeImage<uint8_t>(dir / "halves.png", 2, 1, 3, {255, 0, 0, 0, 0, 255});
        // Alpha rising along u, texel centres 0.3 and 0.7 symmetric about 0.5 (77 + 178 = 255).
        test::writeImage<uint8_t>(dir / "ramp.png", 4, 1, 4,
                                  {9, 9, 9, 26, 9, 9, 9, 77, 9, 9, 9, 178, 9, 9, 9, 229});
    }
    ~Folder() {
        std::error_code ec;
        test::fs::remove_all(dir, ec);
    }
};

const Folder& folder() {
    static Folder f;
    return f;
}

// A unit quad in z = 0 (uv = (x, y)) with `shape` fields added, under a point light.
SceneDescription quadScene(const Json& extra) {
    Json shape = {{"type", "quad"}, {"origin", {0, 0, 0}}, {"edge_u", {1, 0, 0}}, {"edge_v", {0, 1, 0}}, {"material", "m"}};
    shape.update(extra);
    Json doc = {{"camera", {{"position", {0.5, 0.5, 3}}, {"look_at", {0.5, 0.5, 0}}, {"fov", 30}}},
                {"materials", {{"m", {{"type", "diffuse"}}}}},
                {"shapes", {shape}},
                {"lights", {{{"type", "point"}, {"position", {0, 0, 2}}, {"intensity", {1, 1, 1}}}}}};
    return loadSceneJson(doc.dump(), folder().dir);
}

float alphaAt(const Json& alpha) { return quadScene({{"alpha", alpha}}).shapes[0].alpha.eval({0.5f, 0.5f}); }

TEST(TextureChannels, EachChannelReadsAsStored) {
    EXPECT_NEAR(alphaAt({{"texture", "packed.png"}, {"channel", "r"}}), 0.2f, 1e-6f);
    EXPECT_NEAR(alphaAt({{"texture", "packed.png"}, {"channel", "g"}}), 0.4f, 1e-6f);
    EXPECT_NEAR(alphaAt({{"type", "image"}, {"file", "packed.png"}, {"channel", "b"}}), 0.6f, 1e-6f);
    EXPECT_NEAR(alphaAt({{"texture", "packed.png"}, {"channel", "a"}}), 0.8f, 1e-6f);
    // An image without alpha is opaque; without "channel" a cutout reads the alpha channel.
    EXPECT_EQ(alphaAt({{"texture", "rgb.png"}, {"channel", "a"}}), 1.0f);
    EXPECT_NEAR(alphaAt({{"texture", "packed.png"}}), 0.8f, 1e-6f);
}

// "encoding": "linear" reads an 8-bit colour as stored; by default it goes through the sRGB
// curve (51 / 255 = 0.2 stored is 0.0331 linear).
TEST(TextureChannels, EncodingLinearSkipsTheSrgbCurve) {
    auto albedoAt = [](const Json& texture) {
        Json doc = {{"camera", {{"position", {0, 0, 3}}, {"look_at", {0, 0, 0}}, {"fov", 30}}},
                    {"materials", {{"m", {{"type", "diffuse"}, {"albedo", texture}}}}},
                    {"shapes", {{{"type", "sphere"}, {"center", {0, 0, 0}}, {"radius", 1}, {"material", "m"}}}},
                    {"lights", {{{"type", "point"}, {"position", {0, 0, 2}}, {"intensity", {1, 1, 1}}}}}};
        return loadSceneJson(doc.dump(), folder().dir).materials[0]->tint().eval({0.5f, 0.5f});
    };
    EXPECT_NEAR(albedoAt({{"texture", "rgb.png"}, {"encoding", "linear"}}).x, 0.2f, 1e-6f);
    EXPECT_NEAR(albedoAt({{"texture", "rgb.png"}, {"encoding", "srgb"}}).x, 0.0331f, 1e-4f);
    EXPECT_NEAR(albedoAt({{"texture", "rgb.png"}}).x, 0.0331f, 1e-4f);
    // "gamma": 0.2^2.2 = 0.02902, 0.4^2.2, 0.6^2.2.
    const Color gamma = albedoAt({{"texture", "rgb.png"}, {"encoding", "gamma"}, {"gamma", 2.2}});
    EXPECT_NEAR(gamma.x, std::pow(0.2f, 2.2f), 1e-5f);
    EXPECT_NEAR(gamma.z, std::pow(0.6f, 2.2f), 1e-5f);
    auto errorPath = [&](const Json& texture) {
        try {
            albedoAt(texture);
        } catch (const SceneError& e) {
            return e.path();
        }
        return std::string("loaded");
    };
    EXPECT_EQ(errorPath({{"texture", "rgb.png"}, {"encoding", "gamma"}}), "materials.m.albedo.gamma");
    EXPECT_EQ(errorPath({{"texture", "rgb.png"}, {"encoding", "log"}}), "materials.m.albedo.encoding");
    EXPECT_EQ(errorPath({{"texture", "rgb.png"}, {"gamma", 2.2}}), "materials.m.albedo.gamma");
}

// "uv_rotation" turns the lookup counter-clockwise (v up) after the scale: at 90 degrees
// uv (0.25, 0.25) reads (-0.25, 0.25), the right (blue) half; (0.25, 0.75) reads (-0.75,
// 0.25), the left (red) half.
TEST(TextureChannels, UvRotationTurnsTheLookup) {
    auto colourAt = [](const Json& texture, Vec2 uv) {
        Json doc = {{"camera", {{"position", {0, 0, 3}}, {"look_at", {0, 0, 0}}, {"fov", 30}}},
                    {"materials", {{"m", {{"type", "diffuse"}, {"albedo", texture}}}}},
                    {"shapes", {{{"type", "sphere"}, {"center", {0, 0, 0}}, {"radius", 1}, {"material", "m"}}}},
                    {"lights", {{{"type", "point"}, {"position", {0, 0, 2}}, {"intensity", {1, 1, 1}}}}}};
        return loadSceneJson(doc.dump(), folder().dir).materials[0]->tint().eval({uv});
    };
    const Json turned = {{"texture", "halves.png"}, {"uv_rotation", 90}};
    EXPECT_GT(colourAt({{"texture", "halves.png"}}, {0.25f, 0.25f}).x, 0.9f);
    EXPECT_GT(colourAt(turned, {0.25f, 0.25f}).z, 0.9f);
    EXPECT_GT(colourAt(turned, {0.25f, 0.75f}).x, 0.9f);
}

TEST(TextureChannels, ChannelsOfOneImageAreCachedApart) {
    SceneDescription d = quadScene({{"alpha", {{"type", "product"},
                                               {"a", {{"texture", "packed.png"}, {"channel", "r"}}},
                                               {"b", {{"texture", "packed.png"}, {"channel", "b"}}}}}});
    EXPECT_NEAR(d.shapes[0].alpha.eval({0.5f, 0.5f}), 0.2f * 0.6f, 1e-6f);
}

TEST(TextureChannels, ColourWithoutChannelStaysSrgb) {
    auto srgb = ImageTexture::load(folder().dir / "packed.png");
    auto g = ImageTexture::load(folder().dir / "packed.png", ImageChannels::G);
    EXPECT_NEAR(srgb->texel(0, 0).y, 0.1329f, 1e-3f);  // sRGB 0.4 decoded
    EXPECT_NEAR(g->texel(0, 0).x, 0.4f, 1e-6f);
    EXPECT_NEAR(g->texel(0, 0).z, 0.4f, 1e-6f);
}

TEST(TextureChannels, UnknownChannelIsRefused) {
    try {
        alphaAt({{"texture", "packed.png"}, {"channel", "x"}});
        FAIL() << "accepted";
    } catch (const SceneError& e) {
        EXPECT_STREQ(e.what(), "shapes[0].alpha.channel: unknown channel \"x\" (expected one of r, g, b, a)");
    }
}

// Rays straight down onto the quad at u = x: does each one stop there?
std::vector<bool> stops(const SceneDescription& d, const std::vector<float>& xs) {
    auto scene = Scene::build(d);
    std::vector<bool> out;
    for (float x : xs) {
        SurfaceHit hit;
        out.push_back(scene->intersect(Ray{{x, 0.5f, 1}, {0, 0, -1}}, hit));
    }
    return out;
}

TEST(AlphaCutoff, MaskIsOpaqueExactlyWhereAlphaReachesTheCutoff) {
    // Between the texel centres at u = 0.125 and 0.875 the alpha rises monotonically and
    // crosses 0.5 at u = 0.5: every ray left of it passes, every ray right of it stops.
    const SceneDescription d = quadScene({{"alpha", {{"texture", "ramp.png"}}}, {"alpha_cutoff", 0.5}});
    EXPECT_EQ(d.shapes[0].alphaCutoff, 0.5f);
    std::vector<float> xs;
    for (float x = 0.13f; x < 0.87f; x += 0.01f)
        if (std::abs(x - 0.5f) > 0.004f) xs.push_back(x);
    const std::vector<bool> hit = stops(d, xs);
    for (size_t i = 0; i < xs.size(); ++i) EXPECT_EQ(hit[i], xs[i] > 0.5f) << "u = " << xs[i];
    // Without the cutoff the same alpha is a coverage: some rays pass where alpha is 0.7.
    const SceneDescription coverage = quadScene({{"alpha", {{"texture", "ramp.png"}}}});
    std::vector<float> right;
    for (int i = 0; i < 200; ++i) right.push_back(0.6f + 0.001f * float(i % 50));
    const std::vector<bool> covered = stops(coverage, right);
    EXPECT_LT(std::count(covered.begin(), covered.end(), true), 200);
}

// pbrt-v4's float imagemap is its image's first channel (MIPMap's Float texel reads channel
// 0, never alpha), decoded by the texture's encoding: sRGB where not given for a PNG (and a
// TGA, docs/import.md), linear for any other file. Here as a shape's alpha, imported and
// loaded: R stored as 0.2.
TEST(TextureChannels, PbrtFloatImagemapReadsItsFirstChannelThroughItsEncoding) {
    const std::string scene = R"(
LookAt 0 0 3  0 0 0  0 1 0
Camera "perspective" "float fov" [30]
WorldBegin
LightSource "point" "rgb I" [1 1 1]
Texture "png" "float" "imagemap" "string filename" "packed.png"
Texture "tga" "float" "imagemap" "string filename" "packed.tga"
Texture "tif" "float" "imagemap" "string filename" "packed.tif"
Texture "lin" "float" "imagemap" "string filename" "packed.png" "string encoding" "linear"
Texture "pow" "float" "imagemap" "string filename" "packed.png" "string encoding" "gamma 2.2"
Shape "sphere" "texture alpha" "png"
Shape "sphere" "texture alpha" "tga"
Shape "sphere" "texture alpha" "tif"
Shape "sphere" "texture alpha" "lin"
Shape "sphere" "texture alpha" "pow"
)";
    test::writeText(folder().dir / "float.pbrt", scene);
    const SceneDescription d = loadImportedScene(importPbrt(folder().dir / "float.pbrt"), folder().dir);
    ASSERT_EQ(d.shapes.size(), 5u);
    EXPECT_NEAR(d.shapes[0].alpha.eval({0.5f, 0.5f}), 0.0331048f, 1e-5f);  // sRGB curve at 0.2
    EXPECT_NEAR(d.shapes[1].alpha.eval({0.5f, 0.5f}), 0.0331048f, 1e-5f);
    EXPECT_NEAR(d.shapes[2].alpha.eval({0.5f, 0.5f}), 0.2f, 1e-6f);
    EXPECT_NEAR(d.shapes[3].alpha.eval({0.5f, 0.5f}), 0.2f, 1e-6f);
    EXPECT_NEAR(d.shapes[4].alpha.eval({0.5f, 0.5f}), std::pow(0.2f, 2.2f), 1e-5f);
}

// In photon's own scenes a channel is data, read as stored, unless an encoding is given.
TEST(TextureChannels, AChannelTakesAnEncodingWhenGiven) {
    EXPECT_NEAR(alphaAt({{"texture", "packed.png"}, {"channel", "g"}, {"encoding", "srgb"}}), 0.1328683f, 1e-5f);
    EXPECT_NEAR(alphaAt({{"texture", "packed.png"}, {"channel", "g"}, {"encoding", "linear"}}), 0.4f, 1e-6f);
    EXPECT_NEAR(alphaAt({{"texture", "packed.png"}, {"channel", "b"}, {"encoding", "gamma"}, {"gamma", 2}}), 0.36f, 1e-5f);
    // Alpha is coverage, stored linearly whatever the encoding.
    EXPECT_NEAR(alphaAt({{"texture", "packed.png"}, {"channel", "a"}, {"encoding", "srgb"}}), 0.8f, 1e-6f);
}

TEST(AlphaCutoff, ConstantAlphaBelowTheCutoffIsInvisible) {
    EXPECT_EQ(stops(quadScene({{"alpha", 0.3}, {"alpha_cutoff", 0.5}}), {0.5f})[0], false);
    EXPECT_EQ(stops(quadScene({{"alpha", 0.6}, {"alpha_cutoff", 0.5}}), {0.5f})[0], true);
}

TEST(AlphaCutoff, RangeAndAlphaAreChecked) {
    auto message = [](const Json& extra) {
        try {
            quadScene(extra);
        } catch (const SceneError& e) {
            return std::string(e.what());
        }
        return std::string("accepted");
    };
    EXPECT_EQ(message({{"alpha", 0.5}, {"alpha_cutoff", 0}}), "shapes[0].alpha_cutoff: must be in (0, 1]");
    EXPECT_EQ(message({{"alpha_cutoff", 0.5}}), "shapes[0].alpha_cutoff: needs \"alpha\"");
}

}  // namespace
}  // namespace photon
