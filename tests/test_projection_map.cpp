// Projection maps: photons leave lights only through cells that can reach geometry.
// A small scene far from a point light (and two small spheres far apart under a
// directional light) renders the same with and without them, for SPPM and for the photon
// mapper, while far fewer emitted photons miss everything.
#include <gtest/gtest.h>
#include "integrators/photon_mapping/photon_mapping.h"
#include "integrators/common/photon_emitter.h"
#include <photon/render.h>
#include "integrators/integrator.h"
#include "scene/scene.h"
#include "scene/scene_loader.h"
#include "scene_builders.h"
#include "test_support.h"

namespace photon {
namespace {

constexpr int kResolution = 32;

// Two diffuse spheres side by side, 6 units from a point light: 1.4% of the light's
// directions meet them.
SceneDescription distantSpheres() {
    SceneDescription d;
    d.camera = test::camera({0, 1.5f, -1}, {0, 0, -6}, {0, 1, 0}, 30, kResolution, kResolution);
    d.materials = {makeDiffuse(Color(0.8f))};
    d.materialNames = {"white"};
    d.shapes = {test::sphere({-1.05f, 0, -6}, 1, 0), test::sphere({1.05f, 0, -6}, 1, 0)};
    LightDescription light;
    light.kind = LightDescription::Kind::Point;
    light.position = {0, 0, 0};
    light.intensity = Color(100.0f);
    d.lights = {light};
    return d;
}

// Two small spheres 8 units apart under a directional light: its emission disc covers
// the bounding sphere of both, of which they fill 2.5%.
SceneDescription spheresApartUnderSun() {
    SceneDescription d;
    d.camera = test::camera({-4, 2, 2.5f}, {-4, 0, 0}, {0, 1, 0}, 30, kResolution, kResolution);
    d.materials = {makeDiffuse(Color(0.8f))};
    d.materialNames = {"white"};
    d.shapes = {test::sphere({-4, 0, 0}, 0.5f, 0), test::sphere({-3.3f, -0.2f, 0.3f}, 0.25f, 0),
                test::sphere({4, 0, 0}, 0.5f, 0)};
    LightDescription light;
    light.kind = LightDescription::Kind::Directional;
    light.direction = normalize(Vec3{0.3f, -1, -0.2f});
    light.irradiance = Color(3.0f);
    d.lights = {light};
    return d;
}

// What the first rays of the photons from the emitter both photon integrators use do:
// the share that meets nothing, and the power delivered to geometry in units of the
// lights' mean power (the same with and without projection maps, as nothing that
// reaches geometry is left out).
struct FirstRays {
    double missFraction = 0, powerDelivered = 0;
};

FirstRays traceFirstRays(const SceneDescription& description, bool projectionMaps) {
    auto scene = Scene::build(description);
    PhotonEmitter emitter(*scene, projectionMaps);
    const int n = 400000;
    FirstRays r;
    for (int i = 0; i < n; ++i) {
        Rng rng(1, 0, static_cast<uint64_t>(i), StreamPurpose::Test);
        std::optional<EmittedPhoton> e = emitter.emit(rng);
        SurfaceHit hit;
        if (e && scene->intersect(e->ray, hit))
            r.powerDelivered += average(e->beta);
        else
            r.missFraction += 1;
    }
    r.missFraction /= n;
    r.powerDelivered /= n;
    return r;
}

double missFraction(const SceneDescription& description, bool projectionMaps) {
    return traceFirstRays(description, projectionMaps).missFraction;
}

// Mean radiance over the pixels that see an object (the background is black).
Color meanOverObject(const Image& image, const Image& mask) {
    Color sum(0.0f);
    int n = 0;
    for (int y = 0; y < kResolution; ++y)
        for (int x = 0; x < kResolution; ++x)
            if (maxComponent(mask.at(x, y)) > 0) {
                sum += image.at(x, y);
                ++n;
            }
    return sum / static_cast<float>(std::max(n, 1));
}

struct Rendered {
    Image image;
    PassStats firstPass;
};

Rendered render(SceneDescription d, bool projectionMaps) {
    d.render.projectionMaps = projectionMaps;
    Renderer renderer(Scene::build(std::move(d)));
    CancelToken cancel;
    Rendered r;
    for (int p = 0; p < renderer.scene().settings().passes; ++p) {
        renderer.renderPass(cancel);
        if (p == 0) r.firstPass = renderer.integrator().lastPassStats();
    }
    r.image = renderer.snapshot();
    return r;
}

SceneDescription withSppm(SceneDescription d) {
    d.render.integrator = IntegratorKind::Sppm;
    d.render.direct = DirectLighting::Photons;  // all the light through the photons
    d.render.passes = 32;
    d.render.photonsPerPass = 200000;
    d.render.seed = 3;
    return d;
}

SceneDescription withPhotonMap(SceneDescription d) {
    d.render.integrator = IntegratorKind::PhotonMap;
    d.render.passes = 8;
    d.render.photonMap.globalPhotons = 1000000;
    d.render.photonMap.causticPhotons = 0;
    d.render.photonMap.gatherRays = 0;
    d.render.seed = 3;
    return d;
}

void expectSameImageFewerMisses(const SceneDescription& scene, const char* what) {
    double missWithout = missFraction(scene, false), missWith = missFraction(scene, true);
    std::printf("%s: miss fraction %.4f without, %.4f with projection maps\n", what, missWithout, missWith);
    EXPECT_GT(missWithout, 0.95);
    EXPECT_LT(missWith * 10, missWithout);

    Rendered sppmWithout = render(withSppm(scene), false), sppmWith = render(withSppm(scene), true);
    Color a = meanOverObject(sppmWithout.image, sppmWith.image), b = meanOverObject(sppmWith.image, sppmWith.image);
    std::printf("%s sppm: %f %f\n", what, luminance(a), luminance(b));
    EXPECT_NEAR(luminance(b), luminance(a), 0.03f * luminance(a)) << what << " SPPM";

    Rendered pmWithout = render(withPhotonMap(scene), false), pmWith = render(withPhotonMap(scene), true);
    a = meanOverObject(pmWithout.image, pmWith.image);
    b = meanOverObject(pmWith.image, pmWith.image);
    std::printf("%s photonmap: %f %f, misses %lld %lld\n", what, luminance(a), luminance(b),
                static_cast<long long>(pmWithout.firstPass.photonMisses), static_cast<long long>(pmWith.firstPass.photonMisses));
    EXPECT_NEAR(luminance(b), luminance(a), 0.03f * luminance(a)) << what << " photon map";
    EXPECT_LT(pmWith.firstPass.photonMisses * 10, pmWithout.firstPass.photonMisses);
}

TEST(ProjectionMap, DistantObjectUnderPointLightSameImageTenfoldFewerMisses) {
    expectSameImageFewerMisses(distantSpheres(), "point light");
}

// A spot light whose cone only partly covers a sphere, with its smooth falloff across it:
// the cells' probabilities follow the falloff and the flux divides by them exactly.
TEST(ProjectionMap, SpotLightDeliversTheSamePower) {
    SceneDescription d = distantSpheres();
    d.lights[0].kind = LightDescription::Kind::Spot;
    d.lights[0].direction = normalize(Vec3{-1.05f, 0.6f, -6});
    d.lights[0].coneAngleDegrees = 12;
    d.lights[0].falloffAngleDegrees = 4;
    FirstRays without = traceFirstRays(d, false), with = traceFirstRays(d, true);
    std::printf("spot light: power delivered %.5f without, %.5f with projection maps; miss fraction %.4f, %.4f\n",
                without.powerDelivered, with.powerDelivered, without.missFraction, with.missFraction);
    EXPECT_GT(without.powerDelivered, 0.2);
    EXPECT_NEAR(with.powerDelivered, without.powerDelivered, 0.01 * without.powerDelivered);
    EXPECT_LT(with.missFraction * 3, without.missFraction);
}

TEST(ProjectionMap, SpheresApartUnderDirectionalLightSameImageTenfoldFewerMisses) {
    expectSameImageFewerMisses(spheresApartUnderSun(), "directional light");
}

// A glass sphere over a floor under a point light: the caustic map's photons leave only
// toward the sphere (the one shape with a specular lobe), so the same number of emitted
// photons stores many times the caustic photons, and they carry the same power.
TEST(ProjectionMap, CausticPhotonsAimAtSpecularShapes) {
    SceneDescription d;
    d.camera = test::camera({0, 3.5f, 3}, {0, 0, 0}, {0, 1, 0}, 40, kResolution, kResolution);
    d.materials = {makeDiffuse(Color(0.8f)), makeDielectric(1.5f)};
    d.materialNames = {"floor", "glass"};
    d.shapes = {test::quad({-4, 0, -4}, {0, 0, 8}, {8, 0, 0}, 0), test::sphere({0, 1, 0}, 0.5f, 1)};
    LightDescription light;
    light.kind = LightDescription::Kind::Point;
    light.position = {0, 3, 0};
    light.intensity = Color(20.0f);
    d.lights = {light};
    d.render.integrator = IntegratorKind::PhotonMap;
    d.render.passes = 1;
    d.render.photonMap.globalPhotons = 1000;
    d.render.photonMap.causticPhotons = 500000;
    d.render.seed = 3;
    auto causticMap = [&](bool projectionMaps) {
        SceneDescription s = d;
        s.render.projectionMaps = projectionMaps;
        auto renderer = std::make_unique<Renderer>(Scene::build(std::move(s)));
        CancelToken cancel;
        EXPECT_TRUE(renderer->renderPass(cancel));
        const auto& pm = dynamic_cast<const PhotonMapIntegrator&>(renderer->integrator());
        return std::pair(pm.causticMap().size(), pm.causticMap().totalPower());
    };
    auto [countWithout, powerWithout] = causticMap(false);
    auto [countWith, powerWith] = causticMap(true);
    std::printf("caustic photons %zu without, %zu with projection maps; power %f, %f W\n", countWithout, countWith,
                average(powerWithout), average(powerWith));
    EXPECT_GT(countWithout, 5000u);
    EXPECT_GT(countWith, 10 * countWithout);
    EXPECT_NEAR(average(powerWith), average(powerWithout), 0.05f * average(powerWithout));
    // All of it first reached the sphere, which receives I * 2 pi (1 - cos a) with
    // sin a = 0.5 / 2 (3.99 W); most of that leaves through the glass toward the floor.
    const float ontoSphere = 20.0f * 2.0f * kPi * (1.0f - std::sqrt(1.0f - 0.25f * 0.25f));
    EXPECT_LT(average(powerWith), ontoSphere);
    EXPECT_GT(average(powerWith), 0.8f * ontoSphere);
}

}  // namespace
}  // namespace photon
