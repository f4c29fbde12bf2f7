// The "materials" section: a name → material map, built with the factories of
// materials/material.h.
#include "scene/json_scene_parts.h"

namespace photon::scene_json {

namespace {

// Albedos and reflectances are fractions of light kept: above 1 a surface would create
// energy and photon tracing would not converge.
const Range kFraction = Range::closed(0, 1);

}  // namespace

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

namespace {

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
            ColorParam reflectance = colorField(obj, "reflectance", Color(0.9f), ctx);
            m = makeConductor(reflectance, roughnessField(obj, 0.2f));
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
