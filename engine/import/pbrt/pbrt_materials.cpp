// Materials and textures: pbrt-v4's material types onto photon's (docs/import.md lists the
// mapping). Roughness: pbrt's alpha is the roughness itself, or its square root with
// "remaproughness" (pbrt-v4's TrowbridgeReitzDistribution::RoughnessToAlpha); photon's
// dielectric and coated diffuse take a perceptual roughness r with alpha = r^2, so they get
// sqrt(alpha), while its conductor takes pbrt's values and remap flag as they are.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include "import/pbrt/pbrt_builder.h"
#include "import/pbrt/pbrt_spectra.h"
#include "scene/scene_paths.h"

namespace photon::pbrt {

namespace {

// What currentMaterial() gives for pbrt's "interface" material where it bounds no medium:
// no surface.
const std::string kNoSurface = "";
// The graphics state's material under pbrt's "interface" (Material or NamedMaterial).
const std::string kInterface = "\x01";

}  // namespace

std::optional<Json> SceneBuilder::colorValue(const Params& p, std::string_view name, int spectrumKind) {
    const Param* param = p.find(name);
    if (!param) return std::nullopt;
    if (param->type == "texture") {
        const std::string& texture = param->strings.at(0);
        auto it = spectrumTextures_.find(texture);
        if (it == spectrumTextures_.end())
            fail(param->where, "\"" + param->name + "\": no spectrum texture named \"" + texture + "\"");
        return it->second;
    }
    // Named metal spectra stay names: photon's conductor reads them from its own table.
    if (param->type == "spectrum" && param->strings.size() == 1 && param->strings[0].rfind("metal-", 0) == 0 &&
        static_cast<SpectrumKind>(spectrumKind) == SpectrumKind::Index) {
        spectrumColor(*param, SpectrumKind::Index, baseDir_);  // checks the name
        return Json(param->strings[0]);
    }
    return rgb(spectrumColor(*param, static_cast<SpectrumKind>(spectrumKind), baseDir_));
}

std::optional<Json> SceneBuilder::floatValue(const Params& p, std::string_view name) {
    const Param* param = p.find(name);
    if (!param) return std::nullopt;
    if (param->type == "texture") {
        const std::string& texture = param->strings.at(0);
        auto it = floatTextures_.find(texture);
        if (it == floatTextures_.end())
            fail(param->where, "\"" + param->name + "\": no float texture named \"" + texture + "\"");
        return it->second;
    }
    if ((param->type != "float" && param->type != "integer") || param->numbers.size() != 1)
        fail(param->where, "\"" + param->name + "\" must be one float or a float texture");
    return Json(param->numbers[0]);
}

namespace {

// A float texture's JSON where a colour is read: numbers become greys (an image is read in
// colour, which for a grey image is the same), a mix's amount stays a float.
Json floatTextureAsColor(Json t) {
    if (t.is_number()) return Json::array({t, t, t});
    if (!t.is_object()) return t;
    for (const char* key : {"even", "odd", "a", "b"})
        if (t.contains(key)) t[key] = floatTextureAsColor(t[key]);
    return t;
}

}  // namespace

Json clampedReflectance(Json value, const Location& where, std::vector<std::string>& warnings) {
    if (!value.is_array()) return value;
    bool clamped = false;
    for (Json& v : value) {
        const double c = v.get<double>();
        if (c < 0 || c > 1) {
            v = std::clamp(c, 0.0, 1.0);
            clamped = true;
        }
    }
    if (clamped) warnings.push_back(where.str() + ": a reflectance outside [0, 1] clamped to it");
    return value;
}

namespace {

double number(const Json& v) { return v.is_number() ? v.get<double>() : -1; }

}  // namespace

// pbrt's (u, v) roughness and remap flag as one perceptual roughness (photon's dielectric
// and coated diffuse are isotropic).
Json SceneBuilder::roughnessFields(const Params& p, bool anisotropic, const std::string& prefix, bool texturable) {
    const Location& where = p.directive().where;
    std::optional<Json> r = floatValue(p, prefix + "roughness"), u = floatValue(p, prefix + "uroughness"),
                        v = floatValue(p, prefix + "vroughness");
    const bool remap = p.boolean("remaproughness", true);
    if (!u) u = r;
    if (!v) v = r;
    if (anisotropic) {
        Json out = Json::object();
        if (u) out["uroughness"] = *u;
        if (v) out["vroughness"] = *v;
        if (u || v) out["remap_roughness"] = remap;
        return out;
    }
    if (!u && !v) return Json::object();
    const Json& one = u ? *u : *v;
    // A roughness map, on a material that takes one (coated_diffuse): pbrt's meaning kept.
    if (texturable && (!one.is_number() || (v && !v->is_number()))) {
        if (u && v && *u != *v)
            warn(where, "anisotropic roughness (uroughness != vroughness) on an isotropic photon material: uroughness used");
        return Json{{"roughness", one}, {"remap_roughness", remap}};
    }
    if (!one.is_number() || (v && !v->is_number())) {
        warn(where, "a textured roughness on this material is not supported; its mean is not known here, 0 used");
        return Json::object();
    }
    double a = number(one);
    if (v && std::abs(number(*v) - a) > 1e-6) {
        warn(where, "anisotropic roughness (uroughness != vroughness) on an isotropic photon material: their mean used");
        a = 0.5 * (a + number(*v));
    }
    const double alpha = remap ? std::sqrt(std::max(a, 0.0)) : a;
    return Json{{"roughness", std::clamp(std::sqrt(std::max(alpha, 0.0)), 0.0, 1.0)}};
}

namespace {

// A dielectric's index: a float, or a spectrum's value (named glasses have one; a sampled
// spectrum's dispersion is lost: its mean over the visible colour channels is used).
double indexOfRefraction(const Params& p, const std::filesystem::path& baseDir, std::vector<std::string>& warnings,
                         const std::string& name = "eta") {
    const Param* eta = p.find(name);
    if (!eta) return 1.5;
    if (eta->type == "texture") fail(eta->where, "a textured eta is not supported");
    const Color c = spectrumColor(*eta, SpectrumKind::Index, baseDir);
    if (eta->type == "spectrum" && eta->numbers.size() > 1)
        warnings.push_back(eta->where.str() + ": dispersion left out; the index's mean over R, G, B used");
    return (c.x + c.y + c.z) / 3;
}

}  // namespace

// pbrt-v4's layered materials attenuate light crossing the layer by exp(-thickness / |cos|)
// even with no medium in it (LayeredBxDF's Tr); photon's coats have no thickness, which
// matches pbrt's default of 0.01 within 2% at normal incidence (in and out). A layer that
// takes more than 5% there (thickness above 0.025) is warned of.
void SceneBuilder::warnOfLayerThickness(const Params& p, const std::string& type) {
    const double thickness = p.number("thickness", 0.01);
    if (thickness > 0.025)
        warn(p.directive().where, type + ": \"thickness\" " + std::to_string(thickness) +
                                      " is left out (photon's coat is thin: pbrt's light crossing it is not attenuated)");
}

// pbrt-v4's HairMaterial: sigma_a, else reflectance (or color), else eumelanin and pheomelanin (1.3 and
// 0 when none is given); the model's eta, beta_m, beta_n and alpha. Its parameters may be
// textures in pbrt; photon's hair takes constants.
Json SceneBuilder::hairJson(const Params& p) {
    const Location& where = p.directive().where;
    Json m = {{"type", "hair"}};
    auto constant = [&](const std::string& name, std::optional<Json> v) -> std::optional<Json> {
        if (v && !v->is_array() && !v->is_number()) {
            unsupported(p.directive(), "hair: a textured \"" + name + "\" is not supported", "its default used");
            return std::nullopt;
        }
        return v;
    };
    // "color" is the reflectance's name in pbrt-v4 before it was renamed, which it still reads.
    const char* reflectanceName = p.has("reflectance") || !p.has("color") ? "reflectance" : "color";
    if (auto sigma = constant("sigma_a", colorValue(p, "sigma_a", int(SpectrumKind::Index)))) {
        m["sigma_a"] = *sigma;
    } else if (auto r = constant(reflectanceName, colorValue(p, reflectanceName, int(SpectrumKind::Reflectance)))) {
        Json c = clampedReflectance(*r, where, out_.warnings);
        for (Json& x : c) x = std::clamp(x.get<double>(), 1e-4, 1.0);  // photon's "color" is in (0, 1]
        m["color"] = c;
    } else {
        for (const char* name : {"eumelanin", "pheomelanin"})
            if (auto v = constant(name, floatValue(p, name))) m[name] = *v;
    }
    for (const auto& [pbrtName, name] : {std::pair{"eta", "eta"}, {"beta_m", "beta_m"}, {"beta_n", "beta_n"}, {"alpha", "alpha"}})
        if (auto v = constant(pbrtName, floatValue(p, pbrtName))) m[name] = *v;
    return m;
}

std::optional<Json> SceneBuilder::materialJson(const std::string& type, const Params& p) {
    const Location& where = p.directive().where;
    Json m;
    if (type == "interface" || type == "none" || type.empty()) return std::nullopt;
    if (type == "diffuse") {
        m = {{"type", "diffuse"},
             {"albedo", clampedReflectance(colorValue(p, "reflectance", int(SpectrumKind::Reflectance)).value_or(rgb(Color(0.5f))),
                                    where, out_.warnings)}};
    } else if (type == "coateddiffuse") {
        m = {{"type", "coated_diffuse"},
             {"albedo", clampedReflectance(colorValue(p, "reflectance", int(SpectrumKind::Reflectance)).value_or(rgb(Color(0.5f))),
                                    where, out_.warnings)},
             {"ior", indexOfRefraction(p, baseDir_, out_.warnings)}};
        m.update(roughnessFields(p, false, "", true));
        if (auto albedo = colorValue(p, "albedo", int(SpectrumKind::Reflectance));
            albedo && !(albedo->is_array() && (*albedo)[0] == 0 && (*albedo)[1] == 0 && (*albedo)[2] == 0))
            warn(where, "coateddiffuse: the medium between coat and base (albedo, g, thickness) is left out");
        warnOfLayerThickness(p, "coateddiffuse");
        // The random walk's depth and samples are pbrt's estimator, which photon's closed form
        // replaces.
        for (const char* name : {"g", "maxdepth", "nsamples"}) p.find(name);
    } else if (type == "dielectric" || type == "thindielectric") {
        m = {{"type", "dielectric"}, {"ior", indexOfRefraction(p, baseDir_, out_.warnings)}};
        if (type == "thindielectric") {
            m["thin"] = true;
        } else {
            m.update(roughnessFields(p, false, "", true));
        }
    } else if (type == "conductor" || type == "coatedconductor") {
        const bool coated = type == "coatedconductor";
        const std::string prefix = coated ? "conductor." : "";
        Json metal = Json::object();
        if (auto r = colorValue(p, "reflectance", int(SpectrumKind::Reflectance))) {
            const Json f0 = clampedReflectance(*r, where, out_.warnings);
            if (f0.is_array()) {
                // pbrt-v4 makes a constant reflectance r an index: eta 1, k = 2 sqrt(r) /
                // sqrt(1 - r), whose Fresnel is r at normal incidence (r at most 0.9999).
                Json k = Json::array();
                for (const Json& c : f0) {
                    const double v = std::min(c.get<double>(), 0.9999);
                    k.push_back(2 * std::sqrt(v) / std::sqrt(1 - v));
                }
                metal["eta"] = {1, 1, 1};
                metal["k"] = k;
            } else {
                metal["reflectance"] = f0;
                warn(where, "conductor \"reflectance\" from a texture: taken as the reflectance at normal incidence "
                            "(Schlick's Fresnel); pbrt-v4 derives an index from it");
            }
        } else {
            metal["eta"] = colorValue(p, prefix + "eta", int(SpectrumKind::Index)).value_or(Json("metal-Cu-eta"));
            metal["k"] = colorValue(p, prefix + "k", int(SpectrumKind::Index)).value_or(Json("metal-Cu-k"));
        }
        Json r = roughnessFields(p, true, prefix);
        // pbrt's conductor is smooth without a roughness; photon's defaults to 0.2.
        if (!r.contains("uroughness")) r = {{"roughness", 0}};
        metal.update(r);
        if (!coated) {
            m = {{"type", "conductor"}};
            m.update(metal);
        } else {
            // The metal's index is given as pbrt-v4 gives it; photon's coated_conductor takes
            // it relative to the coat, as pbrt-v4 does (docs/scene-format.md).
            m = {{"type", "coated_conductor"},
                 {"ior", indexOfRefraction(p, baseDir_, out_.warnings, "interface.eta")},
                 {"conductor", metal}};
            m.update(roughnessFields(p, false, "interface."));
            if (auto albedo = colorValue(p, "albedo", int(SpectrumKind::Reflectance));
                albedo && !(albedo->is_array() && (*albedo)[0] == 0 && (*albedo)[1] == 0 && (*albedo)[2] == 0))
                warn(where, "coatedconductor: the medium between coat and metal (albedo, g, thickness) is left out");
            warnOfLayerThickness(p, "coatedconductor");
            for (const char* name : {"g", "maxdepth", "nsamples"}) p.find(name);
        }
    } else if (type == "diffusetransmission") {
        const double scale = p.number("scale", 1);
        auto scaled = [&](std::optional<Json> v) {
            Json c = v.value_or(rgb(Color(0.25f)));
            if (scale == 1) return c;
            if (c.is_array()) {
                for (Json& x : c) x = x.get<double>() * scale;
                return c;
            }
            return Json{{"type", "product"}, {"a", c}, {"b", rgb(Color(float(scale)))}};
        };
        m = {{"type", "diffuse_transmission"},
             {"reflectance", clampedReflectance(scaled(colorValue(p, "reflectance", int(SpectrumKind::Reflectance))), where, out_.warnings)},
             {"transmittance",
              clampedReflectance(scaled(colorValue(p, "transmittance", int(SpectrumKind::Reflectance))), where, out_.warnings)}};
    } else if (type == "hair") {
        m = hairJson(p);
    } else if (type == "subsurface") {
        m = subsurfaceJson(p);
    } else if (type == "measured") {
        // RGL's tabulated BRDFs (.bsdf), read by the scene loader (scene/measured_brdf_file.h).
        const std::string file = p.string("filename", "");
        if (file.empty()) fail(where, "measured: needs a \"string filename\" (a .bsdf file)");
        if (auto why = checkRelativePath(file)) fail(where, "measured: \"" + file + "\": " + *why);
        m = {{"type", "measured"}, {"file", file}};
    } else if (type == "mix") {
        const std::vector<std::string> names = p.strings("materials");
        if (names.size() != 2) fail(where, "mix: \"materials\" must name two materials");
        Json parts = Json::array();
        for (const std::string& n : names) {
            const std::string part = namedMaterial(n, where);
            if (part == kInterface) fail(where, "mix: material \"" + n + "\" is an interface (no surface)");
            parts.push_back(part);
        }
        m = {{"type", "mix"}, {"materials", parts}, {"amount", floatValue(p, "amount").value_or(Json(0.5))}};
    } else {
        unsupported(p.directive(), "material \"" + type + "\" is not supported (photon imports diffuse, coateddiffuse, dielectric, "
                                   "thindielectric, conductor, coatedconductor, diffusetransmission, hair, measured, mix, "
                                   "interface, subsurface)",
                    "rendered as a grey diffuse material");
        return Json{{"type", "diffuse"}, {"albedo", rgb(Color(0.5f))}};
    }
    if (auto d = floatValue(p, "displacement")) m["bump"] = *d;
    if (auto n = p.string("normalmap")) {
        if (auto why = checkRelativePath(*n)) fail(where, "normalmap \"" + *n + "\": " + *why);
        m["normal_map"] = *n;
    }
    return m;
}

void SceneBuilder::makeNamedMaterial(const Directive& d) {
    Params p(d);
    const std::string& name = d.strings.at(0);
    const std::string type = p.string("type", "");
    if (!p.has("type")) fail(d.where, "MakeNamedMaterial \"" + name + "\" has no \"string type\"");
    std::optional<Json> m = materialJson(type, p);
    if (!m)
        if (auto ahead = materialsNamedAhead_.find(name); ahead != materialsNamedAhead_.end())
            fail(d.where, "MakeNamedMaterial \"" + name + "\": an interface (no surface), named at " + ahead->second.str() +
                              " before it is made here; make it before the shapes that use it");
    namedMaterials_[name] = m ? name : kInterface;
    if (m) materials_[name] = *m;
}

std::string SceneBuilder::namedMaterial(const std::string& name, const Location& where) {
    if (auto it = namedMaterials_.find(name); it != namedMaterials_.end()) return it->second;
    materialsNamedAhead_.try_emplace(name, where);
    return name;
}

void SceneBuilder::checkMaterialsNamedAhead() {
    for (const auto& [name, where] : materialsNamedAhead_) {
        if (namedMaterials_.contains(name)) continue;
        const std::string message = "material \"" + name + "\" is named here but never made (MakeNamedMaterial)";
        if (!lenient_) fail(where, message);
        warn(where, message + "; rendered as pbrt-v4's default material, diffuse of reflectance 0.5 (lenient import)");
        materials_[name] = {{"type", "diffuse"}, {"albedo", rgb(Color(0.5f))}};
    }
}

void SceneBuilder::material(const Directive& d) {
    Params p(d);
    std::optional<Json> m = materialJson(d.strings.at(0), p);
    if (!m) {
        state_.material = kInterface;  // shapes under it are no surfaces, or bound media
        return;
    }
    // Identical anonymous materials share one entry.
    for (auto& [name, existing] : materials_.items())
        if (existing == *m && name.rfind("material ", 0) == 0) {
            state_.material = name;
            return;
        }
    const std::string name = "material " + std::to_string(++materialCount_);
    materials_[name] = *m;
    state_.material = name;
}

std::string SceneBuilder::currentMaterial() {
    if (state_.material == kInterface) {
        if (!shapeMedium()) return kNoSurface;
        // A boundary between media and nothing else: a dielectric of index 1 lets every ray
        // through unbent, and the path changes medium there.
        if (!materials_.contains("medium boundary")) materials_["medium boundary"] = {{"type", "dielectric"}, {"ior", 1}};
        return "medium boundary";
    }
    if (!state_.material.empty()) return state_.material;
    // pbrt-v4's default material: diffuse, reflectance 0.5.
    if (!materials_.contains("default")) materials_["default"] = {{"type", "diffuse"}, {"albedo", rgb(Color(0.5f))}};
    return "default";
}

void SceneBuilder::texture(const Directive& d) {
    Params p(d);
    const std::string& name = d.strings.at(0);
    const std::string& kind = d.strings.at(1);
    const std::string& cls = d.strings.at(2);
    if (kind != "spectrum" && kind != "float" && kind != "color")
        fail(d.where, "Texture \"" + name + "\": type must be \"spectrum\" or \"float\", not \"" + kind + "\"");
    const bool color = kind != "float";
    auto value = [&](std::string_view param, double fallback) {
        std::optional<Json> v = color ? colorValue(p, param, int(SpectrumKind::Reflectance)) : floatValue(p, param);
        return v.value_or(color ? rgb(Color(float(fallback))) : Json(fallback));
    };
    // The texture's space is where the CTM places it (pbrt-v4's renderFromTexture): the
    // mappings that read the point, and solid textures, read it there.
    auto placement = [&](Json& mapping) {
        if (!pointCtm(d).identity()) mapping["transform"] = matrixJson(state_.ctm);
    };
    // pbrt-v4's TextureMapping2D: "uv" (uscale, vscale, udelta, vdelta), "spherical",
    // "cylindrical", "planar" (v1, v2, udelta, vdelta).
    auto mapping = [&](Json& t) {
        const std::string map = p.string("mapping", "uv");
        const double du = p.number("udelta", 0), dv = p.number("vdelta", 0);
        if (du != 0 || dv != 0) t["uv_offset"] = {du, dv};
        if (map == "uv") {
            const double su = p.number("uscale", 1), sv = p.number("vscale", 1);
            if (su != 1 || sv != 1) t["uv_scale"] = {su, sv};
            return;
        }
        if (map != "spherical" && map != "cylindrical" && map != "planar") {
            unsupported(d, "Texture \"" + name + "\": mapping \"" + map +
                               "\" is not supported (uv, spherical, cylindrical, planar)", "uv used");
            return;
        }
        Json m = {{"type", map}};
        placement(m);
        if (map == "planar") {
            const Vec3 s = p.vec3("v1", {1, 0, 0}), t2 = p.vec3("v2", {0, 1, 0});
            m["s"] = {s.x, s.y, s.z};
            m["t"] = {t2.x, t2.y, t2.z};
        }
        t["mapping"] = m;
    };
    auto solid = [&](Json& t) {
        Json m = {{"type", "solid"}};
        placement(m);
        t["mapping"] = m;
    };
    // fbm's, wrinkled's and marble's type, octaves and roughness, checked.
    auto noiseOctaves = [&](const std::string& type) -> Json {
        const double octaves = p.number("octaves", 8), roughness = p.number("roughness", 0.5);
        if (!(octaves >= 1 && octaves <= 30 && octaves == std::floor(octaves)))
            fail(d.where, "Texture \"" + name + "\": \"octaves\" must be a whole number from 1 to 30");
        if (!(roughness >= 0 && roughness <= 1))
            fail(d.where, "Texture \"" + name + "\": \"roughness\" must be in [0, 1]");
        return {{"type", type}, {"octaves", int(octaves)}, {"roughness", roughness}};
    };
    Json t;
    if (cls == "imagemap") {
        const std::string file = p.string("filename", "");
        if (file.empty()) fail(d.where, "Texture \"" + name + "\": imagemap needs a \"filename\"");
        if (auto why = checkRelativePath(file)) fail(d.where, "Texture \"" + name + "\": \"" + file + "\": " + *why);
        t = {{"type", "image"}, {"file", file}};
        // A float texture is the image's first channel (pbrt-v4's MIPMap reads channel 0 of
        // an RGB(A) image for a Float texel), through the texture's encoding as a colour's.
        if (!color) t["channel"] = "r";
        mapping(t);
        // pbrt-v4's ColorEncoding: "sRGB", "linear" or "gamma g"; where not given, sRGB for
        // a PNG file and linear for any other (pbrt-v4's ImageTexture Create functions: an
        // 8-bit JPEG is read as linear unless the file says otherwise) but a TGA. pbrt-v3 read
        // TGA and PNG through the sRGB curve unless "bool gamma" said otherwise, and pbrt-v4's
        // --upgrade writes an encoding only where the v3 file gave "gamma", so an upgraded
        // scene's TGAs (every textured one of Bitterli's) would lose the curve their author
        // and their reference renders gave them.
        const std::string extension = lowerCaseExtension(file);
        const std::string encoding = p.string("encoding", extension == ".png" || extension == ".tga" ? "sRGB" : "linear");
        double gamma = 0;
        if (encoding == "sRGB" && !color) {
            t["encoding"] = "srgb";  // a single channel is otherwise read as stored
        } else if (encoding == "linear") {
            t["encoding"] = "linear";
        } else if (std::sscanf(encoding.c_str(), "gamma %lf", &gamma) == 1 && gamma > 0 && gamma < 10) {
            t["encoding"] = "gamma";
            t["gamma"] = gamma;
        } else if (encoding != "sRGB") {
            unsupported(d, "Texture \"" + name + "\": encoding \"" + encoding + "\" is not sRGB, linear or \"gamma g\" (0 < g < 10)",
                        "read as sRGB");
        }
        const std::string wrap = p.string("wrap", "repeat");
        if (wrap == "clamp" || wrap == "black") {
            t["wrap"] = wrap;
        } else if (wrap != "repeat") {
            warn(d.where, "Texture \"" + name + "\": wrap \"" + wrap + "\" read as repeat");
        }
        for (const char* ignored : {"filter", "maxanisotropy"}) p.find(ignored);  // photon filters bilinearly
        const double scale = p.number("scale", 1);
        if (p.boolean("invert", false)) {
            // pbrt-v4 inverts the scaled value, max(0, 1 - scale v): photon's product comes
            // after the image, so only a scale of 1 keeps that order.
            if (scale != 1)
                unsupported(d, "Texture \"" + name + "\": \"invert\" with a \"scale\" other than 1 is not supported",
                            "not inverted");
            else
                t["invert"] = true;
        }
        if (scale != 1) t = {{"type", "product"}, {"a", t}, {"b", color ? rgb(Color(float(scale))) : Json(scale)}};
    } else if (cls == "checkerboard") {
        const double dimension = p.number("dimension", 2);
        if (dimension != 2 && dimension != 3)
            fail(d.where, "Texture \"" + name + "\": a checkerboard's \"dimension\" is 2 or 3");
        t = {{"type", "checkerboard"}, {"even", value("tex1", 1)}, {"odd", value("tex2", 0)}};
        if (dimension == 3) {
            solid(t);
        } else {
            mapping(t);
        }
    } else if (cls == "bilerp") {
        t = {{"type", "bilerp"}, {"v00", value("v00", 0)}, {"v01", value("v01", 1)}, {"v10", value("v10", 0)},
             {"v11", value("v11", 1)}};
        mapping(t);
    } else if (cls == "fbm" || cls == "wrinkled") {
        t = noiseOctaves(cls);
        solid(t);
    } else if (cls == "windy") {
        t = {{"type", "windy"}};
        solid(t);
    } else if (cls == "marble" && color) {
        // A spectrum texture only in pbrt-v4 (its float textures have no marble).
        const double scale = p.number("scale", 1), variation = p.number("variation", 0.2);
        if (!(scale > 0 && std::isfinite(scale)))
            fail(d.where, "Texture \"" + name + "\": \"scale\" must be positive");
        if (!(variation >= 0 && std::isfinite(variation)))
            fail(d.where, "Texture \"" + name + "\": \"variation\" must not be negative");
        t = noiseOctaves("marble");
        t["scale"] = scale, t["variation"] = variation;
        solid(t);
    } else if (cls == "dots") {
        t = {{"type", "dots"}, {"inside", value("inside", 1)}, {"outside", value("outside", 0)}};
        mapping(t);
    } else if (cls == "scale") {
        // pbrt-v4's scale is a float texture for either kind (SpectrumScaledTexture::Create).
        const Json scale = floatValue(p, "scale").value_or(Json(1.0));
        t = {{"type", "product"}, {"a", value("tex", 1)}, {"b", color ? floatTextureAsColor(scale) : scale}};
    } else if (cls == "mix") {
        const std::optional<Json> amount = floatValue(p, "amount");
        t = {{"type", "mix"}, {"a", value("tex1", 0)}, {"b", value("tex2", 1)}, {"amount", amount.value_or(Json(0.5))}};
    } else if (cls == "directionmix") {
        // pbrt-v4 turns "dir" by the CTM at the Texture (renderFromTexture) and normalises it.
        const Vec3 dir = state_.ctm.vector(p.vec3("dir", {0, 1, 0}));
        if (!(lengthSquared(dir) > 0) || !std::isfinite(lengthSquared(dir)))
            fail(d.where, "Texture \"" + name + "\": \"dir\" must be a direction, not zero");
        const Vec3 unit = normalize(dir);
        t = {{"type", "direction_mix"}, {"along", value("tex1", 0)}, {"across", value("tex2", 1)},
             {"direction", {unit.x, unit.y, unit.z}}};
    } else if (cls == "constant") {
        t = value("value", 1);
    } else {
        unsupported(d, "Texture \"" + name + "\": class \"" + cls +
                           "\" is not supported (photon imports imagemap, checkerboard, bilerp, dots, fbm, wrinkled, windy, marble, scale, mix, "
                           "directionmix, constant)",
                    "the constant 0.5 used");
        t = color ? rgb(Color(0.5f)) : Json(0.5);
    }
    (color ? spectrumTextures_ : floatTextures_)[name] = t;
}

}  // namespace photon::pbrt
