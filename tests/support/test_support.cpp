#include <array>
#include "test_support.h"
#include <gtest/gtest.h>
#include <algorithm>
#include <sstream>
#include <cstdlib>
#include <stdexcept>
#include <zlib.h>
#include "scene_builders.h"
#include <tbb/task_arena.h>
#include <photon/render.h>
#include "integrators/integrator.h"
#include "film/pixel_errors.h"
#include "math/rng.h"
#include "scene/scene.h"
#include "scene/scene_loader.h"
#include "texture/image_texture.h"

namespace photon::test {

SceneDescription hitTestScene() {
    SceneDescription d;
    d.camera = camera({0, 0, 5}, {0, 0, 0}, {0, 1, 0}, 40, 8, 8);
    d.materials.push_back(makeDiffuse(Color(0.5f)));
    d.materials.push_back(makeDiffuse(ColorParam(std::make_shared<ImageTexture>(
        2, 1, std::vector<Color>{Color(1, 0, 0), Color(0, 0, 1)}))));
    return d;
}

ShapeDescription quad(Vec3 origin, Vec3 u, Vec3 v, uint32_t material, Color emission) {
    ShapeDescription s;
    s.kind = ShapeDescription::Kind::Mesh;
    s.mesh.positions = {origin, origin + u, origin + u + v, origin + v};
    s.mesh.indices = {0, 1, 2, 0, 2, 3};
    s.mesh.uvs = {{0, 0}, {1, 0}, {1, 1}, {0, 1}};
    s.material = material;
    s.emission = emission;
    return s;
}

std::vector<ShapeDescription> boxFaces(Vec3 lo, Vec3 hi, uint32_t material, int32_t insideMedium) {
    const Vec3 e = hi - lo;
    const Vec3 x{e.x, 0, 0}, y{0, e.y, 0}, z{0, 0, e.z};
    std::vector<ShapeDescription> faces{quad(lo, z, y, material), quad(lo + x, y, z, material),  // -x, +x
                                        quad(lo, x, z, material), quad(lo + y, z, x, material),  // -y, +y
                                        quad(lo, y, x, material), quad(lo + z, x, y, material)}; // -z, +z
    for (ShapeDescription& face : faces) face.insideMedium = insideMedium;
    return faces;
}

LightDescription pointLight(Vec3 p, Color intensity, int32_t medium) {
    LightDescription light;
    light.kind = LightDescription::Kind::Point;
    light.position = p;
    light.intensity = intensity;
    light.medium = medium;
    return light;
}

SceneDescription lightOnly(ShapeDescription light, LightSamplerKind kind) {
    SceneDescription d;
    d.camera = camera({0, 3, 3}, {0, 0, 0}, {0, 1, 0}, 40, 8, 8);
    d.materials.push_back(makeDiffuse(Color(0.5f)));
    d.shapes.push_back(std::move(light));
    d.render.lightSampler = kind;
    return d;
}

void expectRayFindsLightSample(const Scene& scene, const Light& light, Vec3 p, ReceiverSide side, const LightSample& ls, int k) {
    SurfaceHit hit;
    if (!scene.intersect(Ray{p, ls.wi}, hit)) {
        ADD_FAILURE() << "the ray along sample " << k << " found nothing";
        return;
    }
    EXPECT_NEAR(hit.t, ls.distance, 1e-4f * ls.distance);
    // The sample's own triangle: a point on an edge two triangles share is either's to
    // rounding, and a grazing ray may name the other, whose density there may differ.
    const float pdf = light.pdfIncidentFrom(p, side, {hit.p, hit.ng, ls.triangle}, ls.wi);
    EXPECT_NEAR(pdf, ls.pdf, 1e-3f * ls.pdf) << "sample " << k;
}

LightSampleEstimate irradianceFromLightSamples(const Scene& scene, Vec3 p, ReceiverSide side, int samples, bool checkDensity) {
    const Vec3 n = side.n;
    const Light& light = scene.lights().light(0);
    Rng rng(7, 0, 0, StreamPurpose::Test);
    double sum = 0, squares = 0;
    LightSampleEstimate e;
    for (int k = 0; k < samples; ++k) {
        std::optional<LightSample> ls = light.sampleIncident(p, side, {rng.uniform(), rng.uniform()});
        const double value = ls ? ls->weight.x * std::max(0.0f, dot(ls->wi, n)) : 0.0;
        if (!(value > 0)) {
            ++e.nothing;
            continue;
        }
        sum += value, squares += value * value;
        if (checkDensity) expectRayFindsLightSample(scene, light, p, side, *ls, k);
    }
    e.mean = sum / samples;
    e.variance = squares / samples - e.mean * e.mean;
    return e;
}

ShapeDescription sphere(Vec3 center, float radius, uint32_t material, Color emission, bool flipNormals) {
    ShapeDescription s;
    s.kind = ShapeDescription::Kind::Sphere;
    s.center = center;
    s.radius = radius;
    s.material = material;
    s.emission = emission;
    s.flipNormals = flipNormals;
    return s;
}

SceneDescription roomUnder(std::vector<LightDescription> lights, IntegratorKind kind, int passes, uint64_t seed,
                           std::vector<ShapeDescription> ceiling) {
    SceneDescription d;
    d.camera = test::camera({0, 0.8f, 0.95f}, {0, 0, -0.3f}, {0, 1, 0}, 70, 24, 24);
    d.materials = {makeDiffuse(Color(0.6f))};
    d.materialNames = {"room"};
    d.shapes = {test::quad({-1, 0, 1}, {2, 0, 0}, {0, 0, -2}, 0),          // floor
                test::quad({-1, 0, -1}, {2, 0, 0}, {0, 1, 0}, 0),          // walls
                test::quad({-1, 0, 1}, {2, 0, 0}, {0, 1, 0}, 0),
                test::quad({-1, 0, -1}, {0, 0, 2}, {0, 1, 0}, 0),
                test::quad({1, 0, -1}, {0, 0, 2}, {0, 1, 0}, 0)};
    d.shapes.insert(d.shapes.end(), ceiling.begin(), ceiling.end());
    d.lights = std::move(lights);
    d.render.integrator = kind;
    d.render.passes = passes;
    d.render.photonsPerPass = 20000;
    d.render.maxDepth = 16;
    d.render.seed = seed;
    return d;
}

std::vector<ShapeDescription> ceilingWithAHole() {
    return {test::quad({-1, 1, -1}, {2, 0, 0}, {0, 0, 0.75f}, 0), test::quad({-1, 1, 0.25f}, {2, 0, 0}, {0, 0, 0.75f}, 0),
            test::quad({-1, 1, -0.25f}, {0.75f, 0, 0}, {0, 0, 0.5f}, 0),
            test::quad({0.25f, 1, -0.25f}, {0.75f, 0, 0}, {0, 0, 0.5f}, 0)};
}


CameraDescription camera(Vec3 position, Vec3 lookAt, Vec3 up, float fov, int width, int height) {
    CameraDescription c;
    c.position = position;
    c.lookAt = lookAt;
    c.up = up;
    c.fovDegrees = fov;
    c.width = width;
    c.height = height;
    return c;
}

CameraDescription orthographicCamera(Vec3 position, Vec3 lookAt, float viewHeight, int width, int height) {
    CameraDescription c = camera(position, lookAt, {0, 1, 0}, 40, width, height);
    c.projection = CameraProjection::Orthographic;
    c.viewHeight = viewHeight;
    return c;
}

SceneDescription directLitFloor(LightSamplerKind kind, uint64_t seed, int passes) {
    SceneDescription d = pointLightPlane(0.5f, 1.0f, 1.0f, 24, 2.0f);
    d.lights.clear();
    d.render.integrator = IntegratorKind::Path;
    d.render.maxDepth = 1;
    d.render.passes = passes;
    d.render.seed = seed;
    d.render.lightSampler = kind;
    return d;
}

RendersBySampler renderBySampler(const std::function<SceneDescription(LightSamplerKind, uint64_t)>& scene) {
    return {renderImage(scene(LightSamplerKind::Spatial, 1)), renderImage(scene(LightSamplerKind::Spatial, 2)),
            renderImage(scene(LightSamplerKind::Power, 1)), renderImage(scene(LightSamplerKind::Power, 2))};
}

void expectSameBlockMeans(const Image& a1, const Image& a2, const Image& b1, const Image& b2, int block,
                          float tolerance) {
    for (int by = 0; by + block <= a1.height; by += block)
        for (int bx = 0; bx + block <= a1.width; bx += block) {
            const float a = average(meanOver(a1, bx, by, bx + block, by + block) + meanOver(a2, bx, by, bx + block, by + block));
            const float b = average(meanOver(b1, bx, by, bx + block, by + block) + meanOver(b2, bx, by, bx + block, by + block));
            EXPECT_NEAR(a, b, tolerance * b) << "block " << bx << "," << by;
        }
}

double polygonIrradiance(Vec3 p, Vec3 n, const std::vector<Vec3>& corners, double le) {
    // In double: seen edge-on from afar the edges' terms nearly cancel, and in float a
    // light 3 m away at 3 degrees came out 0.9% off.
    using D3 = std::array<double, 3>;
    const auto unitToward = [&](Vec3 c) {
        const D3 d{double(c.x) - p.x, double(c.y) - p.y, double(c.z) - p.z};
        const double l = std::sqrt(d[0] * d[0] + d[1] * d[1] + d[2] * d[2]);
        return D3{d[0] / l, d[1] / l, d[2] / l};
    };
    double sum = 0;
    for (size_t i = 0; i < corners.size(); ++i) {
        const D3 a = unitToward(corners[i]), b = unitToward(corners[(i + 1) % corners.size()]);
        const D3 c{a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]};
        const double sine = std::sqrt(c[0] * c[0] + c[1] * c[1] + c[2] * c[2]);
        const double cosine = a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
        if (!(sine > 0)) continue;
        sum += std::atan2(sine, cosine) * (c[0] * n.x + c[1] * n.y + c[2] * n.z) / sine;
    }
    return le / 2 * std::abs(sum);
}

NoiseWithoutAndWith expectSameMeansAndMeasureNoise(const std::function<Image(bool with, uint64_t seed)>& render, int block,
                                                   float tolerance) {
    const Image without1 = render(false, 1), without2 = render(false, 2);
    const Image with1 = render(true, 1), with2 = render(true, 2);
    expectSameBlockMeans(without1, without2, with1, with2, block, tolerance);
    return {relativeNoiseOfLuminance(without1, without2), relativeNoiseOfLuminance(with1, with2)};
}

double relativeNoiseOfLuminance(const Image& a, const Image& b) {
    std::vector<float> mean(size_t(a.width) * a.height);
    for (size_t i = 0; i < mean.size(); ++i) {
        const int x = int(i % a.width), y = int(i / a.width);
        mean[i] = 0.5f * (luminance(a.at(x, y)) + luminance(b.at(x, y)));
    }
    return relativeNoiseOfLuminance(a, b, errorPixels(mean, a.width, a.height));
}

double relativeNoiseOfLuminance(const Image& a, const Image& b, const std::vector<bool>& keep) {
    double d2 = 0, sum = 0;
    size_t kept = 0;
    for (int y = 0; y < a.height; ++y)
        for (int x = 0; x < a.width; ++x) {
            if (!keep[size_t(y) * a.width + x]) continue;
            const double la = luminance(a.at(x, y)), lb = luminance(b.at(x, y));
            d2 += (la - lb) * (la - lb), sum += (la + lb) / 2, ++kept;
        }
    return std::sqrt(d2 / double(kept) / 2) / (sum / double(kept));
}

uint64_t seedShift() {
    static const uint64_t shift = [] {
        const char* value = std::getenv("PHOTON_TEST_SEED_SHIFT");
        return value ? static_cast<uint64_t>(std::strtoull(value, nullptr, 10)) : uint64_t{0};
    }();
    return shift;
}

std::unique_ptr<Renderer> resumedAfter(SceneDescription d, int passes) {
    d.render.seed += seedShift();
    CancelToken cancel;
    std::stringstream saved;
    {
        Renderer first(Scene::build(d));
        for (int i = 0; i < passes; ++i) EXPECT_TRUE(first.renderPass(cancel));
        first.saveCheckpoint(saved);
    }
    auto resumed = std::make_unique<Renderer>(Scene::build(d));
    resumed->restoreCheckpoint(saved);
    EXPECT_EQ(resumed->run(cancel), RenderOutcome::Completed);
    return resumed;
}

Image renderImage(SceneDescription d) {
    d.render.seed += seedShift();
    Renderer renderer(Scene::build(std::move(d)));
    CancelToken cancel;
    renderer.run(cancel);
    return renderer.snapshot();
}

SceneDescription cornellBoxWith(MaterialPtr material, int resolution, bool sphere) {
    SceneDescription d = exampleScene("cornell-box", resolution, 1, 0, 11);
    const uint32_t index = uint32_t(d.materials.size());
    d.materials.push_back(std::move(material));
    d.materialNames.push_back("under test");
    // The blocks are its two meshes of more than one quad.
    for (ShapeDescription& s : d.shapes)
        if (s.kind == ShapeDescription::Kind::Mesh && s.mesh.triangleCount() > 2)
            s.material = index;
    if (sphere) {
        std::erase_if(d.shapes, [&](const ShapeDescription& s) { return s.material == index; });
        d.shapes.push_back(test::sphere({0.1f, 0.3f, 0.1f}, 0.3f, index));
    }
    d.render.maxDepth = 64;
    return d;
}

PathAndSppmMeans renderPathAndSppm(SceneDescription d, int pathPasses, int sppmPasses, int64_t photonsPerPass) {
    auto meanOf = [&](IntegratorKind kind, int passes, int64_t photons) {
        SceneDescription copy = d;
        copy.render.integrator = kind;
        copy.render.passes = passes;
        copy.render.photonsPerPass = photons;
        // The tolerances were set for this count in every pass: adaptive counts would lower
        // it on these small images, and the radii (with their bias) would shrink less.
        copy.render.adaptivePhotons = false;
        Image image = renderImage(std::move(copy));
        return meanOver(image, 0, 0, image.width, image.height);
    };
    return {meanOf(IntegratorKind::Path, pathPasses, 0), meanOf(IntegratorKind::Sppm, sppmPasses, photonsPerPass)};
}

Image renderWithThreads(SceneDescription d, int threads) {
    Image image;
    tbb::task_arena arena(threads);
    arena.execute([&] { image = renderImage(std::move(d)); });
    return image;
}

SceneDescription pointLightPlane(float rho, float intensity, float height, int resolution, float halfSize) {
    SceneDescription d;
    d.camera = camera({0, 3, 0}, {0, 0, 0}, {0, 0, -1}, 50, resolution, resolution);
    d.materials = {makeDiffuse(Color(rho))};
    d.materialNames = {"plane"};
    // u x v = (+x) x (-z) points up (+y).
    d.shapes = {quad({-halfSize, 0, halfSize}, {2 * halfSize, 0, 0}, {0, 0, -2 * halfSize}, 0)};
    LightDescription light;
    light.kind = LightDescription::Kind::Point;
    light.position = {0, height, 0};
    light.intensity = Color(intensity);
    d.lights = {light};
    return d;
}

SceneDescription lightOverPlane(const LightDescription& light, float rho, int resolution, DirectLighting direct,
                                int passes, int64_t photons) {
    SceneDescription d = pointLightPlane(rho, 1.0f, 1.0f, resolution);
    d.lights = {light};
    d.render.direct = direct;
    d.render.passes = passes;
    d.render.photonsPerPass = photons;
    return d;
}

Vec3 planePointSeen(const Camera& camera, float x, float y) {
    const Ray ray = camera.generateRay(x, y, {0.5f, 0.5f});
    return ray.o + ray.d * (-ray.o.y / ray.d.y);
}

LitAndDark expectBlocksMatch(const Image& image, const std::function<Color(float, float)>& radiance, float tolerance) {
    constexpr int kBlock = 4, kPoints = 64;
    LitAndDark counts;
    for (int by = 0; by + kBlock <= image.height; by += kBlock)
        for (int bx = 0; bx + kBlock <= image.width; bx += kBlock) {
            Color expected(0.0f);
            for (int j = 0; j < kBlock * kPoints; ++j)
                for (int i = 0; i < kBlock * kPoints; ++i)
                    expected += radiance(bx + (i + 0.5f) / kPoints, by + (j + 0.5f) / kPoints);
            expected = expected / float(kBlock * kPoints * kBlock * kPoints);
            const Color got = meanOver(image, bx, by, bx + kBlock, by + kBlock);
            for (int c = 0; c < 3; ++c)
                EXPECT_NEAR(got[c], expected[c], tolerance * expected[c] + 1e-4f) << "block " << bx << "," << by << " channel " << c;
            (expected.y > 1e-3f ? counts.lit : counts.dark) += 1;
        }
    return counts;
}

void expectPhotonsDrawWhatShadowRaysDraw(const LightDescription& light, float rho, int resolution) {
    const Image byRays = renderImage(lightOverPlane(light, rho, resolution, DirectLighting::LightSampling, 64, 1000));
    const Image byPhotons = renderImage(lightOverPlane(light, rho, resolution, DirectLighting::Photons, 128, 100000));
    for (int by = 0; by < resolution; by += 16)
        for (int bx = 0; bx < resolution; bx += 16) {
            const float a = meanOver(byRays, bx, by, bx + 16, by + 16).y;
            const float b = meanOver(byPhotons, bx, by, bx + 16, by + 16).y;
            EXPECT_NEAR(b, a, 0.035f * a + 1e-4f) << "block " << bx << "," << by;
        }
}

SceneDescription furnace(float rho, float emission, int resolution) {
    SceneDescription d;
    d.camera = camera({0, 0, 0}, {0, 0, 1}, {0, 1, 0}, 60, resolution, resolution);
    d.materials = {makeDiffuse(Color(rho))};
    d.materialNames = {"wall"};
    d.shapes = {sphere({0, 0, 0}, 1, 0, Color(emission), true)};
    return d;
}

SceneDescription ballOfMedium(IntegratorKind kind, MediumDescription medium, Color sky) {
    SceneDescription d;
    d.camera = camera({0, 0, 0}, {0, 0, -1}, {0, 1, 0}, 60, 16, 16);
    d.materials = {makeDielectric(1.0f)};
    d.materialNames = {"boundary"};
    d.media = {std::move(medium)};
    d.camera.medium = 0;
    d.shapes = {sphere({0, 0, 0}, 1.0f, 0)};
    d.shapes[0].insideMedium = 0;
    if (!isBlack(sky)) {
        LightDescription environment;
        environment.kind = LightDescription::Kind::Environment;
        environment.radiance = sky;
        d.lights = {environment};
    }
    d.render.integrator = kind;
    d.render.maxDepth = 200;
    d.render.passes = 256;
    d.render.photonsPerPass = 1000;
    return d;
}

std::string gzipped(std::string_view bytes) {
    z_stream zs{};
    if (deflateInit2(&zs, Z_BEST_COMPRESSION, Z_DEFLATED, 16 + MAX_WBITS, 8, Z_DEFAULT_STRATEGY) != Z_OK)
        throw std::runtime_error("deflateInit2 failed");
    std::string out(deflateBound(&zs, uLong(bytes.size())), '\0');
    zs.next_in = reinterpret_cast<Bytef*>(const_cast<char*>(bytes.data()));
    zs.avail_in = uInt(bytes.size());
    zs.next_out = reinterpret_cast<Bytef*>(out.data());
    zs.avail_out = uInt(out.size());
    const int status = deflate(&zs, Z_FINISH);
    out.resize(zs.total_out);
    deflateEnd(&zs);
    if (status != Z_STREAM_END) throw std::runtime_error("deflate failed");
    return out;
}

}  // namespace photon::test
