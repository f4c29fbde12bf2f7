// Media given by their look (description/medium_reflectance.h): a diffuse reflectance, which
// may be a texture read where a path enters (scene/medium_palette.h), and a mean free path;
// and walks under a surface that count as one vertex (MediumDescription::subsurface).
#include <gtest/gtest.h>
#include <cmath>
#include <cstdio>
#include "media/diffusion_dipole.h"
#include "test_support.h"

namespace photon::subsurface_reflectance_tests {
namespace {

constexpr float kIor = 1.33f;
constexpr int kSteps = MediumPalettes::kSteps;

std::shared_ptr<const Texture> image(int width, std::vector<Color> texels) {
    return std::make_shared<ImageTexture>(width, 1, std::move(texels));
}

// A medium of the reflectance (a colour or a texture) and mean free path, its coefficients
// those of the reflectance's mean, as the scene loader gives them.
MediumDescription mediumOf(ColorParam reflectance, Color meanFreePath, bool subsurface = true) {
    auto look = std::make_shared<MediumReflectance>();
    look->reflectance = reflectance;
    look->meanFreePath = meanFreePath;
    look->boundaryIor = kIor;
    const ScatteringCoefficients c = coefficientsOfReflectance(reflectance.average(), meanFreePath, kIor);
    MediumDescription m;
    m.name = "skin";
    m.absorption = c.absorption;
    m.scattering = c.scattering;
    m.reflectance = std::move(look);
    m.subsurface = subsurface;
    return m;
}

// A ball of radius 1 of `medium` behind smooth glass of index 1.33 in a white sky of
// radiance 1, seen from outside at 16 x 16: the ball fills the middle 8 x 8 pixels.
SceneDescription ballInSky(IntegratorKind kind, MediumDescription medium, int passes, int maxDepth) {
    SceneDescription d;
    d.camera = test::camera({0, 0, 4}, {0, 0, 0}, {0, 1, 0}, 20, 16, 16);
    d.materials = {makeDielectric(kIor), makeDiffuse(Color(0.5f))};
    d.materialNames = {"skin", "floor"};
    d.media = {std::move(medium)};
    d.shapes = {test::sphere({0, 0, 0}, 1.0f, 0)};
    d.shapes[0].insideMedium = 0;
    LightDescription sky;
    sky.kind = LightDescription::Kind::Environment;
    sky.radiance = Color(1.0f);
    d.lights = {sky};
    d.render.integrator = kind;
    d.render.passes = passes;
    d.render.maxDepth = maxDepth;
    d.render.photonsPerPass = 4000;
    d.render.adaptivePhotons = false;
    d.render.volumePhotons = VolumePhotons::Never;
    return d;
}

// The same ball on a grey floor, lit only by a square light up to one side: the ball's
// shadow, centred on (-1, -1, 0), has only the light that went through the ball.
SceneDescription ballOverFloor(MediumDescription medium) {
    SceneDescription d = ballInSky(IntegratorKind::Path, std::move(medium), 1, 8);
    d.lights.clear();
    d.camera = test::camera({0, 4, 4}, {-0.5f, -1, 0}, {0, 1, 0}, 50, 16, 16);
    d.shapes.push_back(test::quad({-4, -1, -4}, {0, 0, 8}, {8, 0, 0}, 1));
    // Facing (-1, -1, 0): u x v is the emitting side's normal.
    const float a = 1.0f / std::sqrt(2.0f);
    d.shapes.push_back(test::quad(Vec3{2.5f, 2.5f, 0} - Vec3{0, 0, 1} - Vec3{-a, a, 0}, {0, 0, 2}, Vec3{-a, a, 0} * 2.0f, 1,
                                  Color(8.0f)));
    return d;
}

Color ballMean(const Image& image) { return test::meanOver(image, 4, 4, 12, 12); }

// The dipole inverted: the albedo found gives back the reflectance; none without
// scattering, all of it without absorption.
TEST(SubsurfaceReflectance, TheAlbedoGivesBackTheReflectance) {
    for (double r : {0.01, 0.2, 0.5, 0.8, 0.99})
        EXPECT_NEAR(dipoleDiffuseReflectance(albedoOfDiffuseReflectance(r, kIor), kIor), r, 1e-9) << r;
    EXPECT_NEAR(dipoleDiffuseReflectance(0, 1.5), 0, 1e-12);
    EXPECT_NEAR(dipoleDiffuseReflectance(1, 1.5), 1, 1e-12);
    const ScatteringCoefficients c = coefficientsOfReflectance({0.5f, 0.2f, 0.8f}, {0.1f, 0.2f, 0.4f}, kIor);
    EXPECT_NEAR(c.absorption.y + c.scattering.y, 5.0f, 1e-5f);
}

// A texture of one reflectance that lies on one of the palette's steps gives every path
// the medium of that constant reflectance, whose coefficients are the same floats: the
// same image, bit for bit, from both integrators.
TEST(SubsurfaceReflectance, ATextureOfOneStepRendersAsThatColour) {
    const Color r(16.0f / kSteps, 8.0f / kSteps, 24.0f / kSteps);
    for (IntegratorKind kind : {IntegratorKind::Path, IntegratorKind::Sppm}) {
        const Image constant = test::renderImage(ballInSky(kind, mediumOf(r, Color(0.2f)), 16, 12));
        const Image textured = test::renderImage(ballInSky(kind, mediumOf(ColorParam(image(1, {r})), Color(0.2f)), 16, 12));
        ASSERT_EQ(constant.rgb.size(), textured.rgb.size());
        size_t differ = 0;
        for (size_t i = 0; i < constant.rgb.size(); ++i) differ += constant.rgb[i] != textured.rgb[i];
        EXPECT_EQ(differ, 0u) << "integrator " << int(kind);
        EXPECT_GT(ballMean(constant).y, 0.05f);
    }
}

// A reflectance half way between two steps is dithered to each with odds one half, so the
// image is that of the reflectance itself (the dipole's curvature over one step is below the
// noise here), not of either step: the steps below are 8%, 5% and 11% darker in reflectance.
TEST(SubsurfaceReflectance, DitheringKeepsAReflectanceBetweenSteps) {
    const Color r(6.5f / kSteps, 9.5f / kSteps, 4.5f / kSteps);
    const Color constant = ballMean(test::renderImage(ballInSky(IntegratorKind::Path, mediumOf(r, Color(0.2f)), 1024, 12)));
    const Color textured = ballMean(
        test::renderImage(ballInSky(IntegratorKind::Path, mediumOf(ColorParam(image(1, {r})), Color(0.2f)), 1024, 12)));
    const Color below = ballMean(test::renderImage(
        ballInSky(IntegratorKind::Path, mediumOf(Color(6.0f / kSteps, 9.0f / kSteps, 4.0f / kSteps), Color(0.2f)), 1024, 12)));
    std::printf("  constant %.4f %.4f %.4f  textured %.4f %.4f %.4f  a step below %.4f %.4f %.4f\n", constant.x,
                constant.y, constant.z, textured.x, textured.y, textured.z, below.x, below.y, below.z);
    for (int c = 0; c < 3; ++c) {
        EXPECT_NEAR(textured[c], constant[c], 0.01f * constant[c]) << c;
        EXPECT_GT(constant[c] - below[c], 0.02f * constant[c]) << c;  // what the test can tell apart
    }
}

// A ball whose reflectance is 0.8 on one side and 0.2 on the other (the seam down the
// middle of the view): each camera path walks in the medium of the reflectance where it
// entered, so away from the seam each side looks as a ball of its reflectance throughout.
TEST(SubsurfaceReflectance, EachPathWalksInTheReflectanceWhereItEnters) {
    // The sphere's u = 0.5 + atan2(z, x) / 2 pi: the side facing the camera (z > 0) is u in
    // (0.5, 1), x > 0 below u = 0.75 (texels 0-47 of 64) and x < 0 above.
    const Color bright(0.8f), dark(0.2f, 0.3f, 0.25f);
    std::vector<Color> texels(64, bright);
    for (int i = 48; i < 64; ++i) texels[size_t(i)] = dark;
    const Color mfp(0.1f);
    for (IntegratorKind kind : {IntegratorKind::Path, IntegratorKind::Sppm}) {
        const int passes = 256;
        const Image textured = test::renderImage(ballInSky(kind, mediumOf(ColorParam(image(64, texels)), mfp), passes, 12));
        const Image allBright = test::renderImage(ballInSky(kind, mediumOf(bright, mfp), passes, 12));
        const Image allDark = test::renderImage(ballInSky(kind, mediumOf(dark, mfp), passes, 12));
        // Columns 4-5 show x < 0 (dark), 10-11 x > 0 (bright), rows 5-10.
        const Color left = test::meanOver(textured, 4, 5, 6, 11), right = test::meanOver(textured, 10, 5, 12, 11);
        const Color leftDark = test::meanOver(allDark, 4, 5, 6, 11), rightBright = test::meanOver(allBright, 10, 5, 12, 11);
        std::printf("  integrator %d: dark side %.4f / %.4f, bright side %.4f / %.4f (green)\n", int(kind), left.y,
                    leftDark.y, right.y, rightBright.y);
        for (int c = 0; c < 3; ++c) {
            EXPECT_NEAR(left[c], leftDark[c], 0.03f * leftDark[c]) << int(kind) << ", channel " << c;
            EXPECT_NEAR(right[c], rightBright[c], 0.03f * rightBright[c]) << int(kind) << ", channel " << c;
        }
        EXPECT_GT(rightBright.y, 1.3f * leftDark.y);
    }
}

// A lossless ball (reflectance 1: albedo 1) in a white sky is as white as the sky, thick (20
// mean free paths in radius, index 1.33) or thin (3, index 1.5). Its paths scatter hundreds
// of times under the surface and reflect off its inside many times: a walk that counts as
// one vertex leaves it white at a max_depth of 12; counted vertex by vertex, it is cut short.
// Light comes in by a lobe that is exact under light alike from every direction
// (materials/subsurface_boundary.cpp), so the furnace is white.
TEST(SubsurfaceReflectance, AWalkUnderTheSurfaceIsOneVertex) {
    struct Ball {
        float meanFreePath, ior;
    };
    for (const Ball ball : {Ball{0.05f, 1.33f}, Ball{0.3f, 1.5f}})
        for (IntegratorKind kind : {IntegratorKind::Path, IntegratorKind::Sppm}) {
            auto render = [&](bool subsurface, int passes) {
                SceneDescription d = ballInSky(kind, mediumOf(Color(1.0f), Color(ball.meanFreePath), subsurface), passes, 12);
                d.materials[0] = makeDielectric(ball.ior);
                return ballMean(test::renderImage(std::move(d)));
            };
            const Color walk = render(true, 256), cut = render(false, 64);
            std::printf("  mean free path %.2f, integrator %d: one vertex %.4f %.4f %.4f, vertex by vertex %.4f\n",
                        ball.meanFreePath, int(kind), walk.x, walk.y, walk.z, cut.y);
            // Over 12 seeds SPPM reads 0.9998 and 0.9997 (deviations 0.14% and 0.26% a
            // seed), the path tracer 1.0009 and 1.0043 (0.34% and 0.55%): held to 1% and 2%.
            const float bound = kind == IntegratorKind::Sppm ? 0.01f : 0.02f;
            for (int c = 0; c < 3; ++c) EXPECT_NEAR(walk[c], 1.0f, bound) << int(kind) << ", channel " << c;
            if (ball.meanFreePath < 0.1f) EXPECT_LT(cut.y, 0.9f);
        }
}

// Light under the skin as the volume it is: a ball of pbrt-v4's Skin1 at scale 50 (sssdragon's
// material, which absorbs: sigma_a 1.6-24, sigma_s 37-50.5 a unit) behind glass of index 1.5,
// in a white sky. As a subsurface medium (light in by the Fresnel lobe, the walk one vertex,
// max_depth 5 as sssdragon renders) it looks as the same volume rendered exactly (refracted
// in and out, every event a vertex, max_depth 1,000), within 1.5% per channel; with its
// events counted at max_depth 5 it was 39%, 66% and 85% of it.
TEST(SubsurfaceReflectance, ASubsurfaceBallLooksAsTheVolumeItIs) {
    MediumDescription skin;
    skin.name = "Skin1";
    skin.absorption = Color(1.6f, 8.5f, 24.0f);
    skin.scattering = Color(37.0f, 44.0f, 50.5f);
    auto render = [&](bool subsurface, int maxDepth) {
        MediumDescription m = skin;
        m.subsurface = subsurface;
        SceneDescription d = ballInSky(IntegratorKind::Path, std::move(m), 4096, maxDepth);
        d.materials[0] = makeDielectric(1.5f);
        return ballMean(test::renderImage(std::move(d)));
    };
    const Color subsurface = render(true, 5), volume = render(false, 1000);
    std::printf("  subsurface %.4f %.4f %.4f, volume %.4f %.4f %.4f\n", subsurface.x, subsurface.y, subsurface.z,
                volume.x, volume.y, volume.z);
    for (int c = 0; c < 3; ++c) EXPECT_NEAR(subsurface[c], volume[c], 0.015f * volume[c]) << c;
}

// Photons walk under the surface as camera paths do, however many times they scatter: a
// floor in the shadow of a ball that lets light through (a texture between steps), lit only
// through it there, agrees between SPPM (photons that walk through the ball) and the path
// tracer (paths from the floor through the ball to the light).
TEST(SubsurfaceReflectance, SppmAgreesWithThePathTracerUnderATexturedBall) {
    const Color r(26.5f / kSteps, 28.5f / kSteps, 30.5f / kSteps);
    SceneDescription path = ballOverFloor(mediumOf(ColorParam(image(1, {r})), Color(0.3f))), sppm = path;
    path.render.passes = 4096;
    sppm.render.integrator = IntegratorKind::Sppm;
    sppm.render.passes = 1024;
    sppm.render.photonsPerPass = 8000;
    const Image a = test::renderImage(std::move(path)), b = test::renderImage(std::move(sppm));
    // Blocks of 8 x 8 pixels: the ball's shadow in the upper left, the floor in front of it
    // in the lower left, the ball on the right. In the shadow the path tracer finds the light
    // only by its paths' BSDF samples after the walk: over seeds 1-3 its mean there moved by
    // 4% (0.0342, 0.0336, 0.0328 against SPPM's 0.0335, 0.0334, 0.0344), elsewhere by 1%.
    for (int y = 0; y < 16; y += 8)
        for (int x = 0; x < 16; x += 8) {
            const Color p = test::meanOver(a, x, y, x + 8, y + 8), q = test::meanOver(b, x, y, x + 8, y + 8);
            std::printf("  block (%d, %d): path %.4f %.4f %.4f sppm %.4f %.4f %.4f\n", x, y, p.x, p.y, p.z, q.x, q.y, q.z);
            const float tolerance = x == 0 && y == 0 ? 0.06f : 0.03f;
            for (int c = 0; c < 3; ++c) EXPECT_NEAR(q[c], p[c], tolerance * p[c]) << x << ", " << y << ", channel " << c;
        }
}

// The palette's dither is hashed from the point and the walks draw from their paths' own
// numbers: a textured ball over a floor renders the same image, bit for bit, on one thread
// and on two, by both integrators.
TEST(SubsurfaceReflectance, TheSameImageOnAnyNumberOfThreads) {
    std::vector<Color> texels(16);
    for (int i = 0; i < 16; ++i) texels[size_t(i)] = Color(0.1f + 0.05f * float(i), 0.5f, 0.9f - 0.05f * float(i));
    for (IntegratorKind kind : {IntegratorKind::Path, IntegratorKind::Sppm}) {
        SceneDescription d = ballOverFloor(mediumOf(ColorParam(image(16, texels)), Color(0.3f)));
        d.render.integrator = kind;
        d.render.passes = 6;
        d.render.photonsPerPass = 4000;
        const Image one = test::renderWithThreads(d, 1), two = test::renderWithThreads(d, 2);
        EXPECT_EQ(one.rgb, two.rgb) << int(kind);
    }
}

}  // namespace
}  // namespace photon::subsurface_reflectance_tests
