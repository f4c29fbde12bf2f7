// The JSON scene loader (engine/scene/json_*.cpp), the mesh loader and texture loading:
// a full scene parses to the expected values, defaults apply, the example scenes in scenes/
// load, textures decode.
#include <fstream>
#include <iterator>
#include "scene_loader_fixture.h"
#include "texture/image_texture.h"

using namespace photon::test;
using photon::Color;
using photon::SceneDescription;
using photon::SceneError;
using photon::Vec2;
using photon::Vec3;


// ---- a valid scene ----

TEST(SceneLoader, FullSceneCamera) {
    SceneDescription s = load(fullScene());
    EXPECT_VEC3_NEAR(s.camera.position, Vec3(0, 1, 6.8f), 0);
    EXPECT_VEC3_NEAR(s.camera.lookAt, Vec3(0, 1, 0), 0);
    EXPECT_VEC3_NEAR(s.camera.up, Vec3(0, 1, 0), 0);
    EXPECT_FLOAT_EQ(s.camera.fovDegrees, 19.5f);
    EXPECT_EQ(s.camera.width, 640);
    EXPECT_EQ(s.camera.height, 480);
    EXPECT_FLOAT_EQ(s.camera.apertureRadius, 0.05f);
    EXPECT_FLOAT_EQ(s.camera.focusDistance, 6.5f);
}

TEST(SceneLoader, FullSceneMaterials) {
    SceneDescription s = load(fullScene());
    ASSERT_EQ(s.materials.size(), 6u);
    EXPECT_EQ(s.materialNames, (std::vector<std::string>{"white", "wood", "glass", "mirror", "metal", "gloss"}));
    for (const auto& m : s.materials) EXPECT_TRUE(m);
    EXPECT_VEC3_NEAR(s.materials[0]->tint().value, Vec3(0.725f, 0.71f, 0.68f), 0);
    ASSERT_TRUE(s.materials[1]->tint().textured());
    EXPECT_EQ(dynamic_cast<const photon::ImageTexture&>(*s.materials[1]->tint().texture).width(), 2);
    EXPECT_VEC3_NEAR(s.materials[3]->tint().value, Color(0.95f), 0);
    EXPECT_VEC3_NEAR(s.materials[4]->tint().value, Vec3(0.9f, 0.6f, 0.3f), 0);
}

TEST(SceneLoader, MixOfNamedAndInlineMaterials) {
    Json doc = fullScene();
    doc["materials"]["blend"] = Json::parse(
        R"({"type": "mix", "materials": ["white", {"type": "conductor", "roughness": 0.3}], "amount": 0.25})");
    SceneDescription s = load(doc);
    const photon::Material& blend = *s.materials.back();
    EXPECT_EQ(blend.lobes(), unsigned(photon::kDiffuseLobe | photon::kGlossyLobe));
    // A mirror pair of directions: three quarters of the white diffuse, a quarter of the metal.
    const Vec3 wo(0.6f, 0, 0.8f), wi(-0.6f, 0, 0.8f);
    const auto radiance = photon::TransportMode::Radiance;
    auto metal = photon::makeConductor(Color(0.9f), 0.3f);
    Color expected = s.materials[0]->eval(wo, wi, s.materials[0]->inputsAt({0, 0}), radiance) * 0.75f +
                     metal->eval(wo, wi, metal->inputsAt({0, 0}), radiance) * 0.25f;
    EXPECT_VEC3_NEAR(blend.eval(wo, wi, blend.inputsAt({0, 0}), radiance), expected, 1e-5);

    expectError([](Json& d) { d["materials"]["blend"] = Json::parse(R"({"type": "mix", "materials": ["later", "white"]})"); },
                "materials.blend.materials[0]", "names no material defined before this one: \"later\"");
    expectError([](Json& d) { d["materials"]["blend"] = Json::parse(R"({"type": "mix", "materials": ["white"]})"); },
                "materials.blend.materials", "must name exactly 2 materials");
    expectError([](Json& d) { d["materials"]["blend"] = Json::parse(R"({"type": "mix", "materials": ["white", "glass"]})"); },
                "materials.blend.materials",
                "a mix cannot join a one-sided material (a dielectric) with a two-sided one");
}

TEST(SceneLoader, FullSceneQuads) {
    SceneDescription s = load(fullScene());
    ASSERT_EQ(s.shapes.size(), 6u);
    const auto& floor = s.shapes[0];
    EXPECT_EQ(floor.kind, photon::ShapeDescription::Kind::Mesh);
    EXPECT_EQ(floor.name, "shapes[0]");
    EXPECT_EQ(floor.material, 1u);
    ASSERT_EQ(floor.mesh.triangleCount(), 2u);
    ASSERT_EQ(floor.mesh.normals.size(), 4u);
    ASSERT_EQ(floor.mesh.uvs.size(), 4u);
    EXPECT_VEC3_NEAR(floor.mesh.positions[2], Vec3(1, 0, 1), 0);  // origin + u + v
    EXPECT_EQ(floor.mesh.uvs[2].x, 1);
    EXPECT_EQ(floor.mesh.uvs[2].y, 1);
    // u x v = (0,0,2) x (2,0,0) = +y, and both triangles are wound to agree with it.
    for (size_t t = 0; t < 2; ++t) {
        const auto& m = floor.mesh;
        Vec3 p0 = m.positions[m.indices[3 * t]], p1 = m.positions[m.indices[3 * t + 1]],
             p2 = m.positions[m.indices[3 * t + 2]];
        EXPECT_VEC3_NEAR(photon::normalize(photon::cross(p1 - p0, p2 - p0)), Vec3(0, 1, 0), 1e-6);
    }
    for (Vec3 n : floor.mesh.normals) EXPECT_VEC3_NEAR(n, Vec3(0, 1, 0), 1e-6);
    EXPECT_FALSE(floor.flipNormals);
    EXPECT_TRUE(s.shapes[1].flipNormals);
    EXPECT_VEC3_NEAR(s.shapes[5].emission, Vec3(17, 12, 4), 0);
    EXPECT_VEC3_NEAR(s.shapes[0].emission, Vec3(0, 0, 0), 0);
}

TEST(SceneLoader, FullSceneFileMeshIsTransformed) {
    SceneDescription s = load(fullScene());
    const auto& m = s.shapes[2].mesh;
    EXPECT_EQ(s.shapes[2].material, 4u);
    ASSERT_EQ(m.triangleCount(), 1u);
    ASSERT_EQ(m.normals.size(), 3u);
    ASSERT_EQ(m.uvs.size(), 3u);
    // scale 0.5, rotate 90 degrees about +y (x -> -z), translate (1, 2, 3).
    EXPECT_VEC3_NEAR(m.positions[m.indices[0]], Vec3(1, 2, 3), 1e-6);
    EXPECT_VEC3_NEAR(m.positions[m.indices[1]], Vec3(1, 2, 2.5f), 1e-6);
    EXPECT_VEC3_NEAR(m.positions[m.indices[2]], Vec3(1, 2.5f, 3), 1e-6);
    EXPECT_VEC3_NEAR(m.normals[m.indices[0]], Vec3(1, 0, 0), 1e-6);
    EXPECT_NEAR(m.uvs[m.indices[1]].x, 1, 0);
    EXPECT_NEAR(m.uvs[m.indices[2]].y, 1, 0);
}

TEST(SceneLoader, FullSceneSphereAndInlineMesh) {
    SceneDescription s = load(fullScene());
    const auto& sphere = s.shapes[3];
    EXPECT_EQ(sphere.kind, photon::ShapeDescription::Kind::Sphere);
    EXPECT_VEC3_NEAR(sphere.center, Vec3(0.4f, 0.3f, 0.2f), 0);
    EXPECT_FLOAT_EQ(sphere.radius, 0.3f);
    EXPECT_EQ(sphere.material, 2u);

    const auto& m = s.shapes[4].mesh;  // scale (2, 3, 4), then translate (1, 1, 1)
    ASSERT_EQ(m.positions.size(), 3u);
    EXPECT_VEC3_NEAR(m.positions[0], Vec3(1, 1, 1), 0);
    EXPECT_VEC3_NEAR(m.positions[1], Vec3(3, 1, 1), 0);
    EXPECT_VEC3_NEAR(m.positions[2], Vec3(1, 4, 1), 0);
    EXPECT_EQ(m.indices, (std::vector<uint32_t>{0, 1, 2}));
    // Normals take the inverse transpose: (1, 1, 0) -> (1/2, 1/3, 0), normalised.
    EXPECT_VEC3_NEAR(m.normals[0], photon::normalize(Vec3(0.5f, 1 / 3.0f, 0)), 1e-6);
    EXPECT_VEC3_NEAR(m.normals[2], Vec3(0, 0, 1), 1e-6);  // [0, 0, 2] arrives normalised
    EXPECT_EQ(m.uvs[2].y, 1);
}

TEST(SceneLoader, FullSceneLights) {
    SceneDescription s = load(fullScene());
    using Kind = photon::LightDescription::Kind;
    ASSERT_EQ(s.lights.size(), 4u);
    EXPECT_EQ(s.lights[0].kind, Kind::Point);
    EXPECT_VEC3_NEAR(s.lights[0].position, Vec3(0, 1.5f, 0), 0);
    EXPECT_VEC3_NEAR(s.lights[0].intensity, Color(5), 0);
    EXPECT_EQ(s.lights[1].kind, Kind::Spot);
    EXPECT_VEC3_NEAR(s.lights[1].direction, Vec3(0, -1, 0), 0);  // normalised
    EXPECT_FLOAT_EQ(s.lights[1].coneAngleDegrees, 30);
    EXPECT_FLOAT_EQ(s.lights[1].falloffAngleDegrees, 25);  // default: 5/6 of the cone
    EXPECT_EQ(s.lights[2].kind, Kind::Directional);
    EXPECT_VEC3_NEAR(s.lights[2].irradiance, Color(3), 0);
    EXPECT_EQ(s.lights[3].kind, Kind::Environment);
    EXPECT_VEC3_NEAR(s.lights[3].radiance, Color(0.1f), 0);
}

TEST(SceneLoader, FullSceneRenderSettings) {
    photon::RenderSettings r = load(fullScene()).render;
    EXPECT_EQ(r.integrator, photon::IntegratorKind::Path);
    EXPECT_EQ(r.passes, 16);
    EXPECT_EQ(r.photonsPerPass, 1000);
    EXPECT_DOUBLE_EQ(r.timeLimitSeconds, 2.5);
    EXPECT_EQ(r.initialRadius, 0);  // "auto"
    EXPECT_FLOAT_EQ(r.alpha, 0.7f);
    EXPECT_EQ(r.maxDepth, 5);
    EXPECT_EQ(r.seed, 42u);
    EXPECT_EQ(r.kernel, photon::KernelKind::Biweight);
    EXPECT_FLOAT_EQ(r.exposure, -1);
    EXPECT_EQ(r.direct, photon::DirectLighting::Photons);
}

TEST(SceneLoader, RadiositySettings) {
    Json d = fullScene();
    d["render"]["integrator"] = "radiosity";
    d["render"]["radiosity"] = {{"patch_size", 0.2}, {"max_patches", 1000}, {"rays_per_patch", 64},
                                {"direct_samples", 8}, {"tolerance", 0.01}, {"max_iterations", 50}};
    photon::RenderSettings r = load(d).render;
    EXPECT_EQ(r.integrator, photon::IntegratorKind::Radiosity);
    EXPECT_FLOAT_EQ(r.radiosity.patchSize, 0.2f);
    EXPECT_EQ(r.radiosity.maxPatches, 1000);
    EXPECT_EQ(r.radiosity.raysPerPatch, 64);
    EXPECT_EQ(r.radiosity.directSamples, 8);
    EXPECT_FLOAT_EQ(r.radiosity.tolerance, 0.01f);
    EXPECT_EQ(r.radiosity.maxIterations, 50);
    d["render"]["radiosity"] = {{"patch_size", "auto"}};
    photon::RadiositySettings defaults;
    photon::RadiositySettings a = load(d).render.radiosity;
    EXPECT_EQ(a.patchSize, 0);
    EXPECT_EQ(a.maxPatches, defaults.maxPatches);
    EXPECT_EQ(a.raysPerPatch, 1024);
    EXPECT_EQ(a.directSamples, 64);
    EXPECT_FLOAT_EQ(a.tolerance, 1e-4f);
    EXPECT_EQ(a.maxIterations, 1000);
}

TEST(SceneLoader, Defaults) {
    SceneDescription s = load(Json::parse(R"({
      "camera": {"position": [0, 0, 5], "look_at": [0, 0, 0], "fov": 40},
      "materials": {"d": {"type": "diffuse"}, "m": {"type": "mirror"}, "g": {"type": "dielectric"},
                    "c": {"type": "conductor"}, "p": {"type": "plastic"}, "cd": {"type": "coated_diffuse"},
                    "dt": {"type": "diffuse_transmission"}},
      "shapes": [{"type": "sphere", "center": [0, 0, 0], "radius": 1, "material": "d"}],
      "lights": [{"type": "spot", "position": [0, 1, 0], "direction": [0, -1, 0], "intensity": [1, 1, 1]}]
    })"));
    EXPECT_EQ(s.camera.width, 512);
    EXPECT_EQ(s.camera.height, 512);
    EXPECT_VEC3_NEAR(s.camera.up, Vec3(0, 1, 0), 0);
    EXPECT_EQ(s.camera.apertureRadius, 0);
    EXPECT_FLOAT_EQ(s.camera.focusDistance, 5);  // |look_at - position|
    EXPECT_VEC3_NEAR(s.materials[0]->tint().value, Color(0.8f), 0);
    EXPECT_VEC3_NEAR(s.materials[1]->tint().value, Color(1.0f), 0);
    EXPECT_VEC3_NEAR(s.materials[3]->tint().value, Color(0.9f), 0);
    EXPECT_VEC3_NEAR(s.materials[4]->tint().value, Color(0.5f), 0);
    EXPECT_VEC3_NEAR(s.materials[5]->tint().value, Color(0.5f), 0);
    EXPECT_EQ(s.materials[5]->lobes(), unsigned(photon::kDiffuseLobe | photon::kDeltaLobe));  // smooth coat
    EXPECT_VEC3_NEAR(s.materials[6]->tint().value, Color(0.25f), 0);          // reflectance
    EXPECT_TRUE(s.materials[6]->transmits());
    EXPECT_FALSE(s.shapes[0].flipNormals);
    EXPECT_FLOAT_EQ(s.lights[0].coneAngleDegrees, 30);
    EXPECT_FLOAT_EQ(s.lights[0].falloffAngleDegrees, 25);
    photon::RenderSettings r = s.render, d;
    EXPECT_EQ(r.integrator, photon::IntegratorKind::Sppm);
    EXPECT_EQ(r.passes, 64);
    EXPECT_EQ(r.photonsPerPass, 200000);
    EXPECT_EQ(r.timeLimitSeconds, 0);
    EXPECT_EQ(r.initialRadius, 0);
    EXPECT_EQ(r.autoRadiusPhotons, 8);
    EXPECT_FLOAT_EQ(r.alpha, d.alpha);
    EXPECT_EQ(r.maxDepth, 8);
    EXPECT_EQ(r.seed, 1u);
    EXPECT_EQ(r.kernel, photon::KernelKind::Uniform);
    EXPECT_EQ(r.exposure, 0);
    EXPECT_EQ(r.direct, photon::DirectLighting::LightSampling);
}

TEST(SceneLoader, NumericInitialRadiusAndBigSeed) {
    Json doc = fullScene();
    doc["render"]["initial_radius"] = 0.01;
    doc["render"]["seed"] = 18446744073709551615ull;
    doc["render"]["auto_radius_photons"] = 16;
    photon::RenderSettings r = load(doc).render;
    EXPECT_FLOAT_EQ(r.initialRadius, 0.01f);
    EXPECT_EQ(r.autoRadiusPhotons, 16);
    EXPECT_EQ(r.seed, 18446744073709551615ull);
}

TEST(SceneLoader, EmissiveShapeAloneLightsTheScene) {
    Json doc = fullScene();
    doc.erase("lights");
    EXPECT_TRUE(load(doc).lights.empty());
}

TEST(SceneLoader, MatrixTransform) {
    Json doc = fullScene();
    // A rotation by 90 degrees about z and a translation, written out.
    doc["shapes"][4]["transform"] = Json::parse(R"({"matrix": [0, -1, 0, 5,  1, 0, 0, 6,  0, 0, 1, 7,  0, 0, 0, 1]})");
    SceneDescription scene = load(doc);
    const auto& m = scene.shapes[4].mesh;
    EXPECT_VEC3_NEAR(m.positions[1], Vec3(5, 7, 7), 1e-6);  // (1, 0, 0) -> (0, 1, 0) + t
    EXPECT_VEC3_NEAR(m.positions[2], Vec3(4, 6, 7), 1e-6);  // (0, 1, 0) -> (-1, 0, 0) + t
}

TEST(SceneLoader, MirroringTransformKeepsWindingConsistent) {
    Json doc = fullScene();
    doc["shapes"][0]["transform"] = Json::parse(R"({"scale": [-1, 1, 1]})");
    SceneDescription scene = load(doc);
    const auto& m = scene.shapes[0].mesh;
    Vec3 p0 = m.positions[m.indices[0]], p1 = m.positions[m.indices[1]], p2 = m.positions[m.indices[2]];
    Vec3 geometric = photon::normalize(photon::cross(p1 - p0, p2 - p0));
    // The floor still faces +y, and the geometric normal agrees with the shading normal.
    EXPECT_VEC3_NEAR(m.normals[0], Vec3(0, 1, 0), 1e-6);
    EXPECT_VEC3_NEAR(geometric, Vec3(0, 1, 0), 1e-6);
}

TEST(SceneLoader, SphereTransformUniformScale) {
    Json doc = fullScene();
    doc["shapes"][3]["transform"] = Json::parse(R"({"scale": 2, "rotate": {"axis": [1, 0, 0], "angle": 90},
                                                    "translate": [0, 0, 1]})");
    SceneDescription scene = load(doc);
    const auto& s = scene.shapes[3];
    EXPECT_FLOAT_EQ(s.radius, 0.6f);
    // (0.4, 0.3, 0.2) * 2 = (0.8, 0.6, 0.4); about x by 90: (x, -z, y) = (0.8, -0.4, 0.6); + (0, 0, 1).
    EXPECT_VEC3_NEAR(s.center, Vec3(0.8f, -0.4f, 1.6f), 1e-6);
}

TEST(SceneLoader, PlyAndGltfMeshes) {
    Json doc = fullScene();
    doc["shapes"][2].erase("transform");
    doc["shapes"][2]["file"] = "meshes/tri.ply";
    auto ply = load(doc).shapes[2].mesh;
    ASSERT_EQ(ply.triangleCount(), 1u);
    EXPECT_VEC3_NEAR(ply.positions[ply.indices[1]], Vec3(2, 0, 0), 0);
    doc["shapes"][2]["file"] = "meshes/tri.gltf";
    auto gltf = load(doc).shapes[2].mesh;
    ASSERT_EQ(gltf.triangleCount(), 1u);
    EXPECT_VEC3_NEAR(gltf.positions[gltf.indices[1]], Vec3(1, 0, 5), 1e-6);  // node translation baked in
    // An external buffer inside the scene folder loads (escape.gltf, whose buffer is
    // outside, is refused in SceneLoaderErrors.UnreadableFiles).
    doc["shapes"][2]["file"] = "meshes/external.gltf";
    EXPECT_EQ(load(doc).shapes[2].mesh.triangleCount(), 1u);
}

TEST(SceneLoader, TexturesAreShared) {
    Json doc = fullScene();
    doc["materials"]["gloss"]["albedo"] = Json::parse(R"({"texture": "textures/wood.png"})");
    SceneDescription s = load(doc);
    EXPECT_EQ(s.materials[1]->tint().texture, s.materials[5]->tint().texture);
}

TEST(SceneLoader, TheFilesASceneNamesAreListedOnceInNormalForm) {
    Json doc = fullScene();
    doc["materials"]["gloss"]["albedo"] = Json::parse(R"({"texture": "./textures//wood.png"})");
    EXPECT_EQ(load(doc).files, (std::vector<std::string>{"meshes/tri.obj", "textures/wood.png"}));
}

TEST(SceneLoader, LoadSceneFileResolvesAgainstItsFolder) {
    const fs::path file = fixture().scene / "scene.json";
    writeText(file, kFullScene);
    SceneDescription s = photon::loadSceneFile(file);
    EXPECT_EQ(s.shapes.size(), 6u);
    EXPECT_TRUE(s.materials[1]->tint().textured());
}

void expectDenoise(const photon::DenoiseSettings& got, const photon::DenoiseSettings& want) {
    EXPECT_EQ(got.enabled, want.enabled);
    EXPECT_EQ(got.sigmaSpatial, want.sigmaSpatial);
    EXPECT_EQ(got.sigmaRange, want.sigmaRange);
    EXPECT_EQ(got.guide, want.guide);
    EXPECT_EQ(got.sigmaAlbedo, want.sigmaAlbedo);
    EXPECT_EQ(got.sigmaNormal, want.sigmaNormal);
    EXPECT_EQ(got.featureSamples, want.featureSamples);
}

TEST(SceneLoader, Denoise) {
    Json doc = fullScene();
    EXPECT_FALSE(load(doc).render.denoise.enabled);  // absent: off
    doc["render"]["denoise"] = true;
    expectDenoise(load(doc).render.denoise, {true, 1.5f, 1.0f, true, 0.1f, 0.2f, 4});
    doc["render"]["denoise"] = false;
    EXPECT_FALSE(load(doc).render.denoise.enabled);
    doc["render"]["denoise"] = {{"sigma_spatial", 3}, {"sigma_range", 0.5}, {"guide", false}, {"sigma_albedo", 0.2},
                                {"sigma_normal", 0.4}, {"feature_samples", 8}};
    expectDenoise(load(doc).render.denoise, {true, 3.0f, 0.5f, false, 0.2f, 0.4f, 8});  // an object turns it on
    doc["render"]["denoise"] = {{"enabled", false}, {"sigma_spatial", 3}};
    EXPECT_FALSE(load(doc).render.denoise.enabled);
}

// A dielectric is the smooth boundary unless rough (glossy lobes, still one-sided) or thin
// (a two-sided slab, delta lobes, which photons cross one at a time).
TEST(SceneLoader, DielectricKinds) {
    SceneDescription s = load(Json::parse(R"({
      "camera": {"position": [0, 0, 5], "look_at": [0, 0, 0], "fov": 40},
      "materials": {"smooth": {"type": "dielectric", "ior": 1.33, "roughness": 0},
                    "rough": {"type": "dielectric", "ior": 1.5, "roughness": 0.3},
                    "pane": {"type": "dielectric", "thin": true},
                    "ice": {"type": "dielectric", "ior": 0.985, "roughness": 0.5, "thin": false}},
      "shapes": [{"type": "sphere", "center": [0, 0, 0], "radius": 1, "material": "smooth"}],
      "lights": [{"type": "spot", "position": [0, 1, 0], "direction": [0, -1, 0], "intensity": [1, 1, 1]}]
    })"));
    ASSERT_TRUE(s.materials[0]->smoothSpecular());
    EXPECT_FLOAT_EQ(s.materials[0]->smoothSpecular()->ior, 1.33f);
    EXPECT_EQ(s.materials[1]->lobes(), unsigned(photon::kGlossyLobe));
    EXPECT_FALSE(s.materials[1]->twoSided());
    EXPECT_TRUE(s.materials[2]->isDeltaOnly());
    EXPECT_TRUE(s.materials[2]->twoSided());
    EXPECT_FALSE(s.materials[2]->smoothSpecular());
    EXPECT_EQ(s.materials[3]->lobes(), unsigned(photon::kGlossyLobe));
}

// ---- the example scenes ----

TEST(ExampleScenes, AllLoad) {
    for (const char* name :
         {"cornell-box.json", "cornell-glass.json", "rough-glass.json", "envmap.json", "point-light-plane.json",
          "textured-mesh.json", "textures.json", "cutouts.json", "coated.json", "translucent-sheet.json",
          "instances.json", "hair.json"}) {
        SCOPED_TRACE(name);
        SceneDescription s = photon::loadSceneFile(photon::test::sourcePath(std::string("scenes/") + name));
        EXPECT_EQ(s.camera.width, 512);
        EXPECT_EQ(s.camera.height, 512);
        EXPECT_EQ(s.render.passes, 64);
        EXPECT_EQ(s.render.photonsPerPass, 200000);
    }
}

TEST(ExampleScenes, CornellBoxLightFacesDown) {
    SceneDescription s = photon::loadSceneFile(photon::test::sourcePath("scenes/cornell-box.json"));
    int emitters = 0;
    for (const auto& shape : s.shapes) {
        if (photon::isBlack(shape.emission)) continue;
        ++emitters;
        const auto& m = shape.mesh;
        EXPECT_VEC3_NEAR(m.normals[0], Vec3(0, -1, 0), 0);
        Vec3 p0 = m.positions[m.indices[0]], p1 = m.positions[m.indices[1]], p2 = m.positions[m.indices[2]];
        EXPECT_VEC3_NEAR(photon::normalize(photon::cross(p1 - p0, p2 - p0)), Vec3(0, -1, 0), 1e-6);
        EXPECT_NEAR(p0.y, 1.98f, 1e-6);
    }
    EXPECT_EQ(emitters, 1);
}

// The uv sphere's triangles are wound outward and its normals point outward.
TEST(ExampleScenes, TexturedMeshIsOutwardFacing) {
    auto mesh = photon::loadMeshFile(photon::test::sourcePath("scenes/meshes/uv-sphere.obj"));
    ASSERT_GT(mesh.triangleCount(), 100u);
    ASSERT_EQ(mesh.normals.size(), mesh.positions.size());
    ASSERT_EQ(mesh.uvs.size(), mesh.positions.size());
    for (size_t t = 0; t < mesh.triangleCount(); ++t) {
        Vec3 p0 = mesh.positions[mesh.indices[3 * t]], p1 = mesh.positions[mesh.indices[3 * t + 1]],
             p2 = mesh.positions[mesh.indices[3 * t + 2]];
        Vec3 centroid = (p0 + p1 + p2) / 3.0f;
        EXPECT_GT(photon::dot(photon::cross(p1 - p0, p2 - p0), centroid), 0) << "triangle " << t;
    }
}

// ---- textures ----

TEST(Texture, BilinearLookupWithWrapAndBottomRowAtVZero) {
    auto tex = photon::ImageTexture::load(fixture().scene / "textures/wood.png");
    ASSERT_EQ(tex->width(), 2);
    ASSERT_EQ(tex->height(), 2);
    EXPECT_VEC3_NEAR(tex->lookup({0.25f, 0.25f}), Vec3(0, 0, 1), 1e-6);  // bottom left: blue
    EXPECT_VEC3_NEAR(tex->lookup({0.25f, 0.75f}), Vec3(1, 0, 0), 1e-6);  // top left: red
    EXPECT_VEC3_NEAR(tex->lookup({0.75f, 0.75f}), Vec3(0, 1, 0), 1e-6);  // top right: green
    EXPECT_VEC3_NEAR(tex->lookup({0.5f, 0.25f}), Vec3(0.5f, 0.5f, 1), 1e-6);
    // Wrap-around: u = 0 lies halfway between the last and the first column.
    EXPECT_VEC3_NEAR(tex->lookup({0.0f, 0.25f}), Vec3(0.5f, 0.5f, 1), 1e-6);
    EXPECT_VEC3_NEAR(tex->lookup({1.25f, -0.75f}), tex->lookup({0.25f, 0.25f}), 1e-6);
    EXPECT_VEC3_NEAR(tex->lookup({-3.75f, 7.25f}), tex->lookup({0.25f, 0.25f}), 1e-5);
    EXPECT_VEC3_NEAR(tex->average(), Vec3(0.5f, 0.5f, 0.5f), 1e-6);
    Color nan = tex->lookup({std::nanf(""), INFINITY});
    EXPECT_TRUE(photon::isFinite(nan));
}

TEST(Texture, SrgbGreyAlphaAndFloat) {
    const fs::path dir = fixture().scene / "textures";
    writeImage<uint8_t>(dir / "grey.png", 2, 1, 1, {128, 10});
    auto grey = photon::ImageTexture::load(dir / "grey.png");
    // The exact sRGB curve: 128/255 -> 0.2158605, and the linear toe 10/255/12.92.
    EXPECT_VEC3_NEAR(grey->lookup({0.25f, 0.5f}), Color(0.2158605f), 1e-6);
    EXPECT_VEC3_NEAR(grey->lookup({0.75f, 0.5f}), Color(10 / 255.0f / 12.92f), 1e-7);

    // Alpha is ignored, and colour is not premultiplied by it.
    writeImage<uint8_t>(dir / "alpha.png", 1, 1, 4, {255, 128, 0, 0});
    EXPECT_VEC3_NEAR(photon::ImageTexture::load(dir / "alpha.png")->average(), Vec3(1, 0.2158605f, 0), 1e-6);

    writeImage<uint16_t>(dir / "deep.png", 1, 1, 3, {65535, 32768, 0});
    const float half16 = float(std::pow((32768 / 65535.0 + 0.055) / 1.055, 2.4));  // 0.21404
    EXPECT_VEC3_NEAR(photon::ImageTexture::load(dir / "deep.png")->average(), Vec3(1, half16, 0), 1e-6);

    // Float images are linear; negative and NaN texels become 0.
    writeImage<float>(dir / "linear.exr", 2, 1, 3, {2.5f, 0.5f, -1, std::nanf(""), 1, 0});
    auto lin = photon::ImageTexture::load(dir / "linear.exr");
    EXPECT_VEC3_NEAR(lin->lookup({0.25f, 0.5f}), Vec3(2.5f, 0.5f, 0), 1e-6);
    EXPECT_VEC3_NEAR(lin->lookup({0.75f, 0.5f}), Vec3(0, 1, 0), 1e-6);
}

TEST(Texture, TooLargeIsRefused) {
    const fs::path file = fixture().scene / "textures/wide.png";
    writeImage<uint8_t>(file, 16385, 1, 1, std::vector<uint8_t>(16385, 0));
    try {
        photon::ImageTexture::load(file);
        FAIL() << "loaded a texture over the limit";
    } catch (const std::runtime_error& e) {
        EXPECT_EQ(std::string(e.what()),
                  "image is 16385x1, larger than the limit of 16384 pixels a side and 64M pixels in total");
    }
    EXPECT_THROW(photon::ImageTexture::load(fixture().scene / "textures/missing.png"), std::runtime_error);
}

TEST(Texture, PngChunkLongerThanTheFileIsRefusedBeforeDecoding) {
    const fs::path file = fixture().scene / "textures/cut.png";
    writeImage<uint8_t>(file, 2, 2, 3, std::vector<uint8_t>(12, 200));
    ASSERT_EQ(photon::ImageTexture::load(file)->width(), 2);
    std::string bytes;
    {
        std::ifstream in(file, std::ios::binary);
        bytes.assign(std::istreambuf_iterator<char>(in), {});
    }
    // The IHDR chunk (13 bytes of data) starts at byte 8; the next chunk at 8 + 12 + 13.
    ASSERT_EQ(bytes.substr(12, 4), "IHDR");
    const size_t next = 33;
    const std::string type = bytes.substr(next + 4, 4);
    const std::string declared = "\x7f\xff\xff\xf0";  // 2147483632 bytes
    bytes.replace(next, 4, declared);
    std::ofstream(file, std::ios::binary | std::ios::trunc) << bytes;
    try {
        photon::ImageTexture::load(file);
        FAIL() << "loaded a PNG whose chunk runs past the end of the file";
    } catch (const std::runtime_error& e) {
        EXPECT_EQ(std::string(e.what()), "damaged PNG: chunk " + type + " at byte 33 declares 2147483632 bytes of data, "
                                         "but the file has " + std::to_string(bytes.size() - next - 12) + " after it");
    }
}

// ---- the JSON reader on its own ----

TEST(JsonReader, PathsAndUnknownFields) {
    photon::Json doc = photon::parseJsonDocument(R"({"a": {"b": [1, {"c": 2, "d": 3}]}})");
    photon::JsonObject top = photon::JsonValue(doc, "").object();
    auto b = top.required("a").object().required("b").elements();
    ASSERT_EQ(b.size(), 2u);
    EXPECT_EQ(b[1].path(), "a.b[1]");
    photon::JsonObject inner = b[1].object();
    EXPECT_EQ(inner.number("c", 0), 2);
    try {
        inner.finish();
        FAIL();
    } catch (const SceneError& e) {
        EXPECT_EQ(std::string(e.what()), "a.b[1].d: unknown field");
    }
    EXPECT_EQ(b[0].integer(0, 5), 1);
    EXPECT_THROW(b[0].integer(2, 5), SceneError);
}

namespace photon {
namespace {

// The loader's choice list, the CLI and the API all go by kIntegratorNames.
TEST(SceneLoader, IntegratorNamesMatchTheEnum) {
    for (size_t i = 0; i < kIntegratorNames.size(); ++i) {
        Json doc = fullScene();
        doc["render"]["integrator"] = std::string(kIntegratorNames[i]);
        EXPECT_EQ(static_cast<size_t>(load(doc).render.integrator), i) << kIntegratorNames[i];
        EXPECT_EQ(integratorNamed(kIntegratorNames[i]), IntegratorKind(i));
        EXPECT_EQ(integratorName(IntegratorKind(i)), kIntegratorNames[i]);
    }
    EXPECT_EQ(integratorNamed("bdpt"), std::nullopt);
}

}  // namespace
}  // namespace photon
