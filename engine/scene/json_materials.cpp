// The "materials" section: a name → material map, built with the factories of
// materials/material.h.
#include "materials/microfacet.h"
#include "materials/named_metals.h"
#include "scene/json_scene_parts.h"

namespace photon::scene_json {

namespace {

// Albedos and reflectances are fractions of light kept: above 1 a surface would create
// energy and photon tracing would not converge.
const Range kFraction = Range::closed(0, 1);

std::shared_ptr<const Texture> loadTexture(const JsonValue& value, LoadContext& ctx) {
    std::filesystem::path file = resolveFile(value, ctx);
    auto cached = ctx.textures.find(file);
    if (cached != ctx.textures.end()) return cached->second;
    try {
        return ctx.textures[file] = Texture::load(file);
    } catch (const std::exception& e) {
        failWithLibraryError(value, e, ctx);
    }
}

// [r, g, b] or {"texture": "relative/path.png"}.
ColorParam readColorParam(const JsonValue& value, LoadContext& ctx) {
    if (value.json().is_object()) {
        JsonObject obj = value.object();
        auto texture = loadTexture(obj.required("texture"), ctx);
        obj.finish();
        return ColorParam(texture);
    }
    if (!value.json().is_array()) value.fail("must be an array of 3 numbers or {\"texture\": \"path\"}");
    return ColorParam(value.vec3(kFraction));
}

ColorParam colorField(JsonObject& obj, std::string_view key, Color fallback, LoadContext& ctx) {
    auto value = obj.optional(key);
    return value ? readColorParam(*value, ctx) : ColorParam(fallback);
}

// Roughness is the perceptual GGX parameter (alpha = roughness^2), meaningful in [0, 1].
float roughnessField(JsonObject& obj, float fallback) { return obj.number("roughness", fallback, kFraction); }

float iorField(JsonObject& obj) { return obj.number("ior", 1.5f, Range::positive()); }

// A conductor's eta or k: [r, g, b] inside `range`, the name of a pbrt-v4 conductor
// spectrum ("metal-Au-eta", taken as its RGB projection, materials/metal_table.h), or a
// texture {"texture": "path"} (a float image for values above 1).
ColorParam complexIorPart(const JsonValue& value, const Range& range, LoadContext& ctx) {
    if (value.json().is_object()) return readColorParam(value, ctx);
    if (!value.json().is_string()) return ColorParam(value.vec3(range));
    auto color = findPbrtMetalSpectrum(value.string());
    if (!color) value.fail("unknown named spectrum \"" + value.string() + "\" (expected [r, g, b] or one of " +
                           pbrtMetalSpectrumNames() + ")");
    return ColorParam(*color);
}

// The complex index of a conductor: "metal" (a symbol of materials/metal_table.h) or "eta"
// and "k" together; nullopt if none of them is given (the Schlick form). Both forms, or
// either beside "reflectance", are refused.
std::optional<ComplexIorParam> complexIorFields(JsonObject& obj, LoadContext& ctx) {
    auto metal = obj.optional("metal");
    auto eta = obj.optional("eta");
    auto k = obj.optional("k");
    if (!metal && !eta && !k) return std::nullopt;
    if (obj.has("reflectance")) {
        obj.optional("reflectance")->fail("gives Schlick's F0; the complex index (metal, eta, k) is another way to "
                                          "give the Fresnel term: use one");
    }
    if (metal) {
        if (eta || k) (eta ? *eta : *k).fail("a named metal gives eta and k already: use either metal or eta and k");
        auto ior = findMetal(metal->string());
        if (!ior) metal->fail("unknown metal \"" + metal->string() + "\" (expected one of " + metalSymbols() + ")");
        return ComplexIorParam{ior->eta, ior->k};
    }
    if (!eta || !k) obj.required(eta ? "k" : "eta");  // throws: missing required field
    return ComplexIorParam{complexIorPart(*eta, Range::positive(), ctx), complexIorPart(*k, Range::nonNegative(), ctx)};
}

// GGX alphas from "roughness" or, for an anisotropic lobe, "uroughness" (along the shading
// frame's s axis) and "vroughness" (along t), each defaulting to "roughness". photon's
// roughness is perceptual, alpha = roughness^2; "remap_roughness" switches to pbrt-v4's
// meaning: true, alpha = sqrt(roughness) (its remaproughness); false, alpha = roughness.
GgxAlpha conductorAlphaFields(JsonObject& obj) {
    float roughness = roughnessField(obj, 0.2f);
    float u = obj.number("uroughness", roughness, kFraction);
    float v = obj.number("vroughness", roughness, kFraction);
    auto remap = obj.optional("remap_roughness");
    if (!remap) return {roughnessToAlpha(u), roughnessToAlpha(v)};
    if (remap->boolean()) return {pbrtRoughnessToAlpha(u), pbrtRoughnessToAlpha(v)};
    return {u, v};
}

MaterialPtr readMaterial(const JsonValue& value, LoadContext& ctx) {
    JsonObject obj = value.object();
    enum Type { Diffuse, Dielectric, Mirror, Conductor, Plastic };
    auto type = Type(obj.required("type").choice({"diffuse", "dielectric", "mirror", "conductor", "plastic"}, "type"));
    MaterialPtr m;
    switch (type) {
        case Diffuse: m = makeDiffuse(colorField(obj, "albedo", Color(0.8f), ctx)); break;
        case Dielectric: m = makeDielectric(iorField(obj)); break;
        case Mirror: m = makeMirror(colorField(obj, "reflectance", Color(1.0f), ctx)); break;
        case Conductor: {
            std::optional<ComplexIorParam> ior = complexIorFields(obj, ctx);
            GgxAlpha alpha = conductorAlphaFields(obj);
            m = ior ? makeConductor(*ior, alpha) : makeConductor(colorField(obj, "reflectance", Color(0.9f), ctx), alpha);
            break;
        }
        case Plastic: {
            ColorParam albedo = colorField(obj, "albedo", Color(0.5f), ctx);
            float ior = iorField(obj);
            m = makePlastic(albedo, ior, roughnessField(obj, 0.0f));
            break;
        }
    }
    obj.finish();
    return m;
}

}  // namespace

void readMaterials(const JsonValue& value, LoadContext& ctx, SceneDescription& scene) {
    JsonObject obj = value.object();
    for (auto& [name, material] : obj.members()) {
        ctx.materialIndex[name] = uint32_t(scene.materials.size());
        scene.materials.push_back(readMaterial(material, ctx));
        scene.materialNames.push_back(name);
    }
}

}  // namespace photon::scene_json
