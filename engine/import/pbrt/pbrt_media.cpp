// MakeNamedMedium and MediumInterface. photon renders media that absorb, scatter and emit
// (docs/scene-format.md#media): pbrt-v4's "homogeneous" medium, with its Henyey-Greenstein
// phase function, its coefficients given or a measured "preset", and its light "Le" times
// "Lescale"; its "uniformgrid" medium, whose density is sampled on a grid and whose light
// is "Le" times a "Lescale" grid or a blackbody by a "temperature" grid; its "nanovdb"
// medium, whose density grid, and temperature grid if it has one, are in a NanoVDB file;
// and its procedural "cloud". A medium of another kind ("rgbgrid") is refused, or left out
// under a lenient import.
#include "import/pbrt/pbrt_builder.h"
#include "import/pbrt/pbrt_spectra.h"
#include "import/pbrt/scattering_presets.h"
#include "scene/nanovdb_density.h"
#include "scene/scene_paths.h"

namespace photon::pbrt {

void SceneBuilder::makeNamedMedium(const Directive& d) {
    Params p(d);
    const std::string& name = d.strings.at(0);
    const std::string type = p.string("type", "");
    const std::string what = "medium \"" + name + "\"";
    if (type != "homogeneous" && type != "uniformgrid" && type != "nanovdb" && type != "cloud") {
        media_[name] = false;
        return unsupported(d, what + ": a \"" + type +
                                  "\" medium is not supported (photon renders \"homogeneous\", \"uniformgrid\", "
                                  "\"nanovdb\" and \"cloud\" media)");
    }
    // pbrt-v4's HomogeneousMedium::Create: both coefficients default to 1, times "scale"
    // (which its CloudMedium does not read).
    const float scale = type == "cloud" ? 1.0f : float(p.number("scale", 1));
    auto coefficient = [&](std::string_view key) {
        const Param* param = p.find(key);
        return (param ? spectrumColor(*param, SpectrumKind::Reflectance, baseDir_) : Color(1.0f)) * scale;
    };
    Color absorption, scattering;
    if (auto preset = p.string("preset")) {
        // A measured material (scattering_presets.h), in mm^-1, times "scale", as pbrt-v4's.
        const auto measured = scatteringPreset(*preset);
        if (!measured)
            fail(d.where, what + ": no measured preset named \"" + *preset + "\" (photon has " + scatteringPresetNames() + ")");
        absorption = measured->absorption * scale;
        scattering = measured->scattering * scale;
    } else {
        absorption = coefficient("sigma_a"), scattering = coefficient("sigma_s");
    }
    const double g = p.number("g", 0);
    if (!(g > -1 && g < 1)) fail(d.where, what + ": \"g\" must lie in (-1, 1)");
    media_[name] = true;
    Json m = {{"absorption", rgb(absorption)}};
    if (!isBlack(scattering)) m["scattering"] = rgb(scattering);
    if (g != 0 && !isBlack(scattering)) m["g"] = g;
    if (type == "uniformgrid") m["density"] = sampledGrid(d, p, what, "density");
    if (type == "nanovdb") m["density"] = nanoVdbGrid(d, p, what, "density");
    if (type == "cloud") m["density"] = cloudGrid(d, p, what);
    if (std::optional<Json> emission = mediumEmission(d, p, type, what)) {
        if (isBlack(absorption))
            unsupported(d, what + " emits, but in proportion to its sigma_a (pbrt-v4's sigma_a Le), which is 0",
                        "its emission left out");
        else
            m["emission"] = std::move(*emission);
    }
    mediaJson_[name] = std::move(m);
    p.warnUnused(out_.warnings);
}

// pbrt-v4's GridMedium: the array `key` (nx * ny * nz samples, x fastest) at the centres
// of the cells of the box [p0, p1] cut nx x ny x nz times, in the medium's space, which the
// current transform places in the world.
Json SceneBuilder::sampledGrid(const Directive& d, const Params& p, const std::string& what, const char* key) {
    int n[3];
    const char* axes[3] = {"nx", "ny", "nz"};
    for (int a = 0; a < 3; ++a) {
        const double v = p.number(axes[a], 1);
        if (!(v >= 1 && v <= 4096)) fail(d.where, what + ": \"" + axes[a] + "\" must lie in [1, 4096]");
        n[a] = static_cast<int>(v);
    }
    const std::vector<double> samples = p.numbers(key, {"float"});
    const size_t count = size_t(n[0]) * n[1] * n[2];
    if (samples.size() != count)
        fail(d.where, what + ": \"" + key + "\" holds " + std::to_string(samples.size()) + " values, nx * ny * nz = " +
                          std::to_string(count));
    Json values = Json::array();
    for (double v : samples) {
        if (!(v >= 0) || !std::isfinite(v)) fail(d.where, what + ": \"" + key + "\" values must be finite and >= 0");
        values.push_back(v);
    }
    return boxGrid(d, p, what, {n[0], n[1], n[2]}, std::move(values));
}

// A grid of the given samples over the box [p0, p1] (default the unit cube) of the
// medium's space.
Json SceneBuilder::boxGrid(const Directive& d, const Params& p, const std::string& what, std::array<int, 3> n,
                           Json values) {
    const Vec3 p0 = p.vec3("p0", Vec3(0.0f)), p1 = p.vec3("p1", Vec3(1.0f));
    if (!(p0.x < p1.x && p0.y < p1.y && p0.z < p1.z)) fail(d.where, what + ": \"p0\" must lie below \"p1\" in x, y and z");
    Json grid = {{"resolution", {n[0], n[1], n[2]}}, {"values", std::move(values)},
                 {"bounds", {{p0.x, p0.y, p0.z}, {p1.x, p1.y, p1.z}}}};
    if (!state_.ctm.identity()) grid["transform"] = matrixJson(pointCtm(d));
    return grid;
}

// pbrt-v4's NanoVDBMedium: the file's grid named `grid`, in the medium's space (the current
// transform).
Json SceneBuilder::nanoVdbGrid(const Directive& d, const Params& p, const std::string& what, const char* name) {
    const std::string file = p.string("filename", "");
    if (file.empty()) fail(d.where, what + ": a \"nanovdb\" medium needs a \"filename\"");
    if (auto why = checkRelativePath(file)) fail(d.where, what + ": \"" + file + "\": " + *why);
    Json grid = {{"file", file}, {"grid", name}};
    if (!state_.ctm.identity()) grid["transform"] = matrixJson(pointCtm(d));
    return grid;
}

// The light a medium emits, as pbrt-v4's media read it (docs/scene-format.md#media-that-emit):
// none where it emits nothing. "Le" is read as pbrt-v4 reads light spectra (scaled to unit
// luminance unless "rgb"); a temperature is pbrt-v4's blackbody, its peak 1, at (T -
// "temperatureoffset" (formerly "temperaturecutoff")) "temperaturescale" kelvin.
std::optional<Json> SceneBuilder::mediumEmission(const Directive& d, const Params& p, const std::string& type,
                                                 const std::string& what) {
    if (type == "cloud") return std::nullopt;  // pbrt-v4's cloud reads no "Le"
    auto temperatureFields = [&](Json& e) {
        const double offset = p.number("temperatureoffset").value_or(p.number("temperaturecutoff").value_or(0));
        const double scale = p.number("temperaturescale", 1);
        if (!(scale > 0)) fail(d.where, what + ": \"temperaturescale\" must be > 0");
        if (offset != 0) e["temperature_offset"] = offset;
        if (scale != 1) e["temperature_scale"] = scale;
    };
    if (type == "nanovdb") {
        // pbrt-v4 lights it by the file's "temperature" grid, if it has one, times "Lescale".
        const double scale = p.number("Lescale", 1);
        const std::string file = p.string("filename", "");
        // A file that cannot be read is the scene loader's to name (with the density grid's
        // JSON path); here it has no temperature grid.
        bool hasTemperature = false;
        try {
            hasTemperature = nanoVdbHasGrid(baseDir_ / file, "temperature");
        } catch (const std::runtime_error&) {
        }
        if (!hasTemperature || !(scale > 0)) return std::nullopt;
        Json e = {{"scale", scale}, {"temperature", nanoVdbGrid(d, p, what, "temperature")}};
        temperatureFields(e);
        return e;
    }
    const Param* le = p.find("Le");
    const Color radiance = le ? spectrumColor(*le, SpectrumKind::Illuminant, baseDir_) : Color(0.0f);
    if (type == "homogeneous") {
        const double scale = p.number("Lescale", 1);
        if (isBlack(radiance) || !(scale > 0)) return std::nullopt;
        return Json{{"radiance", rgb(radiance)}, {"scale", scale}};
    }
    // uniformgrid: "Le" or a "temperature" grid, times a "Lescale" grid of the density's
    // size, or without one, pbrt-v4's single sample over the box, which its interpolation
    // toward the faces turns into a tent (1 at the centre, falling to the faces).
    const bool hot = p.find("temperature") != nullptr;
    if (hot && le) fail(d.where, what + ": give either \"Le\" or \"temperature\", not both");
    if (!hot && isBlack(radiance)) return std::nullopt;
    Json e = Json::object();
    if (!hot) e["radiance"] = rgb(radiance);
    e["grid"] = p.find("Lescale") ? sampledGrid(d, p, what, "Lescale") : boxGrid(d, p, what, {1, 1, 1}, Json::array({1}));
    if (hot) {
        e["temperature"] = sampledGrid(d, p, what, "temperature");
        temperatureFields(e);
    }
    return e;
}

// pbrt-v4's CloudMedium: its noise's "density", "wispiness" and "frequency", in the box
// [p0, p1] of the medium's space; the scene loader samples it on a grid
// (media/cloud_density.h).
Json SceneBuilder::cloudGrid(const Directive& d, const Params& p, const std::string& what) {
    Json cloud = Json::object();
    for (const char* key : {"density", "wispiness", "frequency"})
        if (auto v = p.number(key)) {
            if (!(*v >= 0) || !std::isfinite(*v) || (*v == 0 && key[0] == 'f'))
                fail(d.where, what + ": \"" + key + "\" must be finite and " + (key[0] == 'f' ? "> 0" : ">= 0"));
            cloud[key] = *v;
        }
    const Vec3 p0 = p.vec3("p0", Vec3(0.0f)), p1 = p.vec3("p1", Vec3(1.0f));
    if (!(p0.x < p1.x && p0.y < p1.y && p0.z < p1.z)) fail(d.where, what + ": \"p0\" must lie below \"p1\" in x, y and z");
    Json grid = {{"cloud", cloud}, {"bounds", {{p0.x, p0.y, p0.z}, {p1.x, p1.y, p1.z}}}};
    if (!state_.ctm.identity()) grid["transform"] = matrixJson(pointCtm(d));
    return grid;
}

void SceneBuilder::mediumInterface(const Directive& d) {
    // One name: the same medium on both sides; two: inside, then outside.
    const std::string& inside = d.strings.at(0);
    const std::string& outside = d.strings.size() > 1 ? d.strings[1] : inside;
    for (const std::string& n : {inside, outside})
        if (!n.empty() && !media_.count(n)) fail(d.where, "MediumInterface: no medium named \"" + n + "\"");
    state_.insideMedium = inside;
    state_.outsideMedium = outside;
}

std::string SceneBuilder::renderedMedium(const std::string& name) const {
    // A medium left out (lenient import) is no medium.
    auto it = media_.find(name);
    return it != media_.end() && it->second ? name : std::string();
}

std::optional<Json> SceneBuilder::shapeMedium() {
    const std::string inside = renderedMedium(state_.insideMedium), outside = renderedMedium(state_.outsideMedium);
    if (inside == outside) return std::nullopt;
    Json m = Json::object();
    if (!inside.empty()) m["inside"] = inside;
    if (!outside.empty()) m["outside"] = outside;
    return m;
}

}  // namespace photon::pbrt
