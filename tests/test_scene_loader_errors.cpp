// Every kind of bad scene gives an exact SceneError naming the JSON path, and nothing crashes.
#include "scene_loader_fixture.h"

using namespace photon::test;
using photon::Color;
using photon::SceneDescription;
using photon::SceneError;
using photon::Vec2;
using photon::Vec3;


// ---- errors: exact messages at exact paths ----

TEST(SceneLoaderErrors, MalformedJson) {
    SceneError e = errorFromText("{\"camera\": {\"fov\": 19.5,}}");
    EXPECT_EQ(e.path(), "");
    EXPECT_EQ(std::string(e.what()).rfind("malformed JSON: parse error at line 1, column 25: syntax error", 0), 0u)
        << e.what();
    EXPECT_EQ(errorFromText("").path(), "");
    EXPECT_EQ(std::string(errorFromText("[1, 2]").what()), "the scene must be a JSON object");
    EXPECT_EQ(std::string(errorFromText(std::string(200, '[') + std::string(200, ']')).what()),
              "malformed JSON: nested deeper than 64 levels");
}

TEST(SceneLoaderErrors, DuplicateField) {
    std::string text = kFullScene;
    text.replace(text.find("\"radius\": 0.3"), 13, "\"radius\": 0.3, \"radius\": 0.4");
    SceneError e = errorFromText(text);
    EXPECT_EQ(std::string(e.what()), "shapes[3].radius: duplicate field");
}

TEST(SceneLoaderErrors, NonFiniteNumbers) {
    std::string text = kFullScene;
    text.replace(text.find("\"radius\": 0.3"), 13, "\"radius\": 1e999");
    SceneError e = errorFromText(text);
    EXPECT_EQ(e.path(), "shapes[3].radius");
    EXPECT_EQ(std::string(e.what()), "shapes[3].radius: must be a finite number");

    text = kFullScene;
    text.replace(text.find("[0.725, 0.71, 0.68]"), 19, "[0.725, -1e999, 0.68]");
    EXPECT_EQ(std::string(errorFromText(text).what()), "materials.white.albedo[1]: must be a finite number");
    // Finite as a double but not as a float.
    expectError([](Json& d) { d["shapes"][3]["center"][0] = 1e300; }, "shapes[3].center[0]", "must be a finite number");
}

TEST(SceneLoaderErrors, MissingRequiredFields) {
    expectError([](Json& d) { d.erase("camera"); }, "camera", "missing required field");
    expectError([](Json& d) { d.erase("materials"); }, "materials", "missing required field");
    expectError([](Json& d) { d.erase("shapes"); }, "shapes", "missing required field");
    expectError([](Json& d) { d["camera"].erase("fov"); }, "camera.fov", "missing required field");
    expectError([](Json& d) { d["shapes"][3].erase("radius"); }, "shapes[3].radius", "missing required field");
    expectError([](Json& d) { d["shapes"][3].erase("material"); }, "shapes[3].material", "missing required field");
    expectError([](Json& d) { d["materials"]["white"].erase("type"); }, "materials.white.type",
                "missing required field");
    expectError([](Json& d) { d["lights"][0].erase("intensity"); }, "lights[0].intensity", "missing required field");
    expectError([](Json& d) { d["shapes"][2]["transform"]["rotate"].erase("angle"); },
                "shapes[2].transform.rotate.angle", "missing required field");
    // A near miss of the missing field is named with it.
    expectError(
        [](Json& d) {
            d["shapes"][3]["raduis"] = d["shapes"][3]["radius"];
            d["shapes"][3].erase("radius");
        },
        "shapes[3].radius",
        "missing required field; found \"raduis\", which is not a field here: a misspelling of \"radius\"?");
    expectError(
        [](Json& d) {
            d["camera"]["FOV"] = d["camera"]["fov"];
            d["camera"].erase("fov");
        },
        "camera.fov", "missing required field; found \"FOV\", which is not a field here: a misspelling of \"fov\"?");
    // Nothing near: the plain message.
    expectError(
        [](Json& d) {
            d["shapes"][3]["size"] = 1;
            d["shapes"][3].erase("radius");
        },
        "shapes[3].radius", "missing required field");
}

TEST(SceneLoaderErrors, RangeChecks) {
    expectError([](Json& d) { d["shapes"][3]["radius"] = -1; }, "shapes[3].radius", "must be > 0");
    expectError([](Json& d) { d["camera"]["resolution"] = {0, 512}; }, "camera.resolution[0]",
                "must be an integer in [1, 16384]");
    expectError([](Json& d) { d["camera"]["resolution"] = {512, 16385}; }, "camera.resolution[1]",
                "must be an integer in [1, 16384]");
    expectError([](Json& d) { d["camera"]["resolution"] = {512}; }, "camera.resolution",
                "must be an array of 2 integers");
    expectError([](Json& d) { d["render"]["alpha"] = 1.5; }, "render.alpha", "must be in (0, 1)");
    expectError([](Json& d) { d["render"]["passes"] = 1.5; }, "render.passes", "must be an integer in [1, 1000000]");
    expectError([](Json& d) { d["render"]["passes"] = 0; }, "render.passes", "must be an integer in [1, 1000000]");
    expectError([](Json& d) { d["render"]["max_depth"] = 1001; }, "render.max_depth", "must be an integer in [1, 1000]");
    expectError([](Json& d) { d["render"]["seed"] = -1; }, "render.seed", "must be an integer >= 0");
    expectError([](Json& d) { d["render"]["time_limit"] = -1; }, "render.time_limit", "must be >= 0");
    expectError([](Json& d) { d["render"]["target_error"] = -0.5; }, "render.target_error", "must be >= 0");
    expectError(
        [](Json& d) {
            d["render"]["radius_schedule"] = "global";
            d["render"]["adaptive_photons"] = true;
        },
        "render.adaptive_photons", "adaptive_photons needs the per-pixel radius schedule (radius_schedule \"pixel\")");
    expectError([](Json& d) { d["render"]["bands"] = "many"; }, "render.bands",
                "must be \"auto\" or an integer in [1, 65536]");
    expectError([](Json& d) { d["render"]["bands"] = 2.5; }, "render.bands",
                "must be \"auto\" or an integer in [1, 65536]");
    expectError([](Json& d) { d["render"]["bands"] = 0; }, "render.bands", "must be an integer in [1, 65536]");
    expectError([](Json& d) { d["render"]["volume_photons"] = "yes"; }, "render.volume_photons",
                "must be \"auto\", true or false");
    expectError([](Json& d) { d["render"]["volume_photons"] = 1; }, "render.volume_photons",
                "must be \"auto\", true or false");
    expectError([](Json& d) { d["render"]["initial_radius"] = "big"; }, "render.initial_radius",
                "must be \"auto\" or a number > 0");
    expectError([](Json& d) { d["render"]["initial_radius"] = 0; }, "render.initial_radius", "must be > 0");
    expectError([](Json& d) { d["render"]["auto_radius_photons"] = 0; }, "render.auto_radius_photons",
                "must be in (0, 10000]");
    expectError([](Json& d) { d["render"]["auto_radius_photons"] = "many"; }, "render.auto_radius_photons",
                "must be a number");
    expectError([](Json& d) { d["render"]["radiosity"]["patch_size"] = 0; }, "render.radiosity.patch_size",
                "must be > 0");
    expectError([](Json& d) { d["render"]["radiosity"]["patch_size"] = "fine"; }, "render.radiosity.patch_size",
                "must be \"auto\" or a number > 0");
    expectError([](Json& d) { d["render"]["radiosity"]["max_patches"] = 0; }, "render.radiosity.max_patches",
                "must be an integer in [1, 2000000]");
    expectError([](Json& d) { d["render"]["radiosity"]["rays_per_patch"] = 100001; },
                "render.radiosity.rays_per_patch", "must be an integer in [1, 100000]");
    expectError([](Json& d) { d["render"]["radiosity"]["direct_samples"] = 0; }, "render.radiosity.direct_samples",
                "must be an integer in [1, 65536]");
    expectError([](Json& d) { d["render"]["radiosity"]["tolerance"] = 0; }, "render.radiosity.tolerance",
                "must be in (0, 1)");
    expectError([](Json& d) { d["render"]["radiosity"]["max_iterations"] = 2.5; }, "render.radiosity.max_iterations",
                "must be an integer in [1, 1000000]");
    expectError([](Json& d) { d["render"]["radiosity"] = 1; }, "render.radiosity", "must be an object");
    expectError([](Json& d) { d["camera"]["fov"] = 180; }, "camera.fov", "must be in (0, 180)");
    expectError([](Json& d) { d["camera"]["aperture_radius"] = -0.1; }, "camera.aperture_radius", "must be >= 0");
    expectError([](Json& d) { d["camera"]["focus_distance"] = 0; }, "camera.focus_distance", "must be > 0");
    expectError([](Json& d) { d["camera"]["filter"] = {{"type", "cubic"}}; }, "camera.filter.type",
                "unknown filter \"cubic\" (expected one of box, triangle, gaussian, mitchell, lanczos)");
    expectError([](Json& d) { d["camera"]["filter"] = {{"type", "gaussian"}, {"radius", 9}}; }, "camera.filter.radius",
                "must be in [0.05, 8]");
    expectError([](Json& d) { d["camera"]["filter"] = {{"type", "triangle"}, {"radius", {1, 0}}}; },
                "camera.filter.radius[1]", "must be in [0.05, 8]");
    expectError([](Json& d) { d["camera"]["filter"] = {{"type", "triangle"}, {"sigma", 0.5}}; }, "camera.filter.sigma",
                "unknown field");
    expectError([](Json& d) { d["camera"]["filter"] = {{"type", "mitchell"}, {"b", 1.5}}; }, "camera.filter.b",
                "must be in [0, 1]");
    expectError([](Json& d) { d["camera"]["filter"] = {{"radius", 1}}; }, "camera.filter.type", "missing required field");
    expectError([](Json& d) { d["camera"]["filter"] = {{"type", "gaussian"}, {"sigma", 1e-30}}; },
                "camera.filter.sigma", "must be in [0.01, 8]");
    expectError([](Json& d) { d["camera"]["filter"] = {{"type", "lanczos"}, {"tau", 0}}; }, "camera.filter.tau",
                "must be in [0.01, 100]");
    expectError([](Json& d) { d["materials"]["white"]["albedo"] = {0.5, 1.2, 0.5}; }, "materials.white.albedo[1]",
                "must be in [0, 1]");
    expectError([](Json& d) { d["materials"]["metal"]["roughness"] = 2; }, "materials.metal.roughness",
                "must be in [0, 1]");
    expectError([](Json& d) { d["materials"]["glass"]["ior"] = 0; }, "materials.glass.ior", "must be > 0");
    expectError([](Json& d) { d["materials"]["glass"]["two_sided"] = false; }, "materials.glass.two_sided",
                "must be true for a material that lets light through");
    expectError([](Json& d) { d["materials"]["metal"]["two_sided"] = 1; }, "materials.metal.two_sided",
                "must be true or false");
    expectError([](Json& d) { d["materials"]["glass"]["roughness"] = -0.1; }, "materials.glass.roughness",
                "must be in [0, 1]");
    expectError([](Json& d) { d["materials"]["glass"].update({{"thin", true}, {"roughness", 0.2}}); },
                "materials.glass.roughness", "must be 0 for a thin dielectric (its faces are smooth)");
    expectError([](Json& d) { d["shapes"][5]["emission"] = {1, -1, 1}; }, "shapes[5].emission[1]", "must be >= 0");
    expectError([](Json& d) { d["lights"][0]["intensity"] = {1, 1, -1}; }, "lights[0].intensity[2]", "must be >= 0");
    expectError([](Json& d) { d["lights"][1]["cone_angle"] = 95; }, "lights[1].cone_angle", "must be in (0, 90]");
    expectError([](Json& d) { d["lights"][1]["falloff_angle"] = 31; }, "lights[1].falloff_angle",
                "must be <= cone_angle");
}

TEST(SceneLoaderErrors, PhotonMapSettings) {
    expectError([](Json& d) { d["render"]["projection_maps"] = "yes"; }, "render.projection_maps",
                "must be true or false");
    expectError([](Json& d) { d["render"]["photonmap"] = 1; }, "render.photonmap", "must be an object");
    expectError([](Json& d) { d["render"]["photonmap"]["gather_rays"] = -1; }, "render.photonmap.gather_rays",
                "must be an integer in [0, 100000]");
    expectError([](Json& d) { d["render"]["photonmap"]["global_photons"] = 1.5; }, "render.photonmap.global_photons",
                "must be an integer in [0, 10000000]");
    expectError([](Json& d) { d["render"]["photonmap"]["caustic_nearest"] = 0; }, "render.photonmap.caustic_nearest",
                "must be an integer in [1, 10000]");
    expectError([](Json& d) { d["render"]["photonmap"]["global_max_radius"] = "big"; },
                "render.photonmap.global_max_radius", "must be \"auto\" or a number > 0");
    expectError([](Json& d) { d["render"]["photonmap"]["caustic_max_radius"] = 0; },
                "render.photonmap.caustic_max_radius", "must be > 0");
    expectError([](Json& d) { d["render"]["photonmap"]["precomputed_irradiance"] = 1; },
                "render.photonmap.precomputed_irradiance", "must be true or false");
    expectError([](Json& d) { d["render"]["photonmap"]["k"] = 5; }, "render.photonmap.k", "unknown field");
}

TEST(SceneLoaderErrors, WrongTypes) {
    expectError([](Json& d) { d["shapes"][3]["radius"] = "big"; }, "shapes[3].radius", "must be a number");
    expectError([](Json& d) { d["shapes"][3]["radius"] = true; }, "shapes[3].radius", "must be a number");
    expectError([](Json& d) { d["shapes"][3]["center"] = {1, 2}; }, "shapes[3].center", "must be an array of 3 numbers");
    expectError([](Json& d) { d["shapes"][3]["center"] = {1, "2", 3}; }, "shapes[3].center[1]", "must be a number");
    expectError([](Json& d) { d["shapes"][1]["flip_normals"] = 1; }, "shapes[1].flip_normals", "must be true or false");
    expectError([](Json& d) { d["shapes"][0]["material"] = 3; }, "shapes[0].material", "must be a string");
    expectError([](Json& d) { d["materials"]["glass"]["thin"] = 1; }, "materials.glass.thin", "must be true or false");
    expectError([](Json& d) { d["camera"] = Json::array(); }, "camera", "must be an object");
    expectError([](Json& d) { d["shapes"] = Json::object(); }, "shapes", "must be an array");
    expectError([](Json& d) { d["shapes"] = Json::array(); }, "shapes", "must contain at least one shape");
    expectError([](Json& d) { d["lights"] = 1; }, "lights", "must be an array");
    expectError([](Json& d) { d["materials"]["white"]["albedo"] = "red"; }, "materials.white.albedo",
                "must be an array of 3 numbers or a texture object");
    expectError([](Json& d) { d["shapes"][2]["transform"]["scale"] = "x"; }, "shapes[2].transform.scale",
                "must be a number or an array of 3 numbers");
}

TEST(SceneLoaderErrors, UnknownNames) {
    expectError([](Json& d) { d["shapes"][0]["material"] = "foo"; }, "shapes[0].material", "unknown material \"foo\"");
    expectError([](Json& d) { d["shapes"][1]["type"] = "cone"; }, "shapes[1].type",
                "unknown type \"cone\" (expected one of quad, sphere, mesh, curves, instance)");
    expectError([](Json& d) { d["lights"][0]["type"] = "area"; }, "lights[0].type",
                "unknown type \"area\" (expected one of point, spot, directional, environment, projection)");
    expectError([](Json& d) { d["materials"]["white"]["type"] = "lambert"; }, "materials.white.type",
                "unknown type \"lambert\" (expected one of diffuse, dielectric, mirror, conductor, plastic, "
                "coated_diffuse, coated_conductor, diffuse_transmission, mix, hair, measured)");
    expectError(
        [](Json& d) {
            d["materials"]["white"] = {{"type", "diffuse_transmission"}, {"reflectance", {0.6, 0.6, 0.6}},
                                       {"transmittance", {0.3, 0.5, 0.3}}};
        },
        "materials.white",
        "reflectance + transmittance must not exceed 1 in any channel (a sheet cannot pass on more light than "
        "arrives)");
    expectError([](Json& d) { d["camera"]["type"] = "fisheye"; }, "camera.type",
                "unknown type \"fisheye\" (expected one of perspective, orthographic, spherical, realistic)");
    expectError([](Json& d) { d["render"]["integrator"] = "bdpt"; }, "render.integrator",
                "unknown value \"bdpt\" (expected one of sppm, path, radiosity, photonmap)");
    expectError([](Json& d) { d["render"]["kernel"] = "gauss"; }, "render.kernel",
                "unknown value \"gauss\" (expected one of uniform, biweight, cone)");
    expectError([](Json& d) { d["render"]["light_sampler"] = "bvh"; }, "render.light_sampler",
                "unknown value \"bvh\" (expected one of spatial, power)");
    expectError([](Json& d) { d["render"]["direct"] = "none"; }, "render.direct",
                "unknown value \"none\" (expected one of light_sampling, photons)");
}

TEST(SceneLoaderErrors, Denoise) {
    expectError([](Json& d) { d["render"]["denoise"] = 1; }, "render.denoise", "must be true, false or an object");
    expectError([](Json& d) { d["render"]["denoise"] = {{"sigma_spatial", 0}}; }, "render.denoise.sigma_spatial",
                "must be in (0, 64]");
    expectError([](Json& d) { d["render"]["denoise"] = {{"sigma_range", -1}}; }, "render.denoise.sigma_range",
                "must be > 0");
    expectError([](Json& d) { d["render"]["denoise"] = {{"sigma_albedo", 0}}; }, "render.denoise.sigma_albedo",
                "must be > 0");
    expectError([](Json& d) { d["render"]["denoise"] = {{"sigma_normal", "wide"}}; }, "render.denoise.sigma_normal",
                "must be a number");
    expectError([](Json& d) { d["render"]["denoise"] = {{"feature_samples", 0}}; }, "render.denoise.feature_samples",
                "must be an integer in [1, 1024]");
    expectError([](Json& d) { d["render"]["denoise"] = {{"guide", 1}}; }, "render.denoise.guide", "must be true or false");
    expectError([](Json& d) { d["render"]["denoise"] = {{"sigma", 1}}; }, "render.denoise.sigma", "unknown field");
}

TEST(SceneLoaderErrors, UnknownFieldsAtEveryDepth) {
    expectError([](Json& d) { d["colour"] = 1; }, "colour", "unknown field");
    expectError([](Json& d) { d["render"]["pases"] = 64; }, "render.pases", "unknown field");
    expectError([](Json& d) { d["render"]["radiosity"]["patches"] = 64; }, "render.radiosity.patches", "unknown field");
    expectError([](Json& d) { d["camera"]["fov_y"] = 20; }, "camera.fov_y", "unknown field");
    expectError([](Json& d) { d["shapes"][2]["colour"] = {1, 0, 0}; }, "shapes[2].colour", "unknown field");
    expectError([](Json& d) { d["shapes"][2]["transform"]["rotate"]["axes"] = {0, 1, 0}; },
                "shapes[2].transform.rotate.axes", "unknown field");
    expectError([](Json& d) { d["materials"]["white"]["albedoo"] = {1, 1, 1}; }, "materials.white.albedoo",
                "unknown field");
    expectError([](Json& d) { d["materials"]["wood"]["albedo"]["filter"] = "nearest"; },
                "materials.wood.albedo.filter", "unknown field");
    expectError([](Json& d) { d["lights"][2]["position"] = {0, 1, 0}; }, "lights[2].position", "unknown field");
    // A field of another material or shape type is unknown here too.
    expectError([](Json& d) { d["materials"]["glass"]["albedo"] = {1, 1, 1}; }, "materials.glass.albedo",
                "unknown field");
    expectError([](Json& d) { d["shapes"][3]["edge_u"] = {1, 0, 0}; }, "shapes[3].edge_u", "unknown field");
}

TEST(SceneLoaderErrors, Geometry) {
    expectError([](Json& d) { d["shapes"][0]["edge_v"] = {0, 0, 4}; }, "shapes[0]",
                "quad has zero area (edge_u and edge_v are parallel or zero)");
    expectError([](Json& d) { d["shapes"][4]["indices"] = {0, 1, 3}; }, "shapes[4].indices[2]",
                "must be an integer in [0, 2]");
    expectError([](Json& d) { d["shapes"][4]["indices"] = {0, 1, -1}; }, "shapes[4].indices[2]",
                "must be an integer in [0, 2]");
    expectError([](Json& d) { d["shapes"][4]["indices"] = {0, 1}; }, "shapes[4].indices",
                "must have a length that is a multiple of 3");
    expectError([](Json& d) { d["shapes"][4]["indices"] = Json::array(); }, "shapes[4].indices",
                "must contain at least one triangle (3 indices)");
    expectError([](Json& d) { d["shapes"][4]["positions"] = Json::array(); }, "shapes[4].positions",
                "must not be empty");
    expectError([](Json& d) { d["shapes"][4]["normals"].erase(2); }, "shapes[4].normals",
                "must have one entry per position (3)");
    expectError([](Json& d) { d["shapes"][4]["normals"][1] = {0, 0, 0}; }, "shapes[4].normals[1]",
                "must not be the zero vector");
    expectError([](Json& d) { d["shapes"][4]["uvs"][0] = {0, 0, 0}; }, "shapes[4].uvs[0]",
                "must be an array of 2 numbers");
    expectError([](Json& d) { d["shapes"][4]["file"] = "meshes/tri.obj"; }, "shapes[4]",
                "a mesh needs exactly one of \"file\" or \"positions\"");
    expectError([](Json& d) { d["shapes"][4].erase("positions"); }, "shapes[4]",
                "a mesh needs exactly one of \"file\" or \"positions\"");
}

TEST(SceneLoaderErrors, Transforms) {
    expectError([](Json& d) { d["shapes"][3]["transform"] = {{"scale", {1, 2, 1}}}; }, "shapes[3].transform",
                "a sphere can only be scaled uniformly (one scale factor for all axes)");
    expectError([](Json& d) { d["shapes"][2]["transform"]["scale"] = 0; }, "shapes[2].transform.scale",
                "must not be 0");
    expectError([](Json& d) { d["shapes"][2]["transform"]["scale"] = {1, 0, 1}; }, "shapes[2].transform.scale[1]",
                "must not be 0");
    expectError([](Json& d) { d["shapes"][2]["transform"]["rotate"]["axis"] = {0, 0, 0}; },
                "shapes[2].transform.rotate.axis", "must not be the zero vector");
    expectError([](Json& d) { d["shapes"][2]["transform"]["matrix"] = Json::array(); }, "shapes[2].transform",
                "use either \"matrix\" or \"scale\"/\"rotate\"/\"translate\", not both");
    expectError(
        [](Json& d) { d["shapes"][4]["transform"] = {{"matrix", {1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, 0, 1, 1}}}; },
        "shapes[4].transform.matrix", "the last row must be 0, 0, 0, 1");
    expectError([](Json& d) { d["shapes"][4]["transform"] = {{"matrix", {1, 0, 0, 0}}}; },
                "shapes[4].transform.matrix", "must be an array of 16 numbers");
    expectError(
        [](Json& d) { d["shapes"][4]["transform"] = {{"matrix", {1, 0, 0, 0, 0, 1, 0, 0, 1, 1, 0, 0, 0, 0, 0, 1}}}; },
        "shapes[4].transform", "must be invertible (it flattens the shape)");
}

TEST(SceneLoaderErrors, CameraOrientation) {
    expectError([](Json& d) { d["camera"]["up"] = {0, 0, 2}; }, "camera.up", "must not be parallel to the view direction");
    expectError([](Json& d) { d["camera"]["look_at"] = {0, 1, 6.8}; }, "camera.look_at", "must differ from position");
}

TEST(SceneLoaderErrors, Lights) {
    expectError(
        [](Json& d) {
            d.erase("lights");
            d["shapes"][5].erase("emission");
        },
        "lights", "scene has no light (add a light, an emissive shape or a medium that emits)");
    expectError(
        [](Json& d) {
            d["lights"] = Json::array();
            d["shapes"][5]["emission"] = {0, 0, 0};
        },
        "lights", "scene has no light (add a light, an emissive shape or a medium that emits)");
    expectError([](Json& d) { d["lights"][2]["direction"] = {0, 0, 0}; }, "lights[2].direction",
                "must not be the zero vector");
    auto portal = [](Json corners) {
        return [corners](Json& d) {
            d["lights"].push_back({{"type", "environment"}, {"radiance", {1, 1, 1}}, {"portal", corners}});
        };
    };
    expectError(portal({{0, 0, 0}, {1, 0, 0}, {1, 1, 0}}), "lights[4].portal", "must be 4 corners, not 3");
    expectError(portal({{0, 0, 0}, {1, 0, 0}, {2, 1, 0}, {1, 1, 0}}), "lights[4].portal",
                "must be a rectangle: the edges from the first corner are not at right angles");
    expectError(portal({{0, 0, 0}, {0, 0, 0}, {0, 0, 0}, {0, 0, 0}}), "lights[4].portal",
                "the corners must span a rectangle of non-zero area");
}

TEST(SceneLoaderErrors, FilePaths) {
    const std::string inside = "must be a relative path inside the scene folder";
    expectError([](Json& d) { d["shapes"][2]["file"] = "/etc/passwd"; }, "shapes[2].file", inside);
    expectError([](Json& d) { d["shapes"][2]["file"] = "../outside.obj"; }, "shapes[2].file", inside);
    expectError([](Json& d) { d["shapes"][2]["file"] = "meshes/../../outside.obj"; }, "shapes[2].file", inside);
    expectError([](Json& d) { d["shapes"][2]["file"] = ""; }, "shapes[2].file", inside);
    expectError([](Json& d) { d["shapes"][2]["file"] = "meshes/link.obj"; }, "shapes[2].file", inside);  // symlink
    expectError([](Json& d) { d["materials"]["wood"]["albedo"]["texture"] = "/tmp/x.png"; },
                "materials.wood.albedo.texture", inside);
    expectError([](Json& d) { d["materials"]["wood"]["albedo"]["texture"] = "textures/../../x.png"; },
                "materials.wood.albedo.texture", inside);
}

TEST(SceneLoaderErrors, UnreadableFiles) {
    expectError([](Json& d) { d["shapes"][2]["file"] = "meshes/missing.obj"; }, "shapes[2].file",
                "file not found: meshes/missing.obj");
    expectError([](Json& d) { d["shapes"][2]["file"] = "meshes"; }, "shapes[2].file", "not a regular file: meshes");
    expectError([](Json& d) { d["materials"]["wood"]["albedo"]["texture"] = "textures/missing.png"; },
                "materials.wood.albedo.texture", "file not found: textures/missing.png");
    // Invalid contents: the library's reason, without the folder the scene sits in.
    for (auto [edit, path] : std::vector<std::pair<std::function<void(Json&)>, std::string>>{
             {[](Json& d) { d["shapes"][2]["file"] = "meshes/corrupt.obj"; }, "shapes[2].file"},
             {[](Json& d) { d["shapes"][2]["file"] = "meshes/escape.gltf"; }, "shapes[2].file"},
             {[](Json& d) { d["materials"]["wood"]["albedo"]["texture"] = "textures/corrupt.png"; },
              "materials.wood.albedo.texture"}}) {
        Json doc = fullScene();
        edit(doc);
        SceneError e = errorFromText(doc.dump());
        EXPECT_EQ(e.path(), path);
        std::string what = e.what();
        EXPECT_GT(what.size(), path.size() + 2) << what;
        EXPECT_EQ(what.find(fixture().root.string()), std::string::npos) << what;
    }
}

TEST(SceneLoaderErrors, LoadSceneFileUnreadable) {
    const fs::path missing = fixture().scene / "missing.json";
    try {
        photon::loadSceneFile(missing);
        FAIL() << "loaded a missing file";
    } catch (const SceneError& e) {
        EXPECT_EQ(e.path(), "");
        EXPECT_EQ(std::string(e.what()), "cannot read scene file \"" + missing.string() + "\": No such file or directory");
    }
    try {
        photon::loadSceneFile(fixture().scene);
        FAIL() << "loaded a directory";
    } catch (const SceneError& e) {
        EXPECT_EQ(std::string(e.what()), "cannot read scene file \"" + fixture().scene.string() + "\": it is a directory");
    }
}

// Every leaf of the full scene replaced by values of the wrong kind: each load either
// succeeds or throws a SceneError; nothing else escapes and nothing crashes.
TEST(SceneLoaderErrors, MutatedScenesNeverCrash) {
    const Json flat = fullScene().flatten();
    const Json junk[] = {nullptr, "x", -1, 0, 1e30, -1e30, 0.5, true, Json::array(), Json::object(), {1, 2, 3}};
    int errors = 0;
    for (auto it = flat.begin(); it != flat.end(); ++it) {
        for (const Json& j : junk) {
            Json doc = fullScene();
            doc[Json::json_pointer(it.key())] = j;
            try {
                photon::loadSceneJson(doc.dump(), fixture().scene);
            } catch (const SceneError&) {
                ++errors;
            } catch (const std::exception& e) {
                ADD_FAILURE() << it.key() << " = " << j.dump() << ": " << e.what();
            }
        }
    }
    EXPECT_GT(errors, 0);
}