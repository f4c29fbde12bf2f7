// Instanced objects against the same shapes copied into the world by hand: every ray meets
// the same surfaces at the same points with the same normals, uvs and tangents, whatever
// the transform (mirroring and shearing ones included); images match those of the copies
// for every integrator that renders instances, emitters inside objects included; a sphere
// under a non-uniform scale is the ellipsoid; and the JSON names what is wrong.
#include <gtest/gtest.h>
#include <photon/errors.h>
#include <photon/render.h>
#include <photon/scene_file.h>
#include "description/shape_transform.h"
#include "materials/material.h"
#include "math/rng.h"
#include "math/sampling.h"
#include "scene/scene.h"
#include "scene_builders.h"
#include "scene_loader_fixture.h"
#include "test_support.h"
#include "texture/image_texture.h"

namespace photon {
namespace {

// The scene with each instance replaced by copies of its object's shapes, moved into the
// world: what instancing must be equivalent to.
SceneDescription copiedInstances(SceneDescription d) {
    for (const InstanceDescription& instance : d.instances)
        for (ShapeDescription shape : d.objects[instance.object].shapes) {
            EXPECT_TRUE(transformShape(instance.toWorld, shape));
            d.shapes.push_back(std::move(shape));
        }
    d.instances.clear();
    d.objects.clear();
    return d;
}

// A bumpy 8 x 8 height field over [0, 1]^2 (z up) with smooth vertex normals and uvs.
ShapeDescription heightField(uint32_t material) {
    ShapeDescription s;
    const int n = 8;
    auto height = [](float x, float y) { return 0.15f * std::sin(6 * x) * std::cos(5 * y); };
    for (int j = 0; j <= n; ++j)
        for (int i = 0; i <= n; ++i) {
            float x = float(i) / n, y = float(j) / n;
            s.mesh.positions.push_back({x, y, height(x, y)});
            const float e = 1e-3f;
            Vec3 dx{2 * e, 0, height(x + e, y) - height(x - e, y)}, dy{0, 2 * e, height(x, y + e) - height(x, y - e)};
            s.mesh.normals.push_back(normalize(cross(dx, dy)));
            s.mesh.uvs.push_back({x, y});
        }
    for (int j = 0; j < n; ++j)
        for (int i = 0; i < n; ++i) {
            uint32_t a = j * (n + 1) + i, b = a + 1, c = a + n + 1, d = c + 1;
            s.mesh.indices.insert(s.mesh.indices.end(), {a, b, d, a, d, c});
        }
    s.material = material;
    s.name = "height field";
    return s;
}

// Two objects: meshes (a textured height field and a flat quad), placed by any affine
// transform; spheres (plain and textured), moved and scaled.
SceneDescription instancedScene() {
    SceneDescription d = test::hitTestScene();
    d.shapes.push_back(test::quad({-4, -3, -4}, {8, 0, 0}, {0, 0, 8}, 0));
    ObjectDescription meshes{"meshes", {heightField(1), test::quad({0, 0, 0.5f}, {1, 0, 0}, {0, 1, 0}, 0)}};
    meshes.shapes[1].flipNormals = true;
    ObjectDescription spheres{"spheres", {test::sphere({0, 0, 0}, 0.4f, 0), test::sphere({1, 0, 0}, 0.3f, 1)}};
    d.objects = {meshes, spheres};
    const Transform shear{{1, 0.4f, 0, 0, 0, 1, 0.2f, 0, 0.1f, 0, 1, 0}};
    d.instances = {
        {0, Transform::translate({-2, 0, 0}) * Transform::rotate({1, 2, 3}, 40)},
        {0, Transform::translate({1, 1, -1}) * Transform::scale({-1.5f, 0.7f, 1.2f})},  // mirrors
        {0, Transform::translate({0, -2, 1}) * shear},
        // A world sphere's uvs are in the world's frame, an instanced one's in its object's:
        // only these transforms leave the two the same.
        {1, Transform::translate({1, 2, 0}) * Transform::scale(Vec3(1.3f))},
        {1, Transform::translate({-2, -1, 2}) * Transform::scale(Vec3(0.8f))},
    };
    for (size_t k = 0; k < d.instances.size(); ++k) d.instances[k].name = "instance " + std::to_string(k);
    d.lights.push_back({LightDescription::Kind::Point, {0, 4, 4}, {}, Color(10.0f)});
    return d;
}

TEST(Instancing, RaysMeetInstancesAsTheyMeetCopies) {
    SceneDescription d = instancedScene();
    auto instanced = Scene::build(d);
    auto copied = Scene::build(copiedInstances(d));
    Rng rng(7, 0, 0, StreamPurpose::Camera);
    int hits = 0, disagreements = 0, instanceHits = 0;
    const int kRays = 20000;
    for (int i = 0; i < kRays; ++i) {
        Vec3 o = Vec3(rng.uniform(), rng.uniform(), rng.uniform()) * 8.0f - Vec3(4.0f);
        Ray ray{o, sampleUniformSphere({rng.uniform(), rng.uniform()})};
        SurfaceHit a, b;
        const bool hitA = instanced->intersect(ray, a), hitB = copied->intersect(ray, b);
        // Rays through a shared edge may fall either side of it in the two.
        if (hitA != hitB || (hitA && (a.primitive != b.primitive || std::abs(a.t - b.t) > 1e-4f))) {
            ++disagreements;
            continue;
        }
        if (!hitA) continue;
        ++hits;
        instanceHits += a.instance != kNoInstance;
        EXPECT_EQ(instanced->materialIndex(a), copied->materialIndex(b));
        EXPECT_VEC3_NEAR(a.p, b.p, 2e-5f * (1 + length(b.p)));
        EXPECT_VEC3_NEAR(a.ng, b.ng, 2e-5f);
        // Vertex normals are interpolated in the object's frame, then transformed, rather
        // than transformed, then interpolated: the same under a similarity, slightly apart
        // between vertices under a non-uniform scale or a shear.
        if (a.instance == kNoInstance || uniformScale(d.instances[a.instance].toWorld))
            EXPECT_VEC3_NEAR(a.ns, b.ns, 2e-4f);
        else
            EXPECT_GT(dot(a.ns, b.ns), 0.999f);
        if (instanced->material(a).textured()) {  // else the uv is not worked out
            EXPECT_NEAR(a.uv.x, b.uv.x, 2e-5f);
            EXPECT_NEAR(a.uv.y, b.uv.y, 2e-5f);
        }
        SurfaceTangents ta = instanced->tangentsAt(a), tb = copied->tangentsAt(b);
        EXPECT_VEC3_NEAR(ta.dpdu, tb.dpdu, 2e-4f * (1 + length(tb.dpdu)));
        EXPECT_VEC3_NEAR(ta.dpdv, tb.dpdv, 2e-4f * (1 + length(tb.dpdv)));
        Ray toLight{a.p + a.ng * 1e-3f * (dot(a.ng, ray.d) < 0 ? 1.0f : -1.0f), normalize(Vec3(0, 4, 4) - a.p)};
        toLight.tMax = length(Vec3(0, 4, 4) - a.p);
        Ray toLightB{b.p + b.ng * 1e-3f * (dot(b.ng, ray.d) < 0 ? 1.0f : -1.0f), toLight.d, toLight.tMax};
        EXPECT_EQ(instanced->occluded(toLight), copied->occluded(toLightB));
    }
    std::printf("  %d hits (%d on instances), %d of %d rays disagree\n", hits, instanceHits, disagreements, kRays);
    EXPECT_GT(instanceHits, kRays / 40);
    EXPECT_LT(disagreements, kRays / 1000);
}

// Embree's packet query reports instance hits lane by lane as the single-ray query does.
TEST(Instancing, PacketHitsMatchSingleRays) {
    auto scene = Scene::build(instancedScene());
    Rng rng(9, 0, 0, StreamPurpose::Camera);
    Scene::RayPacket packet;
    Ray rays[Scene::RayPacket::kSize];
    for (int lane = 0; lane < Scene::RayPacket::kSize; ++lane) {
        rays[lane] = {Vec3(rng.uniform(), rng.uniform(), rng.uniform()) * 4.0f - Vec3(2.0f),
                      sampleUniformSphere({rng.uniform(), rng.uniform()})};
        packet.setLane(lane, rays[lane]);
    }
    scene->intersect(packet);
    for (int lane = 0; lane < Scene::RayPacket::kSize; ++lane) {
        SurfaceHit single, fromPacket;
        ASSERT_EQ(scene->intersect(rays[lane], single), scene->hitOf(packet, lane, fromPacket));
        EXPECT_EQ(single.shape, fromPacket.shape);
        EXPECT_EQ(single.instance, fromPacket.instance);
        EXPECT_EQ(single.primitive, fromPacket.primitive);
        EXPECT_VEC3_NEAR(single.p, fromPacket.p, 1e-5f);
    }
}

// A unit sphere scaled by (2, 1, 0.5) is the ellipsoid x²/4 + y² + 4z² = 1, its normal the
// gradient (x/4, y, 4z) normalised.
TEST(Instancing, NonUniformlyScaledSphereIsTheEllipsoid) {
    SceneDescription d = instancedScene();
    d.shapes.clear();
    d.objects = {{"ball", {test::sphere({0, 0, 0}, 1, 0)}}};
    d.instances = {{0, Transform::scale({2, 1, 0.5f}), "ellipsoid"}};
    auto scene = Scene::build(d);
    Rng rng(3, 0, 0, StreamPurpose::Camera);
    for (int i = 0; i < 200; ++i) {
        Vec3 o = sampleUniformSphere({rng.uniform(), rng.uniform()}) * 5.0f;
        Vec3 target = Vec3(rng.uniform() - 0.5f, rng.uniform() - 0.5f, rng.uniform() - 0.5f) * 0.5f;
        SurfaceHit hit;
        ASSERT_TRUE(scene->intersect({o, normalize(target - o)}, hit));
        const Vec3 p = hit.p;
        EXPECT_NEAR(p.x * p.x / 4 + p.y * p.y + 4 * p.z * p.z, 1.0f, 1e-4f);
        EXPECT_VEC3_NEAR(hit.ng, normalize(Vec3(p.x / 4, p.y, 4 * p.z)), 1e-4f);
    }
}

// Mean over pixels of |a - b|.
double meanAbsoluteDifference(const Image& a, const Image& b) {
    double sum = 0;
    for (int y = 0; y < a.height; ++y)
        for (int x = 0; x < a.width; ++x) sum += std::abs(luminance(a.at(x, y)) - luminance(b.at(x, y)));
    return sum / (a.width * a.height);
}

// The Cornell box with its blocks replaced by three instances of an object holding a glass
// sphere and a box, and lit also by two instances of a small emissive sphere.
SceneDescription cornellWithInstances(IntegratorKind kind, uint64_t seed) {
    SceneDescription d = test::exampleScene("cornell-box", 40, 8, 20000, seed);
    d.render.integrator = kind;
    d.render.passes = kind == IntegratorKind::Path ? 24 : 8;
    const uint32_t glass = static_cast<uint32_t>(d.materials.size());
    d.materials.push_back(makeDielectric(1.5f));
    d.shapes.resize(6);  // the walls, floor, ceiling and light, without the two blocks
    ObjectDescription block{"block", {test::sphere({0, 0.15f, 0}, 0.15f, glass)}};
    // A box of side 0.2 beside the sphere, its faces' normals outward: u x v = n.
    const Vec3 centre{0.35f, 0.1f, 0};
    for (Vec3 n : {Vec3(1, 0, 0), Vec3(0, 1, 0), Vec3(0, 0, 1)}) {
        Vec3 u = Vec3(n.z, n.x, n.y), v = cross(n, u);
        block.shapes.push_back(test::quad(centre + (n - u - v) * 0.1f, u * 0.2f, v * 0.2f, 0));
        block.shapes.push_back(test::quad(centre + (-n - u - v) * 0.1f, v * 0.2f, u * 0.2f, 0));
    }
    ObjectDescription lamp{"lamp", {test::sphere({0, 0, 0}, 0.05f, 0, Color(20.0f))}};
    d.objects = {block, lamp};
    d.instances = {{0, Transform::translate({-0.6f, 0, 0.2f}) * Transform::rotate({0, 1, 0}, 30), "block 0"},
                   {0, Transform::translate({0.2f, 0, -0.3f}) * Transform::scale({-1.2f, 1.2f, 1.2f}) *
                           Transform::rotate({0, 1, 0}, -20), "block 1"},
                   {0, Transform::translate({0.0f, 0, 0.6f}) * Transform::scale(Vec3(0.8f)), "block 2"},
                   {1, Transform::translate({-0.5f, 1.2f, 0}), "lamp 0"},
                   {1, Transform::translate({0.5f, 1.4f, -0.2f}), "lamp 1"}};
    return d;
}

class InstancesVsCopies : public testing::TestWithParam<IntegratorKind> {};

TEST_P(InstancesVsCopies, RenderTheSameImage) {
    Image instanced = test::renderImage(cornellWithInstances(GetParam(), 1));
    Image copied = test::renderImage(copiedInstances(cornellWithInstances(GetParam(), 1)));
    Image otherSeed = test::renderImage(copiedInstances(cornellWithInstances(GetParam(), 2)));
    const double same = meanAbsoluteDifference(instanced, copied), noise = meanAbsoluteDifference(otherSeed, copied);
    const double mean = luminance(test::meanOver(copied, 0, 0, copied.width, copied.height));
    std::printf("  mean |instanced - copied| %.5f, |other seed - copied| %.5f, image mean %.4f\n", same, noise, mean);
    // The same random numbers meet the same surfaces: what differs is rounding in the last
    // bits of hit points, which moves a few paths, far less than a change of seed does.
    EXPECT_LT(same, 0.1 * noise);
    EXPECT_NEAR(luminance(test::meanOver(instanced, 0, 0, 40, 40)), mean, 0.01 * mean);
}

INSTANTIATE_TEST_SUITE_P(Integrators, InstancesVsCopies,
                         testing::Values(IntegratorKind::Path, IntegratorKind::Sppm, IntegratorKind::PhotonMap),
                         [](const testing::TestParamInfo<IntegratorKind>& info) {
                             return std::string(integratorName(info.param));
                         });

// The JSON form: "objects" by name, {"type": "instance"} among the shapes.
TEST(Instancing, JsonObjectsAndInstances) {
    using test::Json;
    Json doc = test::fullScene();
    doc["objects"] = Json::parse(R"({"pair": {"shapes": [
        {"type": "sphere", "center": [0, 0, 0], "radius": 0.1, "material": "glass"},
        {"type": "mesh", "file": "meshes/tri.obj", "material": "white", "transform": {"translate": [0, 1, 0]}}]}})");
    doc["shapes"].push_back(Json::parse(R"({"type": "instance", "object": "pair"})"));
    doc["shapes"].push_back(Json::parse(
        R"({"type": "instance", "object": "pair", "transform": {"scale": [1, 2, 1], "translate": [3, 0, 0]}})"));
    SceneDescription d = loadSceneJson(doc.dump(), test::fixture().scene);
    ASSERT_EQ(d.objects.size(), 1u);
    EXPECT_EQ(d.objects[0].name, "pair");
    ASSERT_EQ(d.objects[0].shapes.size(), 2u);
    EXPECT_EQ(d.objects[0].shapes[1].name, "objects.pair.shapes[1]");
    EXPECT_VEC3_NEAR(d.objects[0].shapes[1].mesh.positions[0], Vec3(0, 1, 0), 1e-6f);  // its own transform
    ASSERT_EQ(d.instances.size(), 2u);
    EXPECT_EQ(d.instances[1].name, "shapes[7]");
    EXPECT_VEC3_NEAR(d.instances[1].toWorld.point({1, 1, 1}), Vec3(4, 2, 1), 1e-6f);
    EXPECT_EQ(d.shapes.size(), 6u);  // the instances are not among the world's shapes
}

TEST(Instancing, JsonErrorsNameWhatIsWrong) {
    using test::Json;
    auto withObject = [](const char* object, const char* instance) {
        return [=](Json& d) {
            if (*object) d["objects"] = Json::parse(object);
            d["shapes"].push_back(Json::parse(instance));
        };
    };
    const char* pair = R"({"pair": {"shapes": [{"type": "sphere", "center": [0, 0, 0], "radius": 1, "material": "white"}]}})";
    test::expectError(withObject(pair, R"({"type": "instance", "object": "pear"})"), "shapes[6].object",
                      "unknown object \"pear\"");
    test::expectError(withObject(pair, R"({"type": "instance", "object": "pair", "material": "white"})"),
                      "shapes[6].material", "unknown field");
    test::expectError(withObject(R"({"a": {"shapes": [{"type": "instance", "object": "a"}]}})",
                                 R"({"type": "instance", "object": "a"})"),
                      "objects.a.shapes[0].type", "an object's shapes cannot be instances (one level of instancing)");
    test::expectError(withObject(R"({"a": {"shapes": []}})", R"({"type": "instance", "object": "a"})"),
                      "objects.a.shapes", "must contain at least one shape");
    test::expectError(
        withObject(R"({"lamp": {"shapes": [{"type": "sphere", "center": [0, 0, 0], "radius": 1, "material": "white",
                                             "emission": [1, 1, 1]}]}})",
                   R"({"type": "instance", "object": "lamp", "transform": {"scale": [1, 2, 1]}})"),
        "shapes[6].transform",
        "the object has an emissive sphere (objects.lamp.shapes[0]), which can only be scaled uniformly");
}

// An object's triangles count once towards the scene's size, however often it is placed.
TEST(Instancing, TrianglesOfAnObjectCountOnce) {
    using test::Json;
    Json doc = test::fullScene();
    const int64_t before = SceneFile::parseJson(doc.dump(), test::fixture().scene).triangleCount();
    doc["objects"] = Json::parse(R"({"tri": {"shapes": [{"type": "mesh", "file": "meshes/tri.obj", "material": "white"}]}})");
    for (int i = 0; i < 100; ++i)
        doc["shapes"].push_back(Json{{"type", "instance"}, {"object", "tri"}, {"transform", {{"translate", {i, 0, 0}}}}});
    EXPECT_EQ(SceneFile::parseJson(doc.dump(), test::fixture().scene).triangleCount(), before + 1);
}

TEST(Instancing, RadiosityRefusesInstances) {
    SceneDescription d = cornellWithInstances(IntegratorKind::Radiosity, 1);
    try {
        test::renderImage(std::move(d));
        FAIL() << "radiosity rendered an instanced scene";
    } catch (const std::exception& e) {
        EXPECT_STREQ(e.what(), "radiosity: block 0 places an object (instancing); render the scene with sppm or path");
    }
}

}  // namespace
}  // namespace photon
