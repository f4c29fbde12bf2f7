// LightSource and AreaLightSource. pbrt-v4 scales light spectra given other than as "rgb"
// to unit luminance (pbrt_spectra.h); "scale" multiplies, and "power" P multiplies too, by
// P / k_e, k_e the power the light would send out at unit luminance: 4 pi for a point
// light, 2 pi ((1 - cos a) + (cos a - cos b) / 2) for a spot light of full intensity out to
// a and none past b, pi A sides for an area light (pbrt-v4's PointLight, SpotLight and
// DiffuseAreaLight::Create). An "rgb" spectrum is not scaled to unit luminance there
// (SpectrumToPhotometric reads only its illuminant), so its own luminance stays in.
#include <cmath>
#include "description/portal.h"
#include "import/pbrt/pbrt_builder.h"
#include "import/pbrt/pbrt_spectra.h"
#include "scene/scene_paths.h"
#include "texture/image_texture.h"

namespace photon::pbrt {

namespace {


// A rotation's axis and angle (degrees), if `t`'s linear part is a rotation.
std::optional<std::pair<Vec3, float>> axisAngle(const Transform& t) {
    const float* m = t.m.data();
    const Vec3 c0{m[0], m[4], m[8]}, c1{m[1], m[5], m[9]}, c2{m[2], m[6], m[10]};
    for (Vec3 c : {c0, c1, c2})
        if (std::abs(length(c) - 1) > 1e-3f) return std::nullopt;
    if (t.determinant() < 0) return std::nullopt;
    const float cosAngle = std::clamp((m[0] + m[5] + m[10] - 1) * 0.5f, -1.0f, 1.0f);
    const float angle = std::acos(cosAngle);
    if (angle < 1e-6f) return std::make_pair(Vec3(0, 1, 0), 0.0f);
    Vec3 axis{m[9] - m[6], m[2] - m[8], m[4] - m[1]};
    if (length(axis) < 1e-4f) {
        // A half turn: the axis from the symmetric part, (R + I) / 2 = a a^T.
        axis = {std::sqrt(std::max(0.0f, (m[0] + 1) * 0.5f)), std::sqrt(std::max(0.0f, (m[5] + 1) * 0.5f)),
                std::sqrt(std::max(0.0f, (m[10] + 1) * 0.5f))};
        if (m[1] < 0) axis.y = -axis.y;
        if (m[2] < 0) axis.z = -axis.z;
    }
    return std::make_pair(normalize(axis), angle * 180.0f / kPi);
}

// The linear part as photon's 16-number row-major "matrix" (an environment has no position).
Json orientationMatrix(const Transform& t) {
    const float* m = t.m.data();
    return Json::array({m[0], m[1], m[2], 0, m[4], m[5], m[6], 0, m[8], m[9], m[10], 0, 0, 0, 0, 1});
}

}  // namespace

void SceneBuilder::lightSource(const Directive& d) {
    Params p(d);
    const std::string& type = d.strings.at(0);
    const double scale = p.number("scale", 1) * imagingRatio();
    auto spectrum = [&](std::string_view name) {
        const Param* param = p.find(name);
        return param ? spectrumColor(*param, SpectrumKind::Illuminant, baseDir_) : Color(1.0f);
    };
    if (currentObject_) fail(d.where, "LightSource inside ObjectBegin is not supported");
    Json light;
    if (type == "point") {
        const Vec3 from = pointCtm(d).point(p.vec3("from", {0, 0, 0}));
        const double power = p.number("power", -1);
        light = {{"type", "point"},
                 {"position", vec(from)},
                 {"intensity", rgb(spectrum("I") * float(scale * (power > 0 ? power / (4 * kPi) : 1.0)))}};
    } else if (type == "spot") {
        const Vec3 from = pointCtm(d).point(p.vec3("from", {0, 0, 0})), to = state_.ctm.point(p.vec3("to", {0, 0, 1}));
        const double cone = p.number("coneangle", 30), delta = p.number("conedeltaangle", 5);
        if (!(length(to - from) > 0)) fail(d.where, "spot: \"from\" and \"to\" are the same point");
        const double coneAngle = std::clamp(cone, 1e-3, 90.0), falloffAngle = std::clamp(cone - delta, 0.0, coneAngle);
        double power = p.number("power", -1);
        if (power > 0) {
            const double cosEnd = std::cos(coneAngle * kPi / 180), cosStart = std::cos(falloffAngle * kPi / 180);
            power /= 2 * kPi * ((1 - cosStart) + (cosStart - cosEnd) / 2);
        }
        light = {{"type", "spot"},
                 {"position", vec(from)},
                 {"direction", vec(normalize(to - from))},
                 {"intensity", rgb(spectrum("I") * float(scale * (power > 0 ? power : 1.0)))},
                 {"cone_angle", coneAngle},
                 {"falloff_angle", falloffAngle}};
        if (cone > 90) warn(d.where, "spot: a cone wider than 90 degrees is narrowed to 90");
    } else if (type == "distant") {
        const Vec3 from = p.vec3("from", {0, 0, 0}), to = p.vec3("to", {0, 0, 1});
        if (!(length(to - from) > 0)) fail(d.where, "distant: \"from\" and \"to\" are the same point");
        light = {{"type", "directional"},
                 {"direction", vec(normalize(state_.ctm.vector(to - from)))},
                 {"irradiance", rgb(spectrum("L") * float(scale))}};
        // pbrt-v4 multiplies "scale" by the illuminance, L being of unit luminance (an RGB's
        // illuminant is, its RGB is not divided out: DistantLight::Create).
        if (auto e = p.number("illuminance")) light["irradiance"] = rgb(spectrum("L") * float(scale * *e));
    } else if (type == "infinite") {
        if (auto file = p.string("filename")) {
            if (auto why = checkRelativePath(*file)) fail(d.where, "infinite: \"" + *file + "\": " + *why);
            if (p.has("L")) fail(d.where, "infinite: give \"L\" or \"filename\", not both");
            light = {{"type", "environment"}, {"image", *file}, {"layout", "equal_area"}, {"scale", scale}};
            // pbrt-v4 looks the map up in the light's frame, whatever the transform; a
            // rotation and a mirror image (a handedness flip, as exporters write) keep
            // solid angle, which photon's sampling needs.
            if (auto rotation = axisAngle(state_.ctm)) {
                if (rotation->second != 0)
                    light["rotate"] = {{"axis", vec(rotation->first)}, {"angle", rotation->second}};
            } else if (state_.ctm.orthonormal()) {
                light["matrix"] = orientationMatrix(state_.ctm);
            } else {
                fail(d.where, "infinite: the light's transform must be a rotation or a mirror image (it scales or shears)");
            }
            // The image's own irradiance on a surface facing its +z, measured when it is loaded.
            if (auto e = p.number("illuminance")) light["illuminance"] = *e;
        } else {
            // Uniform: the irradiance on any surface is pi L (pbrt-v4 ImageInfiniteLight and
            // UniformInfiniteLight's Create: scale *= E / pi for unit-luminance L).
            const double e = p.number("illuminance", 0);
            light = {{"type", "environment"}, {"radiance", rgb(spectrum("L") * float(e > 0 ? scale * e / kPi : scale))}};
        }
        // The light comes in only through the portal (pbrt-v4's PortalImageInfiniteLight),
        // its corners in world space whatever the light's transform (pbrt-v4's Light::Create
        // takes them through the camera's transform alone).
        if (p.has("portal")) {
            const std::vector<double> v = p.numbers("portal", {"point3"});
            if (v.size() != 12) fail(d.where, "infinite: \"portal\" must be 4 points, not " + std::to_string(v.size()) + " numbers");
            std::array<Vec3, 4> q;
            for (size_t i = 0; i < 4; ++i) q[i] = Vec3(float(v[3 * i]), float(v[3 * i + 1]), float(v[3 * i + 2]));
            if (auto problem = portalProblem(q)) fail(d.where, "infinite: \"portal\" " + *problem);
            for (const Vec3& c : q) light["portal"].push_back(vec(c));
        }
    } else if (type == "goniometric") {
        light = goniometricLight(d, p, spectrum("I") * float(scale));
    } else if (type == "projection") {
        light = projectionLight(d, p, float(scale));
    } else {
        return unsupported(d, "LightSource \"" + type +
                                  "\" is not supported (photon imports point, spot, goniometric, projection, distant, "
                                  "infinite)");
    }
    // pbrt-v4 puts a light in MediumInterface's outside medium; distant and infinite lights
    // are outside the scene.
    if (type == "point" || type == "spot" || type == "goniometric" || type == "projection")
        if (const std::string medium = renderedMedium(state_.outsideMedium); !medium.empty()) light["medium"] = medium;
    lights_.push_back(std::move(light));
}

// pbrt-v4's GoniometricLight: a point light at the light frame's origin whose intensity
// toward each direction is I times the "filename" image's texel there, an equal-area square
// in the light's frame with its y and z swapped (GoniometricLight::Create), so that the
// square's centre looks along the frame's +y. "power" P scales I by P / (4 pi mean texel).
// pbrt-v4 takes the image's texels as the mean of their RGB; photon keeps their colour.
// The light's image "filename", relative to the scene's folder (`what` names the light in
// errors), and the image itself when `load`: a light's "power" is over what its image sends.
std::pair<std::string, std::shared_ptr<const ImageTexture>> SceneBuilder::lightImage(const Directive& d, const Params& p,
                                                                                      const std::string& what, bool load) {
    const std::string file = p.string("filename", "");
    if (file.empty()) fail(d.where, what + ": needs a \"filename\" (the image it sends out)");
    if (auto why = checkRelativePath(file)) fail(d.where, what + ": \"" + file + "\": " + *why);
    if (!load) return {file, nullptr};
    try {
        return {file, ImageTexture::load(baseDir_ / file)};
    } catch (const std::runtime_error& e) {
        fail(d.where, what + ": \"" + file + "\": " + e.what());
    }
}

Json SceneBuilder::goniometricLight(const Directive& d, const Params& p, Color intensity) {
    const double power = p.number("power", -1);
    const auto [file, image] = lightImage(d, p, "goniometric", power > 0);
    if (power > 0) {
        const float mean = average(image->average());
        if (!(mean > 0)) fail(d.where, "goniometric: \"" + file + "\" is black: it cannot send out a \"power\"");
        intensity *= float(power / (4 * kPi * mean));
    }
    const Transform swapYZ{{1, 0, 0, 0, 0, 0, 1, 0, 0, 1, 0, 0}};
    const Transform toWorld = state_.ctm * swapYZ;
    if (!toWorld.orthonormal())
        fail(d.where, "goniometric: the light's transform must be a rotation or a mirror image (it scales or shears)");
    return {{"type", "point"},     {"position", vec(pointCtm(d).point({0, 0, 0}))},
            {"intensity", rgb(intensity)}, {"image", file},
            {"layout", "equal_area"}, {"matrix", orientationMatrix(toWorld)}};
}

// pbrt-v4's ProjectionLight: the "filename" image projected along the light frame's +z
// through "fov" across its shorter side, its top toward the frame's +y (pbrt-v4 flips y and
// then looks the image up from its top), times "scale"; "power" P scales it by P over the
// sum pbrt-v4 takes, A times the texels' mean luminance x cos^3 at their centres.
Json SceneBuilder::projectionLight(const Directive& d, const Params& p, float scale) {
    const double power = p.number("power", -1), fov = p.number("fov", 90);
    if (!(fov > 0 && fov < 180)) fail(d.where, "projection: \"fov\" must lie in (0, 180)");
    const auto [file, image] = lightImage(d, p, "projection", power > 0);
    if (power > 0) {
        const int w = image->width(), h = image->height();
        const double t = std::tan(fov * kPi / 360), aspect = double(w) / h;
        const double halfX = aspect > 1 ? aspect * t : t, halfY = aspect > 1 ? t : t / aspect;
        double sum = 0;
        for (int y = 0; y < h; ++y)
            for (int x = 0; x < w; ++x) {
                const double px = (2 * (x + 0.5) / w - 1) * halfX, py = (2 * (y + 0.5) / h - 1) * halfY;
                sum += luminance(image->texel(x, y)) * std::pow(1 + px * px + py * py, -1.5);
            }
        if (!(sum > 0)) fail(d.where, "projection: \"" + file + "\" is black: it cannot send out a \"power\"");
        scale *= float(power / (4 * halfX * halfY * sum / (double(w) * h)));
    }
    if (!state_.ctm.orthonormal())
        fail(d.where, "projection: the light's transform must be a rotation or a mirror image (it scales or shears)");
    return {{"type", "projection"}, {"position", vec(pointCtm(d).point({0, 0, 0}))},
            {"intensity", rgb(Color(scale))}, {"image", file},
            {"fov", fov}, {"matrix", orientationMatrix(state_.ctm)}};
}

void SceneBuilder::areaLightSource(const Directive& d) {
    Params p(d);
    if (d.strings.at(0) != "diffuse") {
        state_.areaLight.reset();
        return unsupported(d, "AreaLightSource \"" + d.strings[0] + "\" is not supported (diffuse only)",
                           "the shapes it lights emit nothing");
    }
    Json e = Json::object();
    // photon's emission_power P' sets the emission to P' / (Y(mean emission) pi A sides),
    // the scale included; pbrt-v4's to scale P / (k_e pi A sides), k_e the image's mean
    // luminance or 1 for a spectrum: P' = P scale (times Y(L) for an "rgb" L).
    const double scale = p.number("scale", 1) * imagingRatio();
    double powerPerLuminance = scale;
    if (auto file = p.string("filename")) {
        if (auto why = checkRelativePath(*file)) fail(d.where, "AreaLightSource: \"" + *file + "\": " + *why);
        e["emission"] = {{"type", "image"}, {"file", *file}};
        if (p.has("L")) fail(d.where, "AreaLightSource: both \"L\" and \"filename\" given");
    } else {
        const Param* L = p.find("L");
        const Color color = L ? spectrumColor(*L, SpectrumKind::Illuminant, baseDir_) : Color(1.0f);
        e["emission"] = rgb(color);
        powerPerLuminance *= luminance(color);
    }
    if (scale != 1) e["emission_scale"] = scale;
    if (p.boolean("twosided", false)) e["two_sided"] = true;
    if (auto power = p.number("power"); power && *power > 0) e["emission_power"] = *power * powerPerLuminance;
    state_.areaLight = e;
}

}  // namespace photon::pbrt
