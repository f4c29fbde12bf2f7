// Light of a point light scattered in a medium toward the camera, sampled along the camera
// rays by equiangular distances (media/equiangular.h, integrators/common/light_along_ray.h,
// render.equiangular): the distances' density, and single scattering around a point light
// inside fog held to its integral.
#include <gtest/gtest.h>
#include <cmath>
#include <algorithm>
#include <cstdio>
#include <functional>
#include <optional>
#include "math/density_grid.h"
#include "math/ray_cone.h"
#include "media/equiangular.h"
#include "media/henyey_greenstein.h"
#include "materials/material.h"
#include "math/rng.h"
#include "scene_builders.h"
#include "test_support.h"

namespace photon {
namespace {

// Over a segment that passes the point beside it, before it, or leaves the scene, the
// density integrates to 1 over [0, end] (midpoint rule in the angle's variable), and 400,000
// samples fall in each of 16 bins of t as often as its integral says, within 4 standard
// errors.
TEST(EquiangularDistances, DensityIntegratesToOneAndSamplesFollowIt) {
    const Vec3 o{0.1f, -0.2f, 0.3f}, d = normalize(Vec3{1.0f, 0.5f, -0.2f});
    struct Case {
        Vec3 point;
        float end;
    };
    for (const Case& c : {Case{o + d * 1.2f + Vec3{0.0f, 0.0f, 0.05f}, 3.0f}, Case{o - d * 2.0f + Vec3{0.3f, 0.0f, 0.0f}, 1.5f},
                          Case{o + d * 0.5f + Vec3{0.0f, 0.4f, 0.1f}, std::numeric_limits<float>::infinity()}}) {
        const std::optional<EquiangularDistances> e = EquiangularDistances::toward(o, d, 0.0f, c.end, c.point);
        ASSERT_TRUE(e.has_value());
        // The bins cover [0, end], or [0, 20] of an infinite segment, whose tail is counted apart.
        const double end = std::isinf(c.end) ? 20.0 : c.end;
        constexpr int kBins = 16, kSteps = 20000, kSamples = 400000;
        std::vector<double> expected(kBins + 1, 0.0);
        double integral = 0;
        for (int i = 0; i < kSteps; ++i) {
            const double t = (i + 0.5) * end / kSteps, p = e->pdf(float(t)) * end / kSteps;
            integral += p;
            expected[std::min(kBins - 1, int(t / end * kBins))] += p;
        }
        expected[kBins] = std::isinf(c.end) ? 1 - integral : 0.0;  // past 20 along an infinite segment
        if (!std::isinf(c.end)) EXPECT_NEAR(integral, 1.0, 2e-4) << "end " << c.end;
        std::vector<int> counts(kBins + 1, 0);
        Rng rng(3, 0, 1, StreamPurpose::Camera);
        for (int i = 0; i < kSamples; ++i) {
            const float t = e->sample(rng.uniform());
            ASSERT_GE(t, 0.0f);
            if (!std::isinf(c.end)) ASSERT_LE(t, c.end * (1 + 1e-5f));
            counts[std::isinf(c.end) && t >= end ? kBins : std::min(kBins - 1, int(t / end * kBins))]++;
        }
        for (int b = 0; b <= kBins; ++b) {
            const double n = expected[b] * kSamples, sigma = std::sqrt(n * (1 - expected[b])) + 1;
            EXPECT_NEAR(counts[b], n, 4 * sigma) << "end " << c.end << ", bin " << b;
        }
    }
}

// Fog filling z in [-1, 1] (wide, bounded by an index-1 dielectric) with point lights
// inside it, seen from above by an orthographic camera whose 8 x 8 pixels cover x, y in
// [-1, 1]: nothing else, and render.max_depth 1, so the image is single scattering. A
// light's share of the image over a part of it is a volume integral over the box B the
// camera sees there (the part's square times z in [-1, 1]),
//   sigma_s int_B exp(-sigma_t (1 - z)) p(w) I(w) exp(-sigma_t r) / r^2 dV,
// with r the distance to the light at l, w the direction from it, I(w) its intensity that
// way and p(w) = HG(-w_z), the phase function between the camera (+z) and the light. Around
// the light dV = r^2 dr dw, the 1 / r^2 cancels, and the integral over r from where the
// direction enters B to where it leaves (r_in, r_out) is analytic:
//   sigma_s int p(w) I(w) exp(-sigma_t (1 - l_z)) (exp(-k r_in) - exp(-k r_out)) / k dw,
// k = sigma_t (1 - w_z), left to the midpoint rule over w (2,000 x 4,000 directions).
const MediumDescription kFog{"fog", Color(0.1f, 0.2f, 0.05f), Color(0.6f, 0.4f, 1.0f), 0.3f};

// A light of the test: where it is, and its intensity toward w (from it); a light of the
// scene's lights, or a small emitting shape (an area light, material 1).
struct FogLight {
    Vec3 position;
    std::function<double(const double w[3])> intensity;
    LightDescription description;
    int pixelX, pixelY;  // the pixel it lies in (rows run down from y = 1)
    std::optional<ShapeDescription> shape{};
    float radius = 0;  // a ball's
};

Color singleScatteringOver(Vec3 lo, Vec3 hi, const FogLight& light) {
    const Color sigmaT = kFog.extinction();
    constexpr int kNu = 2000, kNphi = 4000;
    constexpr double kPi = 3.14159265358979323846;
    const double l[3] = {light.position.x, light.position.y, light.position.z};
    double sum[3] = {0, 0, 0};
    for (int i = 0; i < kNu; ++i) {
        const double wz = -1 + (i + 0.5) * 2.0 / kNu, s = std::sqrt(1 - wz * wz);
        const double p = henyeyGreenstein(float(-wz), kFog.g);
        for (int j = 0; j < kNphi; ++j) {
            const double phi = (j + 0.5) * 2 * kPi / kNphi;
            const double w[3] = {s * std::cos(phi), s * std::sin(phi), wz};
            // Where the direction enters and leaves the box (slabs).
            double rIn = 0, rOut = 1e30;
            for (int a = 0; a < 3; ++a) {
                if (w[a] == 0) {
                    if (l[a] < lo[a] || l[a] > hi[a]) rOut = -1;
                    continue;
                }
                const double t1 = (lo[a] - l[a]) / w[a], t2 = (hi[a] - l[a]) / w[a];
                rIn = std::max(rIn, std::min(t1, t2)), rOut = std::min(rOut, std::max(t1, t2));
            }
            if (!(rOut > rIn)) continue;
            const double intensity = light.intensity(w);
            if (intensity == 0) continue;
            for (int c = 0; c < 3; ++c) {
                const double k = sigmaT[c] * (1 - wz);
                const double along = k > 0 ? (std::exp(-k * rIn) - std::exp(-k * rOut)) / k : rOut - rIn;
                sum[c] += intensity * p * std::exp(-sigmaT[c] * (1 - l[2])) * along;
            }
        }
    }
    const double dw = (2.0 / kNu) * (2 * kPi / kNphi);
    Color integral;
    // Light leaving a ball's surface crosses its radius less fog than from its centre.
    for (int c = 0; c < 3; ++c) integral[c] = float(kFog.scattering[c] * sum[c] * dw * std::exp(sigmaT[c] * light.radius));
    return integral;
}

// A point light of intensity 1 at (0.3, -0.2, 0.1), in pixel (5, 4).
FogLight pointLight() {
    const Vec3 p{0.3f, -0.2f, 0.1f};
    return {p, [](const double*) { return 1.0; }, test::pointLight(p, Color(1.0f), 0), 5, 4};
}

// A spot light at the same place, its beam (25 degrees, full intensity to 20, smoothstep
// between: pbrt-v4's falloff) aimed across the image and down, so that camera rays cross it.
FogLight spotLight() {
    FogLight spot = pointLight();
    const Vec3 axis = normalize(Vec3{-1.0f, 0.3f, -0.5f});
    constexpr float kCone = 25, kFalloff = 20;
    spot.intensity = [axis](const double w[3]) {
        const double c = w[0] * axis.x + w[1] * axis.y + w[2] * axis.z;
        const double c0 = std::cos(kCone * 3.14159265358979323846 / 180), c1 = std::cos(kFalloff * 3.14159265358979323846 / 180);
        const double t = std::clamp((c - c0) / (c1 - c0), 0.0, 1.0);
        return t * t * (3 - 2 * t);
    };
    spot.description.kind = LightDescription::Kind::Spot;
    spot.description.direction = axis;
    spot.description.coneAngleDegrees = kCone;
    spot.description.falloffAngleDegrees = kFalloff;
    return spot;
}

// Area lights at the point light's place, of the same power toward each direction seen
// from afar: a ball of radius 0.01 and radiance 1 / (pi 0.01^2), whose intensity is 1 every
// way (L pi r^2), and a square of side 0.02 facing down, of radiance 1 / 0.02^2, whose
// intensity is cos theta below it. Light samples along the rays go toward points drawn on
// them by area. Close to them they are not points: in the pixels beside the light's (at
// 0.05 from it or more) the ball's cone of directions and the square's extent change the
// integral by well under 0.1% of the image away from the light; but the ball's light,
// leaving its surface, crosses 0.01 less fog on its way than from its centre (+0.6% to
// +1.0% by channel: without that, the ball's images read 1.004 and 1.007 of the integral
// over 8 seeds).
FogLight sphereLight() {
    FogLight ball = pointLight();
    constexpr float kRadius = 0.01f;
    ball.shape = test::sphere(ball.position, kRadius, 1, Color(1.0f / (3.14159265f * kRadius * kRadius)));
    ball.radius = kRadius;
    return ball;
}
FogLight squareLight() {
    FogLight square = pointLight();
    constexpr float kSide = 0.02f;
    const Vec3 u{kSide, 0, 0}, v{0, -kSide, 0};  // u x v faces -z
    square.shape = test::quad(square.position - (u + v) * 0.5f, u, v, 1, Color(1.0f / (kSide * kSide)));
    square.intensity = [](const double w[3]) { return std::max(0.0, -w[2]); };
    return square;
}

// A point light three times as bright at (-0.6, 0.55, -0.4), in pixel (1, 1).
FogLight brighterPointLight() {
    const Vec3 p{-0.6f, 0.55f, -0.4f};
    return {p, [](const double*) { return 3.0; }, test::pointLight(p, Color(3.0f), 0), 1, 1};
}

SceneDescription lightsInFog(IntegratorKind kind, bool equiangular, int passes, uint64_t seed,
                             const std::vector<FogLight>& lights) {
    SceneDescription d;
    d.camera = test::orthographicCamera({0, 0, 3}, {0, 0, 0}, 2.0f, 8, 8);
    d.materials = {makeDielectric(1.0f), makeDiffuse(Color(0.0f))};
    d.materialNames = {"boundary", "emitter"};
    d.media = {kFog};
    d.shapes = test::boxFaces({-50, -50, -1}, {50, 50, 1}, 0, 0);
    for (const FogLight& l : lights) {
        if (l.shape) d.shapes.push_back(*l.shape);
        else d.lights.push_back(l.description);
    }
    d.render.integrator = kind;
    d.render.maxDepth = 1;
    d.render.passes = passes;
    d.render.photonsPerPass = 2000;
    d.render.volumePhotons = VolumePhotons::Never;
    d.render.equiangular = equiangular;
    d.render.seed = seed;
    return d;
}

// Every pixel but the lights', whose radiance grows as 1 / (the ray's distance from the
// light) and is as noisy for any way of sampling the medium: what varies over it is where
// in the pixel the ray goes.
std::vector<bool> awayFromTheLights(const std::vector<FogLight>& lights) {
    std::vector<bool> keep(64, true);
    for (const FogLight& l : lights) keep[size_t(l.pixelY * 8 + l.pixelX)] = false;
    return keep;
}

// The image's mean over the pixels away from the lights against its integral (the whole
// image's less the lights' pixels', over their area): the path tracer at 1,024 passes within
// 1.5%, SPPM at 256 within 1%. Over 12 seeds they read 0.9993 and 1.0008 of it (deviations
// 0.28% and 0.15% a seed) for the point light, 1.0005 and 1.0018 (0.38%, 0.24%) for the
// spot. The light's own pixel is printed, not held: its radiance grows as 1 / (the ray's
// distance from the light), so its variance over where in the pixel the ray goes diverges
// (logarithmically) for any way of sampling the medium; single seeds read 0.72 to 1.45 of
// its integral.
void expectSingleScatteringMatchesTheIntegral(const std::vector<FogLight>& lights) {
    const float pixel = 0.25f;
    const std::vector<bool> keep = awayFromTheLights(lights);
    const int kept = int(std::count(keep.begin(), keep.end(), true));
    Color away(0.0f), atFirst(0.0f);
    for (const FogLight& l : lights) {
        away += singleScatteringOver({-1, -1, -1}, {1, 1, 1}, l);
        for (const FogLight& at : lights) {
            const Vec3 lo{-1 + at.pixelX * pixel, 1 - (at.pixelY + 1) * pixel, -1};
            const Color inPixel = singleScatteringOver(lo, {lo.x + pixel, lo.y + pixel, 1}, l);
            away -= inPixel;
            if (&at == &lights.front()) atFirst += inPixel / (pixel * pixel);
        }
    }
    away /= kept * pixel * pixel;
    std::printf("  integral: away from the lights %.5f %.5f %.5f, at the first %.4f %.4f %.4f\n", away.x, away.y,
                away.z, atFirst.x, atFirst.y, atFirst.z);
    struct Variant {
        IntegratorKind kind;
        int passes;
        float tolerance;
    };
    for (const Variant& v : {Variant{IntegratorKind::Path, 1024, 0.015f}, Variant{IntegratorKind::Sppm, 256, 0.01f}}) {
        const Image image = test::renderImage(lightsInFog(v.kind, true, v.passes, 1, lights));
        Color seenAway(0.0f);
        for (int y = 0; y < 8; ++y)
            for (int x = 0; x < 8; ++x)
                if (keep[size_t(y * 8 + x)]) seenAway += image.at(x, y) / float(kept);
        const Color seenAt = image.at(lights.front().pixelX, lights.front().pixelY);
        std::printf("  %s: away %.4f %.4f %.4f of the integral, at the first light %.3f %.3f %.3f\n",
                    v.kind == IntegratorKind::Path ? "path" : "sppm", seenAway.x / away.x, seenAway.y / away.y,
                    seenAway.z / away.z, seenAt.x / atFirst.x, seenAt.y / atFirst.y, seenAt.z / atFirst.z);
        for (int c = 0; c < 3; ++c)
            EXPECT_NEAR(seenAway[c], away[c], v.tolerance * away[c])
                << lights.size() << " lights, integrator " << int(v.kind) << ", channel " << c;
    }
}

TEST(LightAlongRays, SingleScatteringAroundAPointLightInFogMatchesTheIntegral) {
    expectSingleScatteringMatchesTheIntegral({pointLight()});
}

// The same with a spot light, whose equiangular distances are drawn on the part of each ray
// inside its beam (rayInsideCone).
TEST(LightAlongRays, SingleScatteringAroundASpotLightInFogMatchesTheIntegral) {
    expectSingleScatteringMatchesTheIntegral({spotLight()});
}

// With the spot and a brighter point light elsewhere, each segment picks one of the two by
// what it could bring along the segment (SegmentLightChoice), and the two strategies'
// weights count that choice. Over 12 seeds: 1.0006 (path tracer) and 1.0002 (SPPM) of the
// integral, deviations 0.31% and 0.10% a seed.
TEST(LightAlongRays, SingleScatteringAroundTwoLightsInFogMatchesTheIntegral) {
    expectSingleScatteringMatchesTheIntegral({spotLight(), brighterPointLight()});
}

// Area lights: the ball and the square, with the brighter point light elsewhere. Each
// segment draws a point on the area light by area and distances toward it; the light
// sample where the flight scatters is weighed against both those and the phase function's
// direction, which may meet the light.
TEST(LightAlongRays, SingleScatteringAroundAreaLightsInFogMatchesTheIntegral) {
    expectSingleScatteringMatchesTheIntegral({sphereLight()});
    expectSingleScatteringMatchesTheIntegral({squareLight(), brighterPointLight()});
}

// Both lights at 64 passes, four pairs of seeds each way, over the pixels away from the
// light: equiangular distances take most of the noise of the light near the light away.
// Over 12 sets of seeds the ratio of the relative noise with them to without was 0.12-0.27
// (path tracer) and 0.15-0.27 (SPPM) for the point light, 0.03-0.23 and 0.03-0.14 for the
// spot, whose samples are drawn inside its beam only; for the ball light (radius 0.01),
// 0.67 (path tracer) and 0.58 (SPPM) in one set.
TEST(LightAlongRays, EquiangularSamplesHaveLessNoiseThanFreeFlightsAlone) {
    for (int which : {0, 1, 2, 3})
        for (IntegratorKind kind : {IntegratorKind::Path, IntegratorKind::Sppm}) {
            const char* names[] = {"point light", "spot light", "two lights", "ball light"};
            const char* name = names[which];
            const std::vector<FogLight> lights = which == 0   ? std::vector<FogLight>{pointLight()}
                                                 : which == 1 ? std::vector<FogLight>{spotLight()}
                                                 : which == 2 ? std::vector<FogLight>{spotLight(), brighterPointLight()}
                                                              : std::vector<FogLight>{sphereLight()};
            const std::vector<bool> keep = awayFromTheLights(lights);
            // Pooled over four pairs of seeds: the free flights' noise is heavy-tailed.
            auto noise = [&](bool equiangular) {
                double squares = 0;
                for (uint64_t seed = 1; seed <= 8; seed += 2) {
                    const double n = test::relativeNoiseOfLuminance(
                        test::renderImage(lightsInFog(kind, equiangular, 64, seed, lights)),
                        test::renderImage(lightsInFog(kind, equiangular, 64, seed + 1, lights)), keep);
                    squares += n * n / 4;
                }
                return std::sqrt(squares);
            };
            const double with = noise(true), without = noise(false);
            std::printf("  %s, %s: relative noise %.4f with, %.4f without\n", name,
                        kind == IntegratorKind::Path ? "path" : "sppm", with, without);
            // A ball's points are drawn by area over all of it, the far side too, where they
            // light nothing, and toward a point of the near side each weighs by its cosine.
            EXPECT_LT(with, (which == 3 ? 0.8 : 0.5) * without) << name << ", integrator " << int(kind);
        }
}

// Equiangular samples in a medium whose density varies (a random grid of 4 x 4 x 6 samples
// over a slab of fog, z in [-0.5, 0.5]), lit by a point light above it: there the free
// flights alone are not heavy-tailed (no light within the medium), so the image with
// equiangular samples, whose weights read the density where they land and the
// transmittance through the grid, must match the image without them. The path tracer,
// single scattering; over 12 seeds at 512 passes each the ratio of their means was 1.0015
// (deviation 0.56% a seed, nearly all of it the free flights': 0.51% against 0.07%), so
// the free flights render 2,048: 1.0016 (0.22%).
TEST(LightAlongRays, UnevenSmokeUnderAPointLightRendersAsWithFreeFlightsAlone) {
    std::vector<float> values;
    Rng rng(4, 0, 1, StreamPurpose::Camera);
    for (int i = 0; i < 96; ++i) values.push_back(2.0f * rng.uniform());
    MediumDescription smoke = kFog;
    smoke.density = std::make_shared<const DensityGrid>(
        4, 4, 6, std::move(values), DensityGrid::latticeFromBox(4, 4, 6, {-1, -1, -0.5f}, {1, 1, 0.5f}));
    auto render = [&](bool equiangular) {
        SceneDescription d = lightsInFog(IntegratorKind::Path, equiangular, equiangular ? 512 : 2048, 1, {});
        d.media = {smoke};
        d.shapes = test::boxFaces({-1, -1, -0.5f}, {1, 1, 0.5f}, 0, 0);
        d.lights = {test::pointLight({0.2f, 0.1f, 1.0f}, Color(2.0f), -1)};
        return test::meanOver(test::renderImage(std::move(d)), 0, 0, 8, 8);
    };
    const Color with = render(true), without = render(false);
    std::printf("  with %.5f %.5f %.5f, without %.5f %.5f %.5f\n", with.x, with.y, with.z, without.x, without.y, without.z);
    for (int c = 0; c < 3; ++c) EXPECT_NEAR(with[c], without[c], 0.015f * without[c]) << "channel " << c;
}

// Multiple scattering around the ball light (radius 0.15 here, max_depth 4): the image with
// light sampled along the rays must match the image without, for the path tracer, whose
// points in the fog go on by the phase function's direction (which meets the ball: the
// light sample's part, shared by the two strategies, is weighed against it), and for SPPM
// with volume photons, whose camera paths end at their first point in the fog (its light
// sample counted in full against the phase function). Over the pixels away from the ball
// the ratio of the two images' means was 0.991-1.009 over 6 seeds for the path tracer
// (4,096 passes against 8,192: at 512 against 2,048 each image moved by 1% from seed to
// seed) and 0.992-1.007 over 8 for SPPM (mean 1.0001).
TEST(LightAlongRays, MultipleScatteringAroundABallLightRendersAsWithFreeFlightsAlone) {
    FogLight ball = sphereLight();
    constexpr float kRadius = 0.15f;
    ball.shape = test::sphere(ball.position, kRadius, 1, Color(1.0f / (3.14159265f * kRadius * kRadius)));
    // Away from the ball: the pixels around its own too.
    std::vector<bool> keep(64, true);
    for (int y = ball.pixelY - 1; y <= ball.pixelY + 1; ++y)
        for (int x = ball.pixelX - 1; x <= ball.pixelX + 1; ++x) keep[size_t(y * 8 + x)] = false;
    struct Variant {
        const char* name;
        IntegratorKind kind;
        VolumePhotons volume;
        int passesWith, passesWithout;
    };
    for (const Variant& v : {Variant{"path", IntegratorKind::Path, VolumePhotons::Never, 4096, 8192},
                             Variant{"sppm, volume photons", IntegratorKind::Sppm, VolumePhotons::Always, 128, 512}}) {
        auto render = [&](bool equiangular) {
            SceneDescription d = lightsInFog(v.kind, equiangular, equiangular ? v.passesWith : v.passesWithout, 1, {ball});
            d.render.maxDepth = 4;
            d.render.volumePhotons = v.volume;
            d.render.photonsPerPass = 5000;
            const Image image = test::renderImage(std::move(d));
            Color mean(0.0f);
            for (int y = 0; y < 8; ++y)
                for (int x = 0; x < 8; ++x)
                    if (keep[size_t(y * 8 + x)]) mean += image.at(x, y);
            return mean;
        };
        const Color with = render(true), without = render(false);
        std::printf("  %s: with / without %.4f %.4f %.4f\n", v.name, with.x / without.x, with.y / without.y,
                    with.z / without.z);
        for (int c = 0; c < 3; ++c) EXPECT_NEAR(with[c], without[c], 0.02f * without[c]) << v.name << ", channel " << c;
    }
}

// rayInsideCone against membership tested point by point: rays from inside and outside the
// cone, toward and away from it, along and across its axis, for a narrow and a wide cone;
// 2,000 points on each segment, each inside the interval exactly where it is inside the cone
// (up to 1e-4 of the segment from the interval's ends).
TEST(RayInsideCone, FindsWhereTheRayIsInsideTheCone) {
    Rng rng(9, 0, 1, StreamPurpose::Camera);
    const Vec3 apex{0.2f, -0.1f, 0.3f};
    for (float cosMax : {0.95f, 0.6f, 0.1f})
        for (int ray = 0; ray < 400; ++ray) {
            const Vec3 axis = normalize(Vec3{rng.uniform() - 0.5f, rng.uniform() - 0.5f, rng.uniform() - 0.5f});
            const Vec3 o = apex + Vec3{rng.uniform() - 0.5f, rng.uniform() - 0.5f, rng.uniform() - 0.5f} * 4.0f;
            const Vec3 d = normalize(Vec3{rng.uniform() - 0.5f, rng.uniform() - 0.5f, rng.uniform() - 0.5f});
            const float end = 6.0f;
            const std::optional<RayInterval> in = rayInsideCone(o, d, 0.0f, end, apex, axis, cosMax);
            for (int i = 0; i < 2000; ++i) {
                const float t = (i + 0.5f) * end / 2000;
                const Vec3 p = o + d * t - apex;
                const bool inside = dot(p, axis) >= cosMax * length(p);
                const bool found = in && t >= in->start && t <= in->end;
                const bool nearEnd = in && (std::abs(t - in->start) < 1e-4f * end || std::abs(t - in->end) < 1e-4f * end);
                if (!nearEnd) ASSERT_EQ(found, inside) << "cos " << cosMax << ", ray " << ray << ", t " << t;
            }
        }
}

}  // namespace
}  // namespace photon
