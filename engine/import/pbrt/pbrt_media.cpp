// MakeNamedMedium and MediumInterface. photon renders homogeneous media that absorb and
// scatter (docs/scene-format.md#media): pbrt-v4's "homogeneous" medium, with its
// Henyey-Greenstein phase function, its coefficients given or a measured "preset". A medium that emits or varies in space is refused, or
// under a lenient import keeps only what photon can render.
#include "import/pbrt/pbrt_builder.h"
#include "import/pbrt/pbrt_spectra.h"
#include "import/pbrt/scattering_presets.h"

namespace photon::pbrt {

void SceneBuilder::makeNamedMedium(const Directive& d) {
    Params p(d);
    const std::string& name = d.strings.at(0);
    const std::string type = p.string("type", "");
    const std::string what = "medium \"" + name + "\"";
    if (type != "homogeneous") {
        media_[name] = false;
        return unsupported(d, what + ": a \"" + type + "\" medium is not supported (photon renders homogeneous media)");
    }
    // pbrt-v4's HomogeneousMedium::Create: both coefficients default to 1, times "scale".
    auto coefficient = [&](std::string_view key) {
        const Param* param = p.find(key);
        return (param ? spectrumColor(*param, SpectrumKind::Reflectance, baseDir_) : Color(1.0f)) * float(p.number("scale", 1));
    };
    Color absorption, scattering;
    if (auto preset = p.string("preset")) {
        // A measured material (scattering_presets.h), in mm^-1, times "scale", as pbrt-v4's.
        const auto measured = scatteringPreset(*preset);
        if (!measured)
            fail(d.where, what + ": no measured preset named \"" + *preset + "\" (photon has " + scatteringPresetNames() + ")");
        absorption = measured->absorption * float(p.number("scale", 1));
        scattering = measured->scattering * float(p.number("scale", 1));
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
    mediaJson_[name] = std::move(m);
    p.warnUnused(out_.warnings);
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
