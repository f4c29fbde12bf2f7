// Camera, Film, Sampler and Integrator: photon's camera and render settings.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <sstream>
#include "description/pixel_filter_description.h"
#include "import/pbrt/lens_system.h"
#include "import/pbrt/pbrt_builder.h"
#include "scene/scene_paths.h"

namespace photon::pbrt {

namespace {
constexpr double kDegrees = 180.0 / 3.14159265358979323846;
}

void SceneBuilder::camera(const Directive& d) {
    Params p(d);
    const std::string& type = d.strings.at(0);
    if (type != "perspective" && type != "orthographic" && type != "spherical" && type != "realistic")
        fail(d.where, "Camera \"" + type + "\" is not supported (photon has perspective, orthographic, spherical and realistic cameras)");
    camera_.orthographic = type == "orthographic";
    if (std::abs(pointCtm(d).determinant()) < 1e-12f) fail(d.where, "Camera: the transform is singular");
    camera_.seen = true;
    camera_.where = d.where;
    // pbrt-v4's exposure time, which its film's sensor multiplies the image by.
    exposureTime_ = p.number("shutterclose", 1) - p.number("shutteropen", 0);
    if (!(exposureTime_ > 0)) fail(d.where, "Camera: \"shutterclose\" must come after \"shutteropen\"");
    // The CTM is camera-from-world here; pbrt names its inverse "camera".
    camera_.cameraToWorld = state_.ctm.inverse();
    camera_.medium = state_.outsideMedium;
    coordinateSystems_["camera"] = {camera_.cameraToWorld};
    if (type == "spherical") {
        const std::string mapping = p.string("mapping", "equalarea");
        if (mapping != "equalarea" && mapping != "equirectangular")
            fail(d.where, "Camera \"spherical\": mapping must be \"equalarea\" or \"equirectangular\", not \"" + mapping + "\"");
        camera_.sphericalMapping = mapping == "equalarea" ? "equal_area" : "equirectangular";
        for (const char* unused : {"lensradius", "focaldistance", "screenwindow", "frameaspectratio", "fov"}) p.find(unused);
        return;
    }
    if (type == "realistic") {
        realisticCamera(d);
        return;
    }
    if (!camera_.orthographic) {
        camera_.fov = p.number("fov", 90);
        if (!(camera_.fov > 0 && camera_.fov < 180)) fail(d.where, "Camera: fov must be in (0, 180)");
    }
    camera_.lensRadius = p.number("lensradius", 0);
    if (camera_.orthographic && camera_.lensRadius > 0)
        fail(d.where, "Camera \"orthographic\": a lens (lensradius) is not supported");
    camera_.focalDistance = p.number("focaldistance", 1e6);
    if (p.has("screenwindow")) camera_.screenWindow = p.numbers("screenwindow", {"float"});
    // pbrt-v4 spans its default screen window over this aspect ratio instead of the film's
    // (checked in writeCameraAndRender, once the film is known).
    if (auto frame = p.number("frameaspectratio")) camera_.frameAspectRatio = *frame;
}

// pbrt-v4's RealisticCamera: its lens file's rows, traced ray by ray (camera/lens_system.h),
// its aperture diameter (pbrt-v4's default 1 mm, clamped to the stop's) and focus distance;
// the film's diagonal comes with the Film.
void SceneBuilder::realisticCamera(const Directive& d) {
    Params p(d);
    const std::string file = p.string("lensfile", "");
    if (file.empty()) fail(d.where, "Camera \"realistic\" needs a \"lensfile\"");
    if (auto why = checkRelativePath(file)) fail(d.where, "Camera \"realistic\": \"" + file + "\": " + *why);
    const std::filesystem::path path = baseDir_ / file;
    std::ifstream in(path);
    if (!in || !isInsideFolder(path, baseDir_)) fail(d.where, "Camera \"realistic\": lens file not found: " + file);
    std::stringstream text;
    text << in.rdbuf();
    const LensFile lens = parseLensFile(text.str());
    if (!lens.error.empty()) fail(d.where, "Camera \"realistic\": " + file + ": " + lens.error);
    camera_.lens = lens.interfaces;
    camera_.lensApertureMm = p.number("aperturediameter", 1.0);
    camera_.focalDistance = p.number("focusdistance", 10.0);
    if (!(camera_.lensApertureMm > 0)) fail(d.where, "Camera \"realistic\": \"aperturediameter\" must be > 0");
    if (!(camera_.focalDistance > 0)) fail(d.where, "Camera \"realistic\": \"focusdistance\" must be > 0");
    for (const char* unused : {"dispersionfactor", "aperture"})
        if (p.find(unused)) warn(d.where, std::string("Camera \"realistic\": \"") + unused + "\" is not supported; left out");
}

namespace {
// pbrt-v4's filter when a file names none: the Gaussian, with photon's (and pbrt's) defaults.
Json defaultFilter() {
    using Kind = PixelFilterDescription::Kind;
    return {{"type", "gaussian"},
            {"radius", PixelFilterDescription::defaultRadius(Kind::Gaussian)},
            {"sigma", PixelFilterDescription{}.sigma}};
}
}  // namespace

// pbrt-v4's filters and their parameters (sec. 8.8) as photon's camera "filter".
void SceneBuilder::pixelFilter(const Directive& d) {
    Params p(d);
    const std::string& type = d.strings.at(0);
    using Kind = PixelFilterDescription::Kind;
    struct Name {
        const char* pbrt;
        const char* photon;
        Kind kind;
    };
    static constexpr Name kNames[] = {{"box", "box", Kind::Box},
                                      {"triangle", "triangle", Kind::Triangle},
                                      {"gaussian", "gaussian", Kind::Gaussian},
                                      {"mitchell", "mitchell", Kind::Mitchell},
                                      {"sinc", "lanczos", Kind::Lanczos}};
    const Name* name = nullptr;
    for (const Name& n : kNames)
        if (type == n.pbrt) name = &n;
    if (!name) {
        warn(d.where, "PixelFilter \"" + type + "\" is not a pbrt-v4 filter; the box filter is used");
        camera_.filter = {{"type", "box"}};
        return;
    }
    // pbrt-v4's defaults are photon's (pixel_filter_description.h).
    const PixelFilterDescription defaults;
    const double radius = PixelFilterDescription::defaultRadius(name->kind);
    const double x = p.number("xradius", radius), y = p.number("yradius", radius);
    if (!(x >= 0.05 && x <= 8 && y >= 0.05 && y <= 8))
        fail(d.where, "PixelFilter: xradius and yradius must be in [0.05, 8]");
    Json f = {{"type", name->photon}, {"radius", {x, y}}};
    // The ranges photon's camera.filter takes (scene-format.md), named with the file's line.
    auto within = [&](const char* param, double fallback, double lo, double hi, const char* range) {
        const double v = p.number(param, fallback);
        if (!(v >= lo && v <= hi)) fail(d.where, "PixelFilter: " + std::string(param) + " must be in " + range);
        return v;
    };
    if (name->kind == Kind::Gaussian) f["sigma"] = within("sigma", defaults.sigma, 0.01, 8, "[0.01, 8]");
    if (name->kind == Kind::Mitchell)
        f["b"] = within("B", defaults.b, 0, 1, "[0, 1]"), f["c"] = within("C", defaults.c, 0, 1, "[0, 1]");
    if (name->kind == Kind::Lanczos) f["tau"] = within("tau", defaults.tau, 0.01, 100, "[0.01, 100]");
    if (type == "mitchell" || type == "sinc")
        warn(d.where, "PixelFilter \"" + type + "\": its negative lobes are left out (photon's pixel estimates are not negative)");
    camera_.filter = std::move(f);
}

void SceneBuilder::film(const Directive& d) {
    Params p(d);
    width_ = static_cast<int>(p.number("xresolution", 1280));
    height_ = static_cast<int>(p.number("yresolution", 720));
    iso_ = p.number("iso", 100);
    if (!(iso_ > 0)) fail(d.where, "Film: \"iso\" must be > 0");
    // The sensor's diagonal in mm: the film a realistic camera's lens images onto.
    filmDiagonalMm_ = p.number("diagonal", 35);
    if (!(filmDiagonalMm_ > 0)) fail(d.where, "Film: \"diagonal\" must be > 0");
    p.find("filename");  // photon's outputs are named by its caller
}

void SceneBuilder::sampler(const Directive& d) {
    Params p(d);
    const std::string& type = d.strings.at(0);
    // pbrt-v4's samples a pixel: xsamples x ysamples for "stratified" (4 x 4 by default; its
    // "jitter" is photon's always), pixelsamples for the others (4 by default for
    // "independent", 16 for the rest).
    if (type == "stratified") {
        p.find("jitter");
        render_["passes"] = static_cast<int64_t>(p.number("xsamples", 4) * p.number("ysamples", 4));
    } else {
        render_["passes"] = static_cast<int64_t>(p.number("pixelsamples", type == "independent" ? 4 : 16));
    }
    // pbrt-v4's "independent" draws independent numbers, as photon's does; its other samplers
    // (zsobol, the default, sobol, paddedsobol, halton, pmj02bn, stratified) stratify each
    // pixel's samples, as photon's Owen-scrambled Sobol passes do.
    render_["sampler"] = type == "independent" ? "independent" : "sobol";
}

void SceneBuilder::integrator(const Directive& d) {
    Params p(d);
    const std::string& type = d.strings.at(0);
    render_["integrator"] = "sppm";
    render_["max_depth"] = static_cast<int64_t>(p.number("maxdepth", 5));
    // pbrt-v4's "bvh" and "exhaustive" samplers weigh lights by their bounds at the point, as
    // photon's spatial sampler does; "uniform" has no counterpart and becomes the default.
    if (auto sampler = p.string("lightsampler")) render_["light_sampler"] = *sampler == "power" ? "power" : "spatial";
    if (type == "sppm") {
        // pbrt-v4 traces one photon a pixel where the file gives no positive count (its
        // SPPMIntegrator, from the film's pixel bounds); the film may come later.
        if (auto photons = p.number("photonsperiteration"); photons && *photons > 0)
            render_["photons_per_pass"] = static_cast<int64_t>(*photons);
        else
            photonsPerPixel_ = true;
        if (auto radius = p.number("radius")) render_["initial_radius"] = *radius;
        if (auto seed = p.number("seed")) render_["seed"] = static_cast<int64_t>(*seed);
        if (auto iterations = p.number("iterations")) render_["passes"] = static_cast<int64_t>(*iterations);
        return;
    }
    warn(d.where, "Integrator \"" + type + "\" rendered with photon's SPPM (its maxdepth kept)");
}

void SceneBuilder::writeCameraAndRender() {
    if (!camera_.seen) throw SceneError("", "the pbrt scene has no Camera");
    const Transform& c = camera_.cameraToWorld;
    const Vec3 position = c.point({0, 0, 0});
    const Vec3 forward = normalize(c.vector({0, 0, 1})), up = normalize(c.vector({0, 1, 0}));
    const Vec3 right = c.vector({1, 0, 0});
    // The way the image's centre looks and its right: pbrt-v4's spherical images are centred
    // on camera space's -x, with -z to their right (camera/camera.cpp).
    const bool spherical = camera_.sphericalMapping.has_value();
    const Vec3 viewForward = spherical ? -normalize(right) : forward, viewRight = spherical ? -forward : right;
    Json cam = {{"type", spherical ? "spherical" : camera_.orthographic ? "orthographic" : "perspective"},
                {"position", {position.x, position.y, position.z}},
                {"look_at", {position.x + viewForward.x, position.y + viewForward.y, position.z + viewForward.z}},
                {"up", {up.x, up.y, up.z}}};
    if (spherical) {
        cam["mapping"] = *camera_.sphericalMapping;
        if (*camera_.sphericalMapping == "equal_area" && width_ != height_)
            warn(camera_.where, "Camera \"spherical\": an equal-area image that is not square is stretched");
    } else if (!camera_.lens.empty()) {
        cam["type"] = "realistic";
        Json rows = Json::array();
        for (const LensInterface& r : camera_.lens) rows.push_back({r.radius, r.thickness, r.eta, r.apertureDiameter});
        cam["lens"] = std::move(rows);
        cam["aperture_diameter"] = camera_.lensApertureMm;
        cam["focus_distance"] = camera_.focalDistance;
        cam["film_diagonal"] = filmDiagonalMm_;
    } else {
        writeViewOfLens(cam);
    }
    cam["resolution"] = {width_, height_};
    cam["filter"] = camera_.filter.is_null() ? defaultFilter() : camera_.filter;
    // pbrt's image x axis is up x forward in a left-handed world; photon's is forward x up.
    if (dot(viewRight, cross(viewForward, up)) < 0) cam["handedness"] = "left";
    if (camera_.lensRadius > 0 && !spherical) {
        cam["aperture_radius"] = camera_.lensRadius;
        cam["focus_distance"] = camera_.focalDistance;
    }
    if (const std::string medium = renderedMedium(camera_.medium); !medium.empty()) cam["medium"] = medium;
    out_.document["camera"] = cam;
}

// A perspective camera's fov or an orthographic one's view_height, from pbrt's fov,
// screen window and frame aspect ratio.
void SceneBuilder::writeViewOfLens(Json& cam) const {
    const Transform& c = camera_.cameraToWorld;
    // pbrt's fov (or an orthographic camera's screen, [-1, 1] on that axis) spans the
    // shorter image axis; photon's the vertical one.
    double tanHalf = camera_.orthographic ? 1.0 : std::tan(camera_.fov / 2 / kDegrees);
    if (width_ < height_) tanHalf *= double(height_) / width_;
    if (camera_.frameAspectRatio && !camera_.screenWindow &&
        std::abs(*camera_.frameAspectRatio / (double(width_) / height_) - 1) > 1e-3)
        fail(camera_.where, "Camera: a frameaspectratio other than the film's (" + std::to_string(width_) + " / " +
                                std::to_string(height_) + ") stretches the image, which is not supported");
    if (camera_.screenWindow) {
        // A symmetric window of the image's shape scales the view; anything else shifts or
        // stretches it, which photon's camera cannot.
        const std::vector<double>& w = *camera_.screenWindow;
        const double aspect = double(width_) / height_;
        const double defaultHalfHeight = aspect >= 1 ? 1 : 1 / aspect;
        const bool symmetric = w.size() == 4 && std::abs(w[0] + w[1]) < 1e-6 && std::abs(w[2] + w[3]) < 1e-6 &&
                               w[3] > 0 && std::abs((w[1] / w[3]) / aspect - 1) < 1e-3;
        if (!symmetric)
            fail(camera_.where, "Camera: a screenwindow that is not centred or not of the image's shape is not supported");
        tanHalf *= w[3] / defaultHalfHeight;
    }
    if (camera_.orthographic) {
        // The screen is in camera space, which the camera's transform scales into the world.
        cam["view_height"] = 2 * tanHalf * double(length(c.vector({0, 1, 0})));
    } else {
        cam["fov"] = 2 * std::atan(tanHalf) * kDegrees;
    }
}

}  // namespace photon::pbrt
