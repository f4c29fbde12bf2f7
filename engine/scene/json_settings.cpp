// The "camera" and "render" sections.
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include "scene/json_scene_parts.h"
#include "camera/lens_system.h"

namespace photon::scene_json {

namespace {

constexpr int kMaxResolution = 16384;

void readResolution(const JsonValue& value, CameraDescription& camera) {
    if (!value.json().is_array() || value.json().size() != 2) value.fail("must be an array of 2 integers");
    auto e = value.elements();
    camera.width = int(e[0].integer(1, kMaxResolution));
    camera.height = int(e[1].integer(1, kMaxResolution));
}

// The basis the camera builds from position, look_at and up must exist.
void checkOrientation(JsonObject& obj, const CameraDescription& c) {
    Vec3 view = c.lookAt - c.position;
    if (lengthSquared(view) == 0) throw SceneError(childPath(obj.path(), "look_at"), "must differ from position");
    float sinAngle = length(cross(normalize(view), normalize(c.up)));
    if (!(sinAngle > 1e-4f)) throw SceneError(childPath(obj.path(), "up"), "must not be parallel to the view direction");
}

// "filter": {"type": ..., "radius": r or [rx, ry], and the type's own parameters}.
PixelFilterDescription readPixelFilter(const JsonValue& value) {
    using Kind = PixelFilterDescription::Kind;
    JsonObject obj = value.object();
    PixelFilterDescription f;
    f.kind = static_cast<Kind>(obj.required("type").choice({"box", "triangle", "gaussian", "mitchell", "lanczos"}, "filter"));
    // Up to 8 pixels: a sample is then drawn from 17 x 17 pixels around its own. At least a
    // twentieth of one, where a Gaussian's values still differ in a float.
    const Range radii = Range::closed(0.05, 8);
    const float radius = PixelFilterDescription::defaultRadius(f.kind);
    f.radius = {radius, radius};
    if (auto r = obj.optional("radius")) {
        if (r->json().is_array()) {
            f.radius = r->vec2(radii);
        } else {
            const float each = r->number(radii);
            f.radius = {each, each};
        }
    }
    // A sigma or tau below a hundredth of a pixel would leave a table of zeros (or floats
    // past their range) to sample from.
    if (f.kind == Kind::Gaussian) f.sigma = obj.number("sigma", f.sigma, Range::closed(0.01, 8));
    if (f.kind == Kind::Mitchell) {
        f.b = obj.number("b", f.b, Range::closed(0, 1));
        f.c = obj.number("c", f.c, Range::closed(0, 1));
    }
    if (f.kind == Kind::Lanczos) f.tau = obj.number("tau", f.tau, Range::closed(0.01, 100));
    obj.finish();
    return f;
}

// "lens": [[radius, thickness, index, aperture diameter], ...] in mm, front first (a
// pbrt-v4 lens file's rows).
std::vector<LensInterface> readLensRows(const JsonValue& value) {
    std::vector<LensInterface> rows;
    for (const JsonValue& row : value.elements()) {
        const std::vector<JsonValue> n = row.elements();
        if (n.size() != 4) row.fail("must be [radius, thickness, index, aperture diameter] (mm)");
        const LensInterface s{n[0].number(), n[1].number(), n[2].number(), n[3].number()};
        if (auto why = lensInterfaceError(s)) row.fail(*why);
        rows.push_back(s);
    }
    if (rows.empty()) value.fail("needs at least one interface");
    return rows;
}

}  // namespace

CameraDescription readCamera(const JsonValue& value, const LoadContext& ctx) {
    JsonObject obj = value.object();
    CameraDescription c;
    std::optional<JsonValue> lensValue;
    const JsonValue* lens = nullptr;
    c.projection =
        CameraProjection(obj.choice("type", 0, {"perspective", "orthographic", "spherical", "realistic"}, "type"));
    c.position = obj.required("position").vec3();
    c.lookAt = obj.required("look_at").vec3();
    if (auto up = obj.optional("up")) c.up = up->direction();
    checkOrientation(obj, c);
    if (c.projection == CameraProjection::Orthographic) {
        c.viewHeight = obj.required("view_height").number(Range::positive());
        if (auto fov = obj.optional("fov")) fov->fail("is not used by an orthographic camera (its view is \"view_height\" high)");
        if (auto lens = obj.optional("aperture_radius"); lens && lens->number() != 0)
            lens->fail("must be 0 for an orthographic camera (it has no lens)");
    } else if (c.projection == CameraProjection::Spherical) {
        c.mapping = CameraSphericalMapping(obj.choice("mapping", 0, {"equal_area", "equirectangular"}, "mapping"));
        if (auto fov = obj.optional("fov")) fov->fail("is not used by a spherical camera (it sees every direction)");
        if (auto height = obj.optional("view_height")) height->fail("is only used by an orthographic camera");
        if (auto lens = obj.optional("aperture_radius"); lens && lens->number() != 0)
            lens->fail("must be 0 for a spherical camera (it has no lens)");
    } else if (c.projection == CameraProjection::LensSystem) {
        if (auto fov = obj.optional("fov")) fov->fail("is not used by a realistic camera (its lens and film make its view)");
        if (auto height = obj.optional("view_height")) height->fail("is only used by an orthographic camera");
        if (auto lens = obj.optional("aperture_radius"))
            lens->fail("is not used by a realistic camera (its stop is \"aperture_diameter\", in mm)");
        lensValue = obj.required("lens");
        lens = &*lensValue;
        c.lens = readLensRows(*lens);
        c.lensApertureDiameter = obj.number("aperture_diameter", 0, Range::nonNegative());
        c.filmDiagonal = obj.number("film_diagonal", 35, Range::positive());
    } else {
        c.fovDegrees = obj.required("fov").number(Range::open(0, 180));
        if (auto height = obj.optional("view_height")) height->fail("is only used by an orthographic camera");
    }
    if (c.projection != CameraProjection::LensSystem)
        for (const char* key : {"lens", "aperture_diameter", "film_diagonal"})
            if (auto v = obj.optional(key)) v->fail("is only used by a realistic camera");
    if (auto res = obj.optional("resolution")) readResolution(*res, c);
    c.apertureRadius = obj.number("aperture_radius", 0, Range::nonNegative());
    // By default the point looked at is in focus.
    c.focusDistance = obj.number("focus_distance", length(c.lookAt - c.position), Range::positive());
    // A lens system that cannot focus there says so where it is given.
    if (lens) {
        try {
            LensSystem(c.lens, c.lensApertureDiameter, c.focusDistance, c.filmDiagonal, c.width, c.height);
        } catch (const std::invalid_argument& e) {
            lens->fail(e.what());
        }
    }
    c.leftHanded = obj.choice("handedness", 0, {"right", "left"}, "handedness") == 1;
    if (auto filter = obj.optional("filter")) c.filter = readPixelFilter(*filter);
    if (auto medium = obj.optional("medium")) c.medium = mediumNamed(*medium, ctx);
    obj.finish();
    return c;
}

namespace {

// "auto" (stored as 0: the integrator derives the value) or a length in scene units > 0.
float readAutoOrPositive(const JsonValue& value) {
    const char* expected = "must be \"auto\" or a number > 0";
    if (value.json().is_string()) {
        if (value.string() != "auto") value.fail(expected);
        return 0;
    }
    if (!value.json().is_number()) value.fail(expected);
    return value.number(Range::positive());
}

RadiositySettings readRadiosity(const JsonValue& value) {
    JsonObject obj = value.object();
    RadiositySettings r;
    if (auto size = obj.optional("patch_size")) r.patchSize = readAutoOrPositive(*size);
    r.maxPatches = obj.integer("max_patches", r.maxPatches, 1, 2'000'000);
    r.raysPerPatch = int(obj.integer("rays_per_patch", r.raysPerPatch, 1, 100'000));
    r.directSamples = int(obj.integer("direct_samples", r.directSamples, 1, 65536));
    r.tolerance = obj.number("tolerance", r.tolerance, Range::open(0, 1));
    r.maxIterations = int(obj.integer("max_iterations", r.maxIterations, 1, 1'000'000));
    obj.finish();
    return r;
}

// `true`/`false` as shorthand for {"enabled": ...}; an object turns the filter on unless it
// says "enabled": false.
DenoiseSettings readDenoise(const JsonValue& value) {
    DenoiseSettings d;
    if (value.json().is_boolean()) {
        d.enabled = value.boolean();
        return d;
    }
    if (!value.json().is_object()) value.fail("must be true, false or an object");
    JsonObject obj = value.object();
    d.enabled = obj.boolean("enabled", true);
    d.sigmaSpatial = obj.number("sigma_spatial", d.sigmaSpatial, Range::openClosed(0, 64));
    d.sigmaRange = obj.number("sigma_range", d.sigmaRange, Range::positive());
    d.guide = obj.boolean("guide", d.guide);
    d.sigmaAlbedo = obj.number("sigma_albedo", d.sigmaAlbedo, Range::positive());
    d.sigmaNormal = obj.number("sigma_normal", d.sigmaNormal, Range::positive());
    d.featureSamples = int(obj.integer("feature_samples", d.featureSamples, 1, 1024));
    obj.finish();
    return d;
}

// Photons emitted for one map: a closed scene stores two or three of each, at 20 bytes
// (plus 2 bytes of normal while the maps are built), so 10 million stay under about 700 MB.
constexpr int64_t kMaxMapPhotons = 10'000'000;

// The "photonmap" block: settings of the two-pass photon mapper.
PhotonMapSettings readPhotonMap(const JsonValue& value) {
    JsonObject obj = value.object();
    PhotonMapSettings p;
    p.globalPhotons = obj.integer("global_photons", p.globalPhotons, 0, kMaxMapPhotons);
    p.causticPhotons = obj.integer("caustic_photons", p.causticPhotons, 0, kMaxMapPhotons);
    p.globalNearest = int(obj.integer("global_nearest", p.globalNearest, 1, 10'000));
    p.causticNearest = int(obj.integer("caustic_nearest", p.causticNearest, 1, 10'000));
    if (auto r = obj.optional("global_max_radius")) p.globalMaxRadius = readAutoOrPositive(*r);
    if (auto r = obj.optional("caustic_max_radius")) p.causticMaxRadius = readAutoOrPositive(*r);
    p.gatherRays = int(obj.integer("gather_rays", p.gatherRays, 0, 100'000));
    p.precomputedIrradiance = obj.boolean("precomputed_irradiance", p.precomputedIrradiance);
    obj.finish();
    return p;
}

}  // namespace

RenderSettings readRender(const JsonValue& value) {
    JsonObject obj = value.object();
    RenderSettings r;
    // The choice lists are in the order of the enums they convert to.
    r.integrator = IntegratorKind(obj.choice("integrator", 0, {"sppm", "path", "radiosity", "photonmap"}));
    r.passes = int(obj.integer("passes", r.passes, 1, 1'000'000));
    r.photonsPerPass = obj.integer("photons_per_pass", r.photonsPerPass, 1, 100'000'000);
    r.timeLimitSeconds = obj.number("time_limit", 0, Range::nonNegative());
    // Scene numbers are read as floats; the target is shown back to users (the job record),
    // so it keeps the decimal they wrote (a float's 7 significant digits) rather than 0.15
    // turning into 0.15000000596.
    char decimal[32];
    std::snprintf(decimal, sizeof decimal, "%.7g", double(obj.number("target_error", 0, Range::nonNegative())));
    r.targetError = std::strtod(decimal, nullptr);
    if (auto radius = obj.optional("initial_radius")) r.initialRadius = readAutoOrPositive(*radius);
    r.autoRadiusPhotons = obj.number("auto_radius_photons", r.autoRadiusPhotons, Range::openClosed(0, 10'000));
    r.alpha = obj.number("alpha", r.alpha, Range::open(0, 1));
    r.maxDepth = int(obj.integer("max_depth", r.maxDepth, 1, 1000));
    if (auto seed = obj.optional("seed")) r.seed = seed->unsignedInteger();
    r.kernel = KernelKind(obj.choice("kernel", 0, {"uniform", "biweight", "cone"}));
    r.exposure = obj.number("exposure", 0);
    r.direct = DirectLighting(obj.choice("direct", 0, {"light_sampling", "photons"}));
    r.projectionMaps = obj.boolean("projection_maps", r.projectionMaps);
    r.radiusSchedule = RadiusSchedule(obj.choice("radius_schedule", 0, {"pixel", "global"}));
    r.lightweight = obj.boolean("lightweight", r.lightweight);
    r.lightSampler = LightSamplerKind(obj.choice("light_sampler", 0, {"spatial", "power"}));
    r.photonGuiding = obj.boolean("photon_guiding", r.photonGuiding);
    r.lobeChoice = LobeChoice(obj.choice("lobe_choice", 0, {"learned", "material"}));
    r.adaptiveCameraPaths = obj.boolean("adaptive_camera_paths", r.adaptiveCameraPaths);
    r.adaptiveRadius = obj.boolean("adaptive_radius", r.adaptiveRadius);
    r.discCoverage = obj.boolean("disc_coverage", r.discCoverage);
    r.equiangular = obj.boolean("equiangular", r.equiangular);
    r.sampler = SamplerKind(obj.choice("sampler", 0, {"sobol", "independent"}));
    if (auto volume = obj.optional("volume_photons")) {
        if (volume->json().is_string() && volume->string() == "auto") r.volumePhotons = VolumePhotons::Auto;
        else if (volume->json().is_boolean()) r.volumePhotons = volume->boolean() ? VolumePhotons::Always : VolumePhotons::Never;
        else volume->fail("must be \"auto\", true or false");
    }
    if (auto adaptive = obj.optional("adaptive_photons")) {
        r.adaptivePhotons = adaptive->boolean();
        // The global schedule's passes are rendered apart (on a farm's workers too), each
        // with the photons it was given: nothing could tell them a count chosen later.
        if (r.adaptivePhotons && r.radiusSchedule == RadiusSchedule::Global)
            adaptive->fail("adaptive_photons needs the per-pixel radius schedule (radius_schedule \"pixel\")");
    }
    if (auto bands = obj.optional("bands")) {
        const char* expected = "must be \"auto\" or an integer in [1, 65536]";
        if (bands->json().is_string()) {
            if (bands->string() != "auto") bands->fail(expected);
        } else if (!bands->json().is_number_integer()) {
            bands->fail(expected);
        } else {
            r.bands = static_cast<int>(bands->integer(1, 65536));
        }
    }
    if (auto p = obj.optional("photonmap")) r.photonMap = readPhotonMap(*p);
    if (auto radiosity = obj.optional("radiosity")) r.radiosity = readRadiosity(*radiosity);
    if (auto denoise = obj.optional("denoise")) r.denoise = readDenoise(*denoise);
    obj.finish();
    return r;
}

}  // namespace photon::scene_json
