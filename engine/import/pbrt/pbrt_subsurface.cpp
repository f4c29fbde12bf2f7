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
    // A constant colour parameter; a texture can vary only the reflectance (the medium's
    // palette, scene/medium_palette.h).
    auto constant = [&](std::string_view key, Color fallback) -> std::optional<Color> {
        const Param* param = p.find(key);
        if (!param) return fallback;
        if (param->type == "texture") return std::nullopt;
        return spectrumColor(*param, SpectrumKind::Reflectance, baseDir_);
    };
    auto refuseTexture = [&](std::string_view key) {
        unsupported(d, "subsurface: a textured \"" + std::string(key) +
                           "\" is not supported (only \"reflectance\" may be a texture)",
                    "rendered as a grey diffuse material");
        return grey;
    };
    Json medium;
    if (auto name = p.string("name")) {
        const auto preset = scatteringPreset(*name);
        if (!preset)
            fail(d.where, "subsurface: no measured material named \"" + *name + "\" (photon has " +
                              scatteringPresetNames() + ")");
        // Reduced scattering coefficients: pbrt-v4 takes them with g = 0.
        medium = {{"absorption", rgb(preset->absorption * float(scale))}, {"scattering", rgb(preset->scattering * float(scale))}};
    } else if (p.has("reflectance")) {
        // pbrt-v4's SubsurfaceFromDiffuse: sigma_t = 1 / (scale mfp), the albedo from the
        // reflectance, read by photon's loader where a path enters (media/diffusion_dipole.h).
        const std::optional<Color> mfp = constant("mfp", Color(1.0f));
        if (!mfp) return refuseTexture("mfp");
        if (!(std::min({mfp->x, mfp->y, mfp->z}) * scale > 0)) fail(d.where, "subsurface: \"mfp\" times \"scale\" must be > 0");
        medium = {{"reflectance", clampedReflectance(*colorValue(p, "reflectance", int(SpectrumKind::Reflectance)), d.where, out_.warnings)},
                  {"mean_free_path", rgb(*mfp * float(scale))},
                  {"boundary_ior", eta}};
        if (g != 0) medium["g"] = g;
    } else {
        // pbrt-v4's defaults, in mm^-1: Jensen et al.'s whole milk.
        const std::optional<Color> sigmaA = constant("sigma_a", {0.0011f, 0.0024f, 0.014f});
        const std::optional<Color> sigmaS = constant("sigma_s", {2.55f, 3.21f, 3.77f});
        if (!sigmaA) return refuseTexture("sigma_a");
        if (!sigmaS) return refuseTexture("sigma_s");
        medium = {{"absorption", rgb(*sigmaA * float(scale))}, {"scattering", rgb(*sigmaS * float(scale))}};
        if (g != 0) medium["g"] = g;
    }
    // pbrt-v4 counts its BSSRDF as one vertex of a path: so is the walk under the surface.
    medium["subsurface"] = true;
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
