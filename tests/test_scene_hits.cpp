// What Scene::intersect reports at a hit, against values worked out by hand: the point, the
// geometric and shading normals (flat faces, interpolated vertex normals, flip_normals on
// meshes and spheres) and the texture coordinates of textured shapes; that Embree's packet
// query reports, lane by lane, exactly what the single-ray query does; and that untextured
// flat triangles and spheres, whose hit records take a shortcut, report what the general
// path does.
#include <gtest/gtest.h>
#include "materials/material.h"
#include "texture/image_texture.h"
#include "math/rng.h"
#include "math/sampling.h"
#include "scene/scene.h"
#include "scene_builders.h"
#include "test_support.h"

namespace photon {
namespace {

constexpr float kEps = 1e-5f;

SceneDescription baseScene() { return test::hitTestScene(); }

SurfaceHit hitAlong(const Scene& scene, Vec3 o, Vec3 d) {
    SurfaceHit hit;
    EXPECT_TRUE(scene.intersect(Ray{o, normalize(d)}, hit));
    return hit;
}

void expectNear(Vec3 a, Vec3 b) {
    EXPECT_NEAR(a.x, b.x, kEps);
    EXPECT_NEAR(a.y, b.y, kEps);
    EXPECT_NEAR(a.z, b.z, kEps);
}

TEST(SceneHits, QuadReportsPointFaceNormalAndItsUv) {
    SceneDescription d = baseScene();
    // Facing +z: u x v = x x y. Its uvs run 0..1 along u and v.
    d.shapes.push_back(test::quad({-1, -1, 0}, {2, 0, 0}, {0, 2, 0}, 1));
    auto scene = Scene::build(std::move(d));
    SurfaceHit hit = hitAlong(*scene, {0.5f, -0.25f, 3}, {0, 0, -1});
    expectNear(hit.p, {0.5f, -0.25f, 0});
    expectNear(hit.ng, {0, 0, 1});
    expectNear(hit.ns, {0, 0, 1});
    EXPECT_NEAR(hit.t, 3.0f, kEps);
    EXPECT_NEAR(hit.uv.x, 0.75f, kEps);
    EXPECT_NEAR(hit.uv.y, 0.375f, kEps);
}

TEST(SceneHits, VertexNormalsAreInterpolatedOnTheGeometricSide) {
    SceneDescription d = baseScene();
    ShapeDescription s;
    s.mesh.positions = {{-1, -1, 0}, {1, -1, 0}, {0, 1, 0}};
    s.mesh.indices = {0, 1, 2};
    // Leaning toward -x at the first vertex, +x at the second, straight up at the third;
    // the winding faces +z but the normals are given facing -z: they are turned around.
    s.mesh.normals = {normalize(Vec3(-1, 0, -1)), normalize(Vec3(1, 0, -1)), Vec3(0, 0, -1)};
    d.shapes.push_back(s);
    auto scene = Scene::build(std::move(d));
    // On the edge midway between the first two vertices: the x components cancel.
    SurfaceHit mid = hitAlong(*scene, {0, -1 + 1e-3f, 2}, {0, 0, -1});
    expectNear(mid.ng, {0, 0, 1});
    EXPECT_NEAR(mid.ns.x, 0.0f, 1e-3f);
    EXPECT_NEAR(mid.ns.z, 1.0f, 1e-3f);
    // Near the first vertex the given normal, (-1, 0, -1)/sqrt 2, is turned around whole:
    // about (1, 0, 1)/sqrt 2.
    SurfaceHit corner = hitAlong(*scene, {-0.9f, -0.95f, 2}, {0, 0, -1});
    EXPECT_GT(corner.ns.x, 0.5f);
    EXPECT_GT(corner.ns.z, 0.5f);
    EXPECT_NEAR(length(corner.ns), 1.0f, kEps);
}

TEST(SceneHits, FlippedMeshAndSphereReportInwardNormals) {
    SceneDescription d = baseScene();
    ShapeDescription quad = test::quad({-1, -1, 0}, {2, 0, 0}, {0, 2, 0}, 0);
    quad.flipNormals = true;
    d.shapes.push_back(quad);
    d.shapes.push_back(test::sphere({0, 0, -10}, 2, 0, Color(0.0f), true));
    auto scene = Scene::build(std::move(d));
    SurfaceHit q = hitAlong(*scene, {0, 0, 3}, {0, 0, -1});
    expectNear(q.ng, {0, 0, -1});
    expectNear(q.ns, {0, 0, -1});
    // The sphere seen from below the quad: its near side at z = -8, normal pointing inward.
    SurfaceHit s = hitAlong(*scene, {0, 0, -1}, {0, 0, -1});
    expectNear(s.p, {0, 0, -8});
    expectNear(s.ng, {0, 0, -1});
    expectNear(s.ns, {0, 0, -1});
}

TEST(SceneHits, TexturedSphereCarriesLongitudeAndLatitude) {
    SceneDescription d = baseScene();
    d.shapes.push_back(test::sphere({0, 0, 0}, 1, 1));
    auto scene = Scene::build(std::move(d));
    // Hit at +x (phi = 0, on the equator): uv = (0.5, 0.5).
    SurfaceHit hit = hitAlong(*scene, {3, 0, 0}, {-1, 0, 0});
    expectNear(hit.p, {1, 0, 0});
    expectNear(hit.ng, {1, 0, 0});
    EXPECT_NEAR(hit.uv.x, 0.5f, kEps);
    EXPECT_NEAR(hit.uv.y, 0.5f, kEps);
    // At the top (latitude 90 degrees) v is 1.
    SurfaceHit top = hitAlong(*scene, {0, 3, 0}, {0, -1, 0});
    EXPECT_NEAR(top.uv.y, 1.0f, kEps);
}

// Casts `count` rays, rayAt(i), sixteen to a packet with every `emptyEvery`-th lane left
// empty, and checks each lane's hit against the single-ray query's, bit for bit. Returns the
// hits compared and, through shapeHits, how many of them were on shapes from `firstShape`.
template <class RayAt>
int expectLanesHitWhatSingleRaysHit(const Scene& scene, int count, int emptyEvery, RayAt rayAt, uint32_t firstShape,
                                    int& shapeHits) {
    int compared = 0;
    for (int first = 0; first < count; first += Scene::RayPacket::kSize) {
        Scene::RayPacket packet;
        Ray rays[Scene::RayPacket::kSize];
        for (int k = 0; k < Scene::RayPacket::kSize; ++k) {
            rays[k] = rayAt(first + k);
            if ((first / 16 + k) % emptyEvery == 0) packet.clearLane(k);
            else packet.setLane(k, rays[k]);
        }
        scene.intersect(packet);
        for (int k = 0; k < Scene::RayPacket::kSize; ++k) {
            if (!packet.valid[k]) continue;
            SurfaceHit single, lane;
            const bool hitSingle = scene.intersect(rays[k], single);
            EXPECT_EQ(scene.hitOf(packet, k, lane), hitSingle);
            if (!hitSingle) continue;
            ++compared;
            shapeHits += single.shape >= firstShape;
            EXPECT_EQ(lane.shape, single.shape);
            EXPECT_EQ(lane.primitive, single.primitive);
            for (int a = 0; a < 3; ++a) {
                EXPECT_EQ(lane.p[a], single.p[a]) << "ray " << first + k;
                EXPECT_EQ(lane.ng[a], single.ng[a]);
                EXPECT_EQ(lane.ns[a], single.ns[a]);
            }
            EXPECT_EQ(lane.uv.x, single.uv.x);
            EXPECT_EQ(lane.uv.y, single.uv.y);
            if (::testing::Test::HasFailure()) return compared;  // the first ray that differs says enough
        }
    }
    return compared;
}

// Random rays through a box of quads around two spheres (one inside-out), cast once one by
// one and once sixteen to a packet with lanes left empty: every lane's hit must match its
// single ray's bit for bit, spheres included (the photon walk casts packets, and must land
// photons where the one-by-one definition does).
TEST(SceneHits, PacketLanesHitExactlyWhatSingleRaysHit) {
    SceneDescription d = baseScene();
    d.shapes.push_back(test::quad({-2, -2, -2}, {4, 0, 0}, {0, 4, 0}, 0));
    d.shapes.push_back(test::quad({-2, -2, -2}, {0, 0, 4}, {4, 0, 0}, 0));
    d.shapes.push_back(test::quad({-2, -2, -2}, {0, 4, 0}, {0, 0, 4}, 0));
    d.shapes.push_back(test::sphere({0.5f, -1, 0}, 0.7f, 1));
    d.shapes.push_back(test::sphere({-0.6f, 0.4f, -0.5f}, 0.5f, 0, Color(0.0f), true));
    auto scene = Scene::build(std::move(d));
    int sphereHits = 0;
    const int compared = expectLanesHitWhatSingleRaysHit(*scene, 4096, 5, [](int i) {
        Rng rng(7, 0, static_cast<uint64_t>(i), StreamPurpose::Test);
        return Ray{Vec3(rng.uniform(), rng.uniform(), rng.uniform()) * 3.0f - Vec3(1.5f),
                   sampleUniformSphere({rng.uniform(), rng.uniform()})};
    }, 3, sphereHits);
    EXPECT_GT(compared, 1500);
    EXPECT_GT(sphereHits, 300);  // the spheres, whose hit points are solved from the ray, were hit often
}

// A unit sphere of 131,072 triangles with vertex normals and uvs (3.7 MB of hit data, past
// a core's L2), textured so that its hits read the uvs.
ShapeDescription largeTexturedSphere() {
    constexpr int kRings = 256, kSegments = 256;
    ShapeDescription mesh;
    mesh.material = 1;
    for (int i = 0; i <= kRings; ++i)
        for (int j = 0; j <= kSegments; ++j) {
            const float theta = kPi * static_cast<float>(i) / kRings, phi = 2.0f * kPi * static_cast<float>(j) / kSegments;
            const Vec3 n(std::sin(theta) * std::cos(phi), std::cos(theta), std::sin(theta) * std::sin(phi));
            mesh.mesh.positions.push_back(n);
            mesh.mesh.normals.push_back(n);
            mesh.mesh.uvs.push_back({static_cast<float>(j) / kSegments, static_cast<float>(i) / kRings});
        }
    for (uint32_t i = 0; i < kRings; ++i)
        for (uint32_t j = 0; j < kSegments; ++j) {
            const uint32_t a = i * (kSegments + 1) + j, b = a + 1, c = a + kSegments + 1, d = c + 1;
            mesh.mesh.indices.insert(mesh.mesh.indices.end(), {a, c, b, b, c, d});
        }
    return mesh;
}

// From a sphere of radius 3 toward a point near the origin.
Ray rayTowardTheOrigin(int i) {
    Rng rng(13, 0, static_cast<uint64_t>(i), StreamPurpose::Test);
    const Vec3 target = (Vec3(rng.uniform(), rng.uniform(), rng.uniform()) - Vec3(0.5f)) * 1.2f;
    const Vec3 origin = sampleUniformSphere({rng.uniform(), rng.uniform()}) * 3.0f;
    return Ray{origin, normalize(target - origin)};
}

// A mesh whose hit data outgrows a core's L2 makes packets prefetch each lane's corners
// before hitOf() reads them; every lane must still report what its single ray does, bit for
// bit. The box of quads above (kilobytes) does not prefetch.
TEST(SceneHits, PacketsThatPrefetchALargeMeshStillHitWhatSingleRaysHit) {
    SceneDescription withMesh = baseScene();
    withMesh.shapes.push_back(largeTexturedSphere());
    auto scene = Scene::build(std::move(withMesh));
    ASSERT_TRUE(scene->prefetchesHits());
    SceneDescription small = baseScene();
    small.shapes.push_back(test::quad({-2, -2, -2}, {4, 0, 0}, {0, 4, 0}, 0));
    EXPECT_FALSE(Scene::build(std::move(small))->prefetchesHits());
    int meshHits = 0;
    const int compared = expectLanesHitWhatSingleRaysHit(*scene, 2048, 7, rayTowardTheOrigin, 0, meshHits);
    EXPECT_EQ(meshHits, compared);  // the mesh is the only shape
    EXPECT_GT(compared, 1500);      // every ray aimed inside the sphere, most lanes filled
}

// The same with the mesh placed twice as an object's instances (and a flat quad in the
// object beside it): a lane's placement is prefetched first, as it names the shape.
TEST(SceneHits, PacketsThatPrefetchInstancesStillHitWhatSingleRaysHit) {
    SceneDescription d = baseScene();
    d.objects = {{"balls", {largeTexturedSphere(), test::quad({-0.5f, -0.5f, 0.9f}, {1, 0, 0}, {0, 1, 0}, 0)}}};
    d.instances = {{0, Transform::translate({-0.5f, 0.2f, 0}) * Transform::scale(Vec3(0.6f)), "left"},
                   {0, Transform::translate({0.6f, -0.3f, 0.2f}) * Transform::rotate({0, 1, 1}, 50), "right"}};
    auto scene = Scene::build(std::move(d));
    ASSERT_TRUE(scene->prefetchesHits());
    int hits = 0;
    const int compared = expectLanesHitWhatSingleRaysHit(*scene, 2048, 7, rayTowardTheOrigin, 0, hits);
    EXPECT_GT(compared, 1000);  // most rays meet one of the two balls
}

// Untextured flat triangles and spheres take a shorter way to their hit record (one table,
// inline) than textured ones: the same rays through the same shapes, once untextured and once
// textured, must report the same points and normals bit for bit.
TEST(SceneHits, ShortcutHitRecordsMatchTheGeneralOnes) {
    auto build = [](uint32_t material) {
        SceneDescription d = baseScene();
        ShapeDescription faceted;  // a tetrahedron's faces, no vertex normals
        faceted.mesh.positions = {{-1.1f, -0.9f, -1.3f}, {1.2f, -1.0f, -0.7f}, {0.1f, 1.3f, -0.9f}, {0.2f, 0.1f, 1.1f}};
        faceted.mesh.indices = {0, 2, 1, 0, 1, 3, 1, 2, 3, 2, 0, 3};
        faceted.material = material;
        faceted.flipNormals = true;
        d.shapes.push_back(faceted);
        d.shapes.push_back(test::sphere({0.3f, 0.2f, 3.0f}, 0.8f, material));
        return Scene::build(std::move(d));
    };
    auto plain = build(0), textured = build(1);
    int compared = 0, sphereHits = 0;
    for (int i = 0; i < 4000; ++i) {
        Rng rng(11, 0, static_cast<uint64_t>(i), StreamPurpose::Test);
        // From around the shapes toward a point among them.
        const Vec3 target = Vec3(rng.uniform(), rng.uniform(), rng.uniform()) * Vec3(2.4f, 2.4f, 5.0f) - Vec3(1.2f, 1.1f, 1.3f);
        const Vec3 origin = target + sampleUniformSphere({rng.uniform(), rng.uniform()}) * 6.0f;
        const Ray ray{origin, normalize(target - origin)};
        SurfaceHit a, b;
        const bool hitA = plain->intersect(ray, a);
        ASSERT_EQ(textured->intersect(ray, b), hitA);
        if (!hitA) continue;
        ++compared;
        sphereHits += a.shape == 1;
        ASSERT_EQ(a.shape, b.shape);
        ASSERT_EQ(a.primitive, b.primitive);
        for (int k = 0; k < 3; ++k) {
            ASSERT_EQ(a.p[k], b.p[k]) << "ray " << i;
            ASSERT_EQ(a.ng[k], b.ng[k]);
            ASSERT_EQ(a.ns[k], b.ns[k]);
        }
        // Untextured shapes carry Embree's barycentrics as their uv.
        ASSERT_EQ(a.uv.x, a.barycentric.x);
        ASSERT_EQ(a.uv.y, a.barycentric.y);
    }
    EXPECT_GT(compared - sphereHits, 500);  // the tetrahedron
    EXPECT_GT(sphereHits, 500);
}

}  // namespace
}  // namespace photon
