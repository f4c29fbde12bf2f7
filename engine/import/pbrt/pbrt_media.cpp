// MakeNamedMedium and MediumInterface. photon renders media that absorb and scatter
// (docs/scene-format.md#media): pbrt-v4's "homogeneous" medium, with its Henyey-Greenstein
// phase function, its coefficients given or a measured "preset", its "uniformgrid" medium,
// whose density is sampled on a grid, its "nanovdb" medium, whose density grid is in a
// NanoVDB file, and its procedural "cloud". A medium that emits, or of another kind
// ("rgbgrid"), is refused, or under a lenient import keeps only what photon can render.
#include "import/pbrt/pbrt_builder.h"
#include "import/pbrt/pbrt_spectra.h"
#include "import/pbrt/scattering_presets.h"

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
    const Param* emission = p.find("Le");
    if (emission && !isBlack(spectrumColor(*emission, SpectrumKind::Illuminant, baseDir_)) && p.number("Lescale", 1) != 0)
        unsupported(d, what + " emits light (Le): photon's media do not emit", "its emission left out");
    const double g = p.number("g", 0);
    if (!(g > -1 && g < 1)) fail(d.where, what + ": \"g\" must lie in (-1, 1)");
    media_[name] = true;
    Json m = {{"absorption", rgb(absorption)}};
    if (!isBlack(scattering)) m["scattering"] = rgb(scattering);
    if (g != 0 && !isBlack(scattering)) m["g"] = g;
    if (type == "uniformgrid") m["density"] = densityGrid(d, p, what);
    if (type == "nanovdb") m["density"] = nanoVdbGrid(d, p, what);
    if (type == "cloud") m["density"] = cloudGrid(d, p, what);
    mediaJson_[name] = std::move(m);
    p.warnUnused(out_.warnings);
}

// pbrt-v4's GridMedium: "density" samples (x fastest) at the centres of the cells of the
// box [p0, p1] cut nx x ny x nz times, in the medium's space, which the current transform
// places in the world.
Json SceneBuilder::densityGrid(const Directive& d, const Params& p, const std::string& what) {
    int n[3];
    const char* axes[3] = {"nx", "ny", "nz"};
    for (int a = 0; a < 3; ++a) {
        const double v = p.number(axes[a], 1);
        if (!(v >= 1 && v <= 4096)) fail(d.where, what + ": \"" + axes[a] + "\" must lie in [1, 4096]");
        n[a] = static_cast<int>(v);
    }
    const std::vector<double> density = p.numbers("density", {"float"});
    const size_t count = size_t(n[0]) * n[1] * n[2];
    if (density.size() != count)
        fail(d.where, what + ": \"density\" holds " + std::to_string(density.size()) + " values, nx * ny * nz = " +
                          std::to_string(count));
    Json values = Json::array();
    for (double v : density) {
        if (!(v >= 0) || !std::isfinite(v)) fail(d.where, what + ": \"density\" values must be finite and >= 0");
        values.push_back(v);
    }
    const Vec3 p0 = p.vec3("p0", Vec3(0.0f)), p1 = p.vec3("p1", Vec3(1.0f));
    if (!(p0.x < p1.x && p0.y < p1.y && p0.z < p1.z)) fail(d.where, what + ": \"p0\" must lie below \"p1\" in x, y and z");
    if (p.find("temperature"))
        unsupported(d, what + " emits light by temperature: photon's media do not emit", "its emission left out");
    Json grid = {{"resolution", {n[0], n[1], n[2]}}, {"values", std::move(values)},
                 {"bounds", {{p0.x, p0.y, p0.z}, {p1.x, p1.y, p1.z}}}};
    if (!state_.ctm.identity()) grid["transform"] = matrixJson(pointCtm(d));
    return grid;
}

// pbrt-v4's NanoVDBMedium: the file's grid named "density", in the medium's space (the
// current transform); a "temperature" grid would make it emit.
Json SceneBuilder::nanoVdbGrid(const Directive& d, const Params& p, const std::string& what) {
    const std::string file = p.string("filename", "");
    if (file.empty()) fail(d.where, what + ": a \"nanovdb\" medium needs a \"filename\"");
    if (auto why = checkRelativePath(file)) fail(d.where, what + ": \"" + file + "\": " + *why);
    // pbrt-v4 lights the medium from the file's "temperature" grid, scaled by Lescale.
    if (p.number("Lescale").value_or(0) > 0)
        unsupported(d, what + " emits light (Lescale, by its file's temperature grid): photon's media do not emit",
                    "its emission left out");
    for (const char* emission : {"temperaturecutoff", "temperaturescale"}) p.find(emission);
    Json grid = {{"file", file}, {"grid", "density"}};
    if (!state_.ctm.identity()) grid["transform"] = matrixJson(pointCtm(d));
    return grid;
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
