// pbrt-v4's "subsurface" material as what it models: a dielectric boundary (eta, roughness)
// around a homogeneous medium that scatters, rendered by photon's volumetric paths and
// photons (docs/scene-format.md#media), where pbrt-v4 approximates the light under the
// surface by a tabulated BSSRDF (photon beam diffusion). The medium's coefficients come, as
// in pbrt-v4's SubsurfaceMaterial::Create, from a measured material's "name", from
// "sigma_a" and "sigma_s" (pbrt-v4's defaults: whole milk), or from a diffuse "reflectance"
// and a mean free path "mfp", each times "scale". The medium fills every shape of the
// material (finish(): placeSubsurfaceMedia), so those should be closed.
#include "import/pbrt/pbrt_builder.h"
#include "import/pbrt/pbrt_spectra.h"
#include "import/pbrt/scattering_presets.h"

namespace photon::pbrt {

namespace {

// The material's member naming its medium while the file is read: not a field of photon's
// materials, removed before the scene is written.
const std::string kSubsurfaceMedium = "\x01medium";

}  // namespace

Json SceneBuilder::subsurfaceJson(const Params& p) {
    const Directive& d = p.directive();
    const double eta = p.number("eta", 1.33), scale = p.number("scale", 1), g = p.number("g", 0);
    if (!(eta > 0)) fail(d.where, "subsurface: \"eta\" must be > 0");
    if (!(scale >= 0)) fail(d.where, "subsurface: \"scale\" must be >= 0");
    if (!(g > -1 && g < 1)) fail(d.where, "subsurface: \"g\" must lie in (-1, 1)");
    const Json grey = {{"type", "diffuse"}, {"albedo", rgb(Color(0.5f))}};
    // A constant colour parameter; a texture cannot vary a homogeneous medium.
    bool textured = false;
    auto constant = [&](std::string_view key, Color fallback) {
        const Param* param = p.find(key);
        if (!param) return fallback;
        if (param->type == "texture") {
            textured = true;
            return fallback;
        }
        return spectrumColor(*param, SpectrumKind::Reflectance, baseDir_);
    };
    Color absorption, scattering;
    double phaseG = g;
    if (auto name = p.string("name")) {
        const auto preset = scatteringPreset(*name);
        if (!preset)
            fail(d.where, "subsurface: no measured material named \"" + *name + "\" (photon has " +
                              scatteringPresetNames() + ")");
        // Reduced scattering coefficients: pbrt-v4 takes them with g = 0.
        absorption = preset->absorption, scattering = preset->scattering, phaseG = 0;
    } else if (p.has("reflectance")) {
        const Color reflectance = constant("reflectance", Color(1.0f)), mfp = constant("mfp", Color(1.0f));
        if (!textured)
            for (int c = 0; c < 3; ++c) {
                if (!(mfp[c] * scale > 0)) fail(d.where, "subsurface: \"mfp\" times \"scale\" must be > 0");
                const double sigmaT = 1 / (mfp[c] * scale);
                const double albedo = albedoOfDiffuseReflectance(std::clamp<double>(reflectance[c], 0, 1), eta);
                scattering[c] = float(albedo * sigmaT);
                absorption[c] = float((1 - albedo) * sigmaT);
            }
    } else {
        // pbrt-v4's defaults, in mm^-1: Jensen et al.'s whole milk.
        absorption = constant("sigma_a", {0.0011f, 0.0024f, 0.014f}) * float(scale);
        scattering = constant("sigma_s", {2.55f, 3.21f, 3.77f}) * float(scale);
    }
    if (p.has("name")) absorption = absorption * float(scale), scattering = scattering * float(scale);
    if (textured) {
        unsupported(d, "subsurface: a textured \"reflectance\", \"mfp\", \"sigma_a\" or \"sigma_s\" is not supported (the "
                       "medium under the surface is homogeneous)",
                    "rendered as a grey diffuse material");
        return grey;
    }
    Json medium = {{"absorption", rgb(absorption)}, {"scattering", rgb(scattering)}};
    if (phaseG != 0) medium["g"] = phaseG;
    // Identical media are one.
    std::string mediumName;
    for (const auto& [name, existing] : mediaJson_.items())
        if (existing == medium && name.rfind("subsurface ", 0) == 0) mediumName = name;
    if (mediumName.empty()) {
        mediumName = "subsurface " + std::to_string(++subsurfaceCount_);
        mediaJson_[mediumName] = medium;
    }
    Json m = {{"type", "dielectric"}, {"ior", eta}};
    m.update(roughnessFields(p, false, "", true));
    m[kSubsurfaceMedium] = mediumName;
    return m;
}

void SceneBuilder::placeSubsurfaceMedia() {
    auto place = [&](Json& shapes) {
        for (Json& s : shapes) {
            if (!s.contains("material")) continue;
            const std::string& material = s["material"].get_ref<const std::string&>();
            if (!materials_.contains(material) || !materials_[material].contains(kSubsurfaceMedium)) continue;
            s["medium"]["inside"] = materials_[material][kSubsurfaceMedium];
        }
    };
    place(shapes_);
    for (auto& [name, object] : objects_.items()) place(object["shapes"]);
    for (auto& [name, material] : materials_.items()) material.erase(kSubsurfaceMedium);
}

}  // namespace photon::pbrt
