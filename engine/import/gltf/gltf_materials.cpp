// glTF's metallic-roughness materials (glTF 2.0 sec. 3.9) and the KHR material extensions
// photon can render, as photon materials and shape fields.
//
// The BRDF of sec. B.3 is a mix, by metalness, of a dielectric layer over a diffuse base
// and a metal: photon's coated_diffuse (albedo under a clear coat of ior 1.5) and conductor
// (Schlick's Fresnel from the base colour) are those two, mixed by `mix` with amount =
// metallic. Both use GGX with alpha = roughness^2, as glTF does (sec. B.3.2).
#include <algorithm>
#include <cmath>
#include <limits>
#include <set>
#include "import/gltf/gltf_parts.h"

namespace photon::gltf {
namespace {

const std::set<std::string> kMaterialExtensions = {"KHR_materials_clearcoat", "KHR_materials_emissive_strength",
                                                   "KHR_materials_ior", "KHR_materials_transmission",
                                                   "KHR_materials_volume"};

Json product(Json a, Json b) { return {{"type", "product"}, {"a", std::move(a)}, {"b", std::move(b)}}; }

double fraction(double v) { return std::clamp(v, 0.0, 1.0); }

const tinygltf::Value* extension(const tinygltf::Material& m, const char* name) {
    auto it = m.extensions.find(name);
    return it == m.extensions.end() ? nullptr : &it->second;
}

// Everything the material's parts share: where it is and what glTF gives.
struct Source {
    const tinygltf::Material& m;
    std::string pointer;  // "/materials/i", or "" for the default material
    Json baseTexture;     // the base colour texture's reference, null without one
    TextureSlot slot(const tinygltf::TextureInfo& info, const std::string& under) const {
        return {info.index, info.texCoord, &info.extensions, pointer + under};
    }
};

// baseColorFactor x baseColorTexture (sRGB colour, sec. 3.9.2).
Json baseColor(const Source& s) {
    const auto& pbr = s.m.pbrMetallicRoughness;
    Json factor = Json::array();
    for (int c = 0; c < 3; ++c) factor.push_back(fraction(pbr.baseColorFactor.size() == 4 ? pbr.baseColorFactor[c] : 1.0));
    if (s.baseTexture.is_null()) return factor;
    return factor == Json{1.0, 1.0, 1.0} ? s.baseTexture : product(s.baseTexture, factor);
}

// roughnessFactor x the texture's G, or metallicFactor x its B (linear data, sec. 3.9.2).
Json packedFraction(Context& ctx, const Source& s, double factor, const char* channel) {
    const auto& info = s.m.pbrMetallicRoughness.metallicRoughnessTexture;
    if (info.index < 0 || factor == 0) return fraction(factor);
    Json texture = textureReference(ctx, s.slot(info, "/pbrMetallicRoughness/metallicRoughnessTexture"), channel);
    return factor == 1 ? texture : product(texture, fraction(factor));
}

double iorOf(Context& ctx, const Source& s) {
    const tinygltf::Value* ext = extension(s.m, "KHR_materials_ior");
    const double ior = ext ? numberIn(*ext, "ior", 1.5) : 1.5;
    if (ior > 0) return ior;
    ctx.warn(s.pointer + "/extensions/KHR_materials_ior/ior", "must be > 0 for photon; 1.5 used");
    return 1.5;
}

// KHR_materials_clearcoat on the metal: a clear coat of index 1.5 (the extension's) over the
// conductor, as photon's coated_conductor, in the share clearcoatFactor. The dielectric
// part keeps its own coat (coated_diffuse's), so a second coat over it is left out.
Json clearcoated(Context& ctx, const Source& s, Json conductor) {
    const tinygltf::Value* ext = extension(s.m, "KHR_materials_clearcoat");
    if (!ext) return conductor;
    const std::string at = s.pointer + "/extensions/KHR_materials_clearcoat/";
    for (const char* texture : {"clearcoatTexture", "clearcoatRoughnessTexture", "clearcoatNormalTexture"})
        if (ext->Has(texture)) ctx.warn(at + texture, "ignored: photon's coat takes constant factors");
    const double factor = fraction(numberIn(*ext, "clearcoatFactor", 0.0));
    if (factor == 0) return conductor;
    Json metal = conductor;
    metal.erase("type");
    Json coated = {{"type", "coated_conductor"},
                   {"ior", 1.5},
                   {"roughness", fraction(numberIn(*ext, "clearcoatRoughnessFactor", 0.0))},
                   {"conductor", metal}};
    if (factor == 1) return coated;
    return {{"type", "mix"}, {"materials", {conductor, coated}}, {"amount", factor}};
}

Json opaqueMaterial(Context& ctx, const Source& s) {
    const auto& pbr = s.m.pbrMetallicRoughness;
    const Json base = baseColor(s);
    const Json metallic = packedFraction(ctx, s, pbr.metallicFactor, "b");
    const Json roughness = packedFraction(ctx, s, pbr.roughnessFactor, "g");
    Json conductor = clearcoated(ctx, s, {{"type", "conductor"}, {"reflectance", base}, {"roughness", roughness}});
    if (metallic == 0.0 && extension(s.m, "KHR_materials_clearcoat"))
        ctx.warn(s.pointer + "/extensions/KHR_materials_clearcoat",
                 "a clear coat over a non-metal is left out (photon's coated_diffuse has one coat)");
    if (metallic == 1.0) return conductor;
    Json coated = {{"type", "coated_diffuse"}, {"albedo", base}, {"ior", iorOf(ctx, s)}, {"roughness", roughness}};
    if (metallic == 0.0) return coated;
    return {{"type", "mix"}, {"materials", {coated, conductor}}, {"amount", metallic}};
}

// KHR_materials_volume's attenuation as an absorbing medium: light crossing a distance d
// keeps attenuationColor^(d / attenuationDistance), so absorption = -ln(colour) / distance
// (the extension's sigma_t, all absorption). Null where it keeps all light. A colour channel
// of 0 absorbs everything: its absorption is that of 1e-6 over the distance (a factor 1e-6).
Json volumeMedium(Context& ctx, const std::string& pointer, const tinygltf::Value& volume) {
    const double distance = numberIn(volume, "attenuationDistance", std::numeric_limits<double>::infinity());
    if (!(distance > 0)) ctx.fail(pointer + "/attenuationDistance", "must be > 0");
    if (std::isinf(distance)) return nullptr;
    Json absorption = Json::array();
    bool any = false;
    const tinygltf::Value& colour = volume.Get("attenuationColor");
    for (int c = 0; c < 3; ++c) {
        const tinygltf::Value& v = colour.IsArray() && int(colour.ArrayLen()) == 3 ? colour.Get(c) : tinygltf::Value();
        const double k = v.IsNumber() || v.IsInt() ? v.GetNumberAsDouble() : 1.0;
        const double a = -std::log(std::clamp(k, 1e-6, 1.0)) / distance;
        absorption.push_back(a);
        any = any || a > 0;
    }
    return any ? Json{{"absorption", absorption}} : Json();
}

// KHR_materials_transmission (and KHR_materials_volume): glass.
Json transmissiveMaterial(Context& ctx, const Source& s, const tinygltf::Value& transmission, MaterialMapping& r) {
    const std::string ext = s.pointer + "/extensions/";
    const Json roughness = packedFraction(ctx, s, s.m.pbrMetallicRoughness.roughnessFactor, "g");
    Json glass = {{"type", "dielectric"}, {"ior", iorOf(ctx, s)}, {"roughness", roughness}};
    if (transmission.Has("transmissionTexture"))
        ctx.warn(ext + "KHR_materials_transmission/transmissionTexture", "ignored; transmissionFactor used");
    if (s.m.pbrMetallicRoughness.metallicFactor > 0)
        ctx.warn(s.pointer + "/pbrMetallicRoughness/metallicFactor", "ignored on a transmissive material");
    const auto& f = s.m.pbrMetallicRoughness.baseColorFactor;
    if (s.m.pbrMetallicRoughness.baseColorTexture.index >= 0 || (f.size() == 4 && (f[0] != 1 || f[1] != 1 || f[2] != 1)))
        ctx.warn(s.pointer + "/pbrMetallicRoughness", "photon's dielectric is clear: the base colour's tint is ignored");
    if (const tinygltf::Value* volume = extension(s.m, "KHR_materials_volume")) {
        // A volume's boundary: a solid dielectric, its attenuation the medium inside. The
        // thickness is for renderers that do not trace the geometry (the extension's own
        // words); a ray tracer crosses the real one.
        r.medium = volumeMedium(ctx, ext + "KHR_materials_volume", *volume);
        return glass;
    }
    // Without KHR_materials_volume the surface is thin-walled (KHR_materials_transmission:
    // "the material is thin"): photon's thin dielectric, which must be smooth.
    if (!roughness.is_number() || roughness.get<double>() > 0) {
        ctx.warn(ext + "KHR_materials_transmission",
                 "a thin-walled rough transmitter is rendered as the boundary of a rough solid dielectric");
        return glass;
    }
    glass["thin"] = true;
    return glass;
}

// Emission on the shape (sec. 3.9.3 and KHR_materials_emissive_strength); photon emits on
// the normal's side unless two_sided.
void emission(Context& ctx, const Source& s, MaterialMapping& r) {
    const auto& e = s.m.emissiveFactor;
    Json factor = Json::array();
    bool black = true;
    for (int c = 0; c < 3; ++c) {
        const double v = e.size() == 3 ? std::max(e[c], 0.0) : 0.0;
        factor.push_back(v);
        black = black && v == 0;
    }
    const tinygltf::Value* strength = extension(s.m, "KHR_materials_emissive_strength");
    const double scale = strength ? std::max(numberIn(*strength, "emissiveStrength", 1.0), 0.0) : 1.0;
    if (black || scale == 0) return;
    Json value = factor;
    if (s.m.emissiveTexture.index >= 0) {
        Json texture = textureReference(ctx, s.slot(s.m.emissiveTexture, "/emissiveTexture"));
        value = factor == Json{1.0, 1.0, 1.0} ? texture : product(texture, factor);
    }
    r.shapeFields["emission"] = value;
    if (scale != 1) r.shapeFields["emission_scale"] = scale;
    if (s.m.doubleSided) r.shapeFields["two_sided"] = true;
}

// alphaMode (sec. 3.9.4): MASK is photon's alpha with alpha_cutoff; BLEND has no
// equivalent and becomes stochastic coverage.
void alpha(Context& ctx, const Source& s, MaterialMapping& r) {
    if (s.m.alphaMode != "MASK" && s.m.alphaMode != "BLEND") return;
    const auto& pbr = s.m.pbrMetallicRoughness;
    const double factor = fraction(pbr.baseColorFactor.size() == 4 ? pbr.baseColorFactor[3] : 1.0);
    const bool textured = !s.baseTexture.is_null();
    const bool mask = s.m.alphaMode == "MASK";
    const double cutoff = s.m.alphaCutoff;
    if (mask && cutoff <= 0) return;  // everything reaches the cutoff
    if (!textured && factor >= (mask ? std::min(cutoff, 1.0) : 1.0)) return;
    if (r.shapeFields.contains("emission")) {
        ctx.warn(s.pointer + "/alphaMode", "photon's emitters are opaque: alpha ignored on an emissive material");
        return;
    }
    Json coverage = factor;
    if (textured) {
        Json t = s.baseTexture;  // its alpha, linear (sec. 3.9.2)
        t["channel"] = "a";
        coverage = factor == 1 ? t : product(t, factor);
    }
    r.shapeFields["alpha"] = coverage;
    if (mask) {
        r.shapeFields["alpha_cutoff"] = std::min(cutoff, 1.0);
    } else {
        ctx.warn(s.pointer + "/alphaMode", "BLEND is rendered as stochastic coverage (a ray passes with probability "
                                           "1 - alpha), not blended");
    }
}

void checkExtensions(Context& ctx, const Source& s) {
    for (const auto& [name, value] : s.m.extensions)
        if (!kMaterialExtensions.count(name)) ctx.warn(s.pointer + "/extensions/" + name, "unknown material extension ignored");
    if (s.m.occlusionTexture.index >= 0)
        ctx.warn(s.pointer + "/occlusionTexture", "ignored: photon computes occlusion by tracing light");
    if (s.m.normalTexture.index >= 0 && s.m.normalTexture.scale != 1)
        ctx.warn(s.pointer + "/normalTexture/scale", "photon's normal maps have no scale; 1 used");
    if (s.m.normalTexture.index >= 0 && !s.m.normalTexture.extensions.empty())
        ctx.warn(s.pointer + "/normalTexture/extensions", "photon's normal maps take no uv transform; ignored");
}

}  // namespace

MaterialMapping mapMaterial(Context& ctx, int index) {
    static const tinygltf::Material kDefault;  // sec. 3.9.6: white, metallic 1, roughness 1
    if (index >= int(ctx.model.materials.size())) ctx.fail("", "a primitive names material " + std::to_string(index) + ", which does not exist");
    Source s{index < 0 ? kDefault : ctx.model.materials[index], index < 0 ? "" : pointerTo("materials", index), nullptr};
    checkExtensions(ctx, s);
    if (s.m.pbrMetallicRoughness.baseColorTexture.index >= 0)
        s.baseTexture = textureReference(ctx, s.slot(s.m.pbrMetallicRoughness.baseColorTexture, "/pbrMetallicRoughness/baseColorTexture"));
    MaterialMapping r;
    const tinygltf::Value* transmission = extension(s.m, "KHR_materials_transmission");
    const double amount = transmission ? fraction(numberIn(*transmission, "transmissionFactor", 0.0)) : 0.0;
    if (amount > 0 && amount < 1)
        ctx.warn(s.pointer + "/extensions/KHR_materials_transmission/transmissionFactor",
                 "photon cannot mix a dielectric with an opaque material: rendered as " +
                     std::string(amount >= 0.5 ? "fully transmissive" : "opaque"));
    r.material = amount >= 0.5 ? transmissiveMaterial(ctx, s, *transmission, r) : opaqueMaterial(ctx, s);
    if (s.m.normalTexture.index >= 0)
        r.material["normal_map"] = textureFile(ctx, {s.m.normalTexture.index, s.m.normalTexture.texCoord, nullptr,
                                                     s.pointer + "/normalTexture"});
    emission(ctx, s, r);
    alpha(ctx, s, r);
    return r;
}

}  // namespace photon::gltf
