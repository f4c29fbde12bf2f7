// Photons from a mesh area light: triangles are picked in proportion to their area, points
// are uniform on each (their mean is the centroid), directions are cosine-distributed on
// the emitting side (mean cosine 2/3), and every photon carries the light's power Le pi A.
#include <gtest/gtest.h>
#include <cmath>
#include "math/rng.h"
#include "materials/material.h"
#include "scene/scene.h"
#include "scene_builders.h"

namespace photon {
namespace {

// Two triangles in the plane z = 0 facing +z: A of area 1, B of area 3.
ShapeDescription twoTriangleLight(bool flip) {
    ShapeDescription s;
    s.mesh.positions = {{0, 0, 0}, {1, 0, 0}, {0, 2, 0}, {2, 0, 0}, {4, 0, 0}, {2, 3, 0}};
    s.mesh.indices = {0, 1, 2, 3, 4, 5};
    s.emission = Color(2, 3, 4);
    s.flipNormals = flip;
    return s;
}

std::shared_ptr<const Scene> lightScene(bool flip) {
    SceneDescription d;
    d.camera = test::camera({0, 0, 5}, {0, 0, 0}, {0, 1, 0}, 40, 8, 8);
    d.materials.push_back(makeDiffuse(Color(0.5f)));
    d.shapes.push_back(twoTriangleLight(flip));
    return Scene::build(std::move(d));
}

struct EmissionStats {
    int64_t count = 0, inB = 0, outside = 0, wrongSide = 0;
    Vec3 sumA, sumB;
    double sumCos = 0;
};

EmissionStats emitMany(const Light& light, float side, int64_t n) {
    EmissionStats s;
    for (int64_t i = 0; i < n; ++i) {
        Rng rng(3, 0, static_cast<uint64_t>(i), StreamPurpose::Test);
        Vec2 uPos{rng.uniform(), rng.uniform()}, uDir{rng.uniform(), rng.uniform()};
        std::optional<PhotonEmission> e = light.emitPhoton(uPos, uDir);
        if (!e) continue;
        ++s.count;
        Vec3 p = e->origin;
        bool inA = p.x >= -1e-6f && p.y >= -1e-6f && 2 * p.x + p.y <= 2 + 1e-5f;
        bool inB = p.x >= 2 - 1e-6f && p.y >= -1e-6f && 3 * (p.x - 2) + 2 * p.y <= 6 + 1e-5f;
        s.outside += (!inA && !inB) || std::abs(p.z) > 1e-6f;
        if (inB) {
            ++s.inB;
            s.sumB += p;
        } else {
            s.sumA += p;
        }
        float cosine = e->direction.z * side;
        s.wrongSide += !(cosine > 0);
        s.sumCos += cosine;
        EXPECT_NEAR(length(e->direction), 1.0f, 1e-5f);
        EXPECT_NEAR(e->normal.z, side, 1e-6f);
        // Le pi A with A = 4: (8 pi, 12 pi, 16 pi) W per photon.
        EXPECT_NEAR(e->flux.x, 8 * kPi, 1e-3f);
        EXPECT_NEAR(e->flux.z, 16 * kPi, 1e-3f);
    }
    return s;
}

void expectMeshLightDistribution(bool flip) {
    auto scene = lightScene(flip);
    ASSERT_EQ(scene->lights().size(), 1u);
    constexpr int64_t kPhotons = 200000;
    EmissionStats s = emitMany(scene->lights().light(0), flip ? -1.0f : 1.0f, kPhotons);
    ASSERT_EQ(s.count, kPhotons);
    EXPECT_EQ(s.outside, 0);
    EXPECT_EQ(s.wrongSide, 0);
    // Binomial with p = 3/4: sigma = sqrt(p (1-p) / n) ~ 0.001; 5 sigma.
    EXPECT_NEAR(static_cast<double>(s.inB) / kPhotons, 0.75, 0.005);
    // Uniform points average to the centroids: A (1/3, 2/3), B (8/3, 1).
    Vec3 meanA = s.sumA / static_cast<float>(kPhotons - s.inB), meanB = s.sumB / static_cast<float>(s.inB);
    EXPECT_NEAR(meanA.x, 1.0f / 3, 0.01f);
    EXPECT_NEAR(meanA.y, 2.0f / 3, 0.01f);
    EXPECT_NEAR(meanB.x, 8.0f / 3, 0.01f);
    EXPECT_NEAR(meanB.y, 1.0f, 0.01f);
    // Cosine-distributed directions: E[cos] = 2/3 (sigma of the mean ~ 0.0005).
    EXPECT_NEAR(s.sumCos / kPhotons, 2.0 / 3.0, 0.003);
}

TEST(AreaLightEmission, TrianglesByAreaUniformPointsCosineDirections) { expectMeshLightDistribution(false); }

TEST(AreaLightEmission, FlippedMeshEmitsFromItsOtherSide) { expectMeshLightDistribution(true); }

}  // namespace
}  // namespace photon
