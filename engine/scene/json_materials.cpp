// The "materials" section: a name → material map, built with the factories of
// materials/material.h.
#include <cmath>
#include <functional>
#include "materials/measured_brdf.h"
#include "materials/named_metals.h"
#include "scene/json_scene_parts.h"
#include "scene/measured_brdf_file.h"
#include "texture/textures.h"

namespace photon::scene_json {

namespace {

// Albedos and reflectances are fractions of light kept: above 1 a surface would create
// energy and photon tracing would not converge.
const Range kFraction = Range::closed(0, 1);

ColorParam colorField(JsonObject& obj, std::string_view key, Color fallback, LoadContext& ctx) {
    auto value = obj.optional(key);
    return value ? readColorParam(*value, ctx, kFraction) : ColorParam(fallback);
}

// Roughness is the perceptual GGX parameter (alpha = roughness^2), meaningful in [0, 1].
float roughnessField(JsonObject& obj, float fallback) { return obj.number("roughness", fallback, kFraction); }

float iorField(JsonObject& obj) { return obj.number("ior", 1.5f, Range::positive()); }

// A conductor's eta or k: [r, g, b] or a texture, inside `range` (docs/scene-format.md,
// "Textures"; a float image for values above 1), or the name of a pbrt-v4 conductor spectrum
// ("metal-Au-eta"), taken as its RGB projection (materials/metal_table.h).
ColorParam complexIorPart(const JsonValue& value, const Range& range, LoadContext& ctx) {
    if (!value.json().is_string()) return readColorParam(value, ctx, range);
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

// A conductor's roughness: "roughness" or, for an anisotropic lobe, "uroughness" (along the
// shading frame's s axis) and "vroughness" (along t), each defaulting to "roughness"; each a
// number in [0, 1] or a texture. photon's roughness is perceptual, alpha = roughness^2;
// "remap_roughness" switches to pbrt-v4's meaning: true, alpha = sqrt(roughness) (its
// remaproughness); false, alpha = roughness. "distribution": "ggx" (the default) or
// "beckmann".
MicrofacetRoughness conductorRoughnessFields(JsonObject& obj, LoadContext& ctx) {
    auto field = [&](std::string_view key, const FloatParam& fallback) {
        auto value = obj.optional(key);
        return value ? readFloatParam(*value, ctx, kFraction) : fallback;
    };
    FloatParam roughness = field("roughness", 0.2f);
    MicrofacetRoughness r{field("uroughness", roughness), field("vroughness", roughness)};
    if (auto remap = obj.optional("remap_roughness"))
        r.toAlpha = remap->boolean() ? RoughnessToAlpha::SquareRoot : RoughnessToAlpha::Identity;
    if (auto distribution = obj.optional("distribution")) {
        const std::string name = distribution->string();
        if (name == "beckmann") r.distribution = MicrofacetDistribution::Beckmann;
        else if (name != "ggx") distribution->fail("unknown distribution \"" + name + "\" (expected \"ggx\" or \"beckmann\")");
    }
    return r;
}

// A coated material's "roughness": a number or a texture in [0, 1], photon's perceptual
// roughness (alpha = roughness^2), or with "remap_roughness" pbrt-v4's meaning (true:
// alpha = sqrt(roughness); false: alpha = roughness). `make` builds the material at one
// roughness; a texture blends precomputed levels (materials/textured_roughness.cpp).
MaterialPtr withRoughness(JsonObject& obj, LoadContext& ctx, const ColorParam& tint, int family, float ior,
                          const std::function<MaterialPtr(float)>& make) {
    auto value = obj.optional("roughness");
    const FloatParam roughness = value ? readFloatParam(*value, ctx, kFraction) : FloatParam(0.0f);
    float exponent = 1;
    if (auto remap = obj.optional("remap_roughness")) exponent = remap->boolean() ? 0.25f : 0.5f;
    if (!roughness.textured()) return make(std::pow(roughness.value, exponent));
    // One ladder of levels per family and index, whatever the colours (~0.2 s to make).
    std::shared_ptr<const RoughnessLevels>& levels = ctx.roughnessLevels[{family, ior}];
    if (!levels) levels = makeRoughnessLevels(make);
    return makeTexturedRoughness(tint, roughness, exponent, levels);
}

// The part of an index that a coat of index `coatIor` sees: eta / coatIor or k / coatIor
// (pbrt-v4's CoatedConductorMaterial divides the same way).
ColorParam relativeTo(ColorParam part, float coatIor) {
    if (coatIor == 1.0f) return part;
    if (!part.textured()) return ColorParam(part.value / coatIor);
    return ColorParam(makeProductTexture(std::move(part), Color(1.0f / coatIor)));
}

// A conductor's fields: its Fresnel term (reflectance, metal, or eta and k) and roughness.
// Under a coat of index coatIor the complex index is taken relative to the coat's.
MaterialPtr readConductor(JsonObject& obj, LoadContext& ctx, float coatIor = 1.0f) {
    std::optional<ComplexIorParam> ior = complexIorFields(obj, ctx);
    MicrofacetRoughness roughness = conductorRoughnessFields(obj, ctx);
    if (!ior) return makeConductor(colorField(obj, "reflectance", Color(0.9f), ctx), roughness);
    return makeConductor(ComplexIorParam{relativeTo(ior->eta, coatIor), relativeTo(ior->k, coatIor)}, roughness);
}

// {"type": "coated_conductor", "ior": 1.5, "roughness": 0, "conductor": {conductor fields}}:
// the coat's index and roughness, and the metal under it.
MaterialPtr readCoatedConductor(JsonObject& obj, LoadContext& ctx) {
    const float ior = iorField(obj);
    const float roughness = roughnessField(obj, 0.0f);
    JsonObject metal = obj.required("conductor").object();
    MaterialPtr conductor = readConductor(metal, ctx, ior);
    metal.finish();
    return makeCoatedConductor(std::move(conductor), ior, roughness);
}

// A boundary (rough if roughness > 0, which may be a roughness map), or with "thin": true a
// thin slab, whose faces are smooth.
MaterialPtr readDielectric(JsonObject& obj, LoadContext& ctx, int family) {
    float ior = iorField(obj);
    if (!obj.boolean("thin", false))
        return withRoughness(obj, ctx, Color(1.0f), family, ior, [&](float r) { return makeRoughDielectric(ior, r); });
    if (roughnessField(obj, 0.0f) > 0) obj.required("roughness").fail("must be 0 for a thin dielectric (its faces are smooth)");
    return makeThinDielectric(ior);
}

// A sheet passes on at most what arrives: reflectance + transmittance <= 1 per channel,
// checked where both are constant (a texture is checked texel by texel nowhere).
MaterialPtr readDiffuseTransmission(JsonObject& obj, LoadContext& ctx) {
    ColorParam reflectance = colorField(obj, "reflectance", Color(0.25f), ctx);
    ColorParam transmittance = colorField(obj, "transmittance", Color(0.25f), ctx);
    if (!reflectance.textured() && !transmittance.textured() &&
        maxComponent(reflectance.value + transmittance.value) > 1.0f + 1e-6f)
        obj.fail("reflectance + transmittance must not exceed 1 in any channel (a sheet cannot pass on more light than "
                 "arrives)");
    return makeDiffuseTransmission(reflectance, transmittance);
}

// {"type": "hair"}: the fibre's absorption from one of "sigma_a" (per diameter), "color"
// (the colour of a mass of such hair) or "eumelanin" and "pheomelanin" (eumelanin 1.3, brown
// hair, when none is given: pbrt-v4's default), and the model's roughnesses.
MaterialPtr readHair(JsonObject& obj) {
    HairParameters h;
    h.eta = obj.number("eta", 1.55f, Range::open(1, 4));
    h.betaM = obj.number("beta_m", 0.3f, Range::openClosed(0, 1));
    h.betaN = obj.number("beta_n", 0.3f, Range::openClosed(0, 1));
    h.alphaDegrees = obj.number("alpha", 2.0f, Range::closed(0, 45));
    auto sigmaA = obj.optional("sigma_a"), color = obj.optional("color");
    const bool melanin = obj.has("eumelanin") || obj.has("pheomelanin");
    if (int(bool(sigmaA)) + int(bool(color)) + int(melanin) > 1)
        obj.fail("give only one of \"sigma_a\", \"color\" or \"eumelanin\"/\"pheomelanin\"");
    if (sigmaA) {
        h.sigmaA = sigmaA->vec3(Range::nonNegative());
    } else if (color) {
        h.sigmaA = hairSigmaAFromReflectance(color->vec3(Range::openClosed(0, 1)), h.betaN);
    } else {
        const float eumelanin = obj.number("eumelanin", melanin ? 0.0f : 1.3f, Range::nonNegative());
        h.sigmaA = hairSigmaAFromMelanin(eumelanin, obj.number("pheomelanin", 0.0f, Range::nonNegative()));
    }
    return makeHair(h);
}

// {"type": "measured", "file": "x.bsdf"}: a measured BRDF in RGL's tensor files, read once
// per scene however many materials name it.
MaterialPtr readMeasured(JsonObject& obj, LoadContext& ctx) {
    const JsonValue file = obj.required("file");
    const std::filesystem::path path = resolveFile(file, ctx);
    std::shared_ptr<const MeasuredBrdf>& brdf = ctx.measuredBrdfs[path];
    if (!brdf) {
        try {
            brdf = readMeasuredBrdf(TensorFile::read(path.string(), file.string()));
        } catch (const std::runtime_error& e) {
            file.fail(e.what());
        }
    }
    return makeMeasured(brdf);
}

MaterialPtr readMaterial(const JsonValue& value, LoadContext& ctx, const std::vector<MaterialPtr>& defined);

// A part of a mix: the name of a material defined before it, or a material object.
MaterialPtr readMixPart(const JsonValue& value, LoadContext& ctx, const std::vector<MaterialPtr>& defined) {
    if (!value.json().is_string()) return readMaterial(value, ctx, defined);
    auto found = ctx.materialIndex.find(value.string());
    if (found == ctx.materialIndex.end() || found->second >= defined.size())
        value.fail("names no material defined before this one: \"" + value.string() + "\"");
    return defined[found->second];
}

// {"type": "mix", "materials": [a, b], "amount": t}: (1 - t) a + t b.
MaterialPtr readMix(JsonObject& obj, LoadContext& ctx, const std::vector<MaterialPtr>& defined) {
    JsonValue parts = obj.required("materials");
    std::vector<JsonValue> two = parts.elements();
    if (two.size() != 2) parts.fail("must name exactly 2 materials");
    MaterialPtr a = readMixPart(two[0], ctx, defined), b = readMixPart(two[1], ctx, defined);
    auto amount = obj.optional("amount");
    FloatParam t = amount ? readFloatParam(*amount, ctx, kFraction) : FloatParam(0.5f);
    try {
        return makeMix(std::move(a), std::move(b), std::move(t));
    } catch (const std::invalid_argument& e) {
        parts.fail(e.what());
    }
}

MaterialPtr readMaterial(const JsonValue& value, LoadContext& ctx, const std::vector<MaterialPtr>& defined) {
    JsonObject obj = value.object();
    enum Type {
        Diffuse, Dielectric, Mirror, Conductor, Plastic, CoatedDiffuse, CoatedConductor, DiffuseTransmission, Mix, Hair,
        Measured
    };
    auto type = Type(obj.required("type").choice({"diffuse", "dielectric", "mirror", "conductor", "plastic",
                                                  "coated_diffuse", "coated_conductor", "diffuse_transmission", "mix",
                                                  "hair", "measured"},
                                                 "type"));
    MaterialPtr m;
    switch (type) {
        case Diffuse: m = makeDiffuse(colorField(obj, "albedo", Color(0.8f), ctx)); break;
        case Dielectric: m = readDielectric(obj, ctx, type); break;
        case Mirror: m = makeMirror(colorField(obj, "reflectance", Color(1.0f), ctx)); break;
        case Conductor: m = readConductor(obj, ctx); break;
        case Plastic:
        case CoatedDiffuse: {
            ColorParam albedo = colorField(obj, "albedo", Color(0.5f), ctx);
            float ior = iorField(obj);
            auto make = type == Plastic ? makePlastic : makeCoatedDiffuse;
            m = withRoughness(obj, ctx, albedo, type, ior, [&](float r) { return make(albedo, ior, r); });
            break;
        }
        case CoatedConductor: m = readCoatedConductor(obj, ctx); break;
        case DiffuseTransmission: m = readDiffuseTransmission(obj, ctx); break;
        case Mix: m = readMix(obj, ctx, defined); break;
        case Hair: m = readHair(obj); break;
        case Measured: m = readMeasured(obj, ctx); break;
    }
    // Any material may bend its shading normal by a tangent-space map, read as stored, or
    // by a bump map's heights (scene units).
    if (type == Hair)
        for (const char* field : {"normal_map", "bump"})
            if (auto v = obj.optional(field)) v->fail("a hair fibre has no surface to bend the normal of");
    auto map = obj.optional("normal_map");
    if (map) m = makeNormalMapped(m, loadImage(*map, ImageChannels::Data, ctx));
    if (auto bump = obj.optional("bump")) {
        if (map) bump->fail("cannot be given with \"normal_map\"");
        m = makeBumpMapped(m, readFloatParam(*bump, ctx, Range::any()));
    }
    // An opaque material is seen alike from both sides unless "two_sided" is false; a
    // dielectric's or a translucent sheet's two sides differ already.
    if (auto sided = obj.optional("two_sided")) {
        if (!sided->boolean()) {
            if (type == Dielectric || !m->twoSided() || m->transmits()) sided->fail("must be true for a material that lets light through");
            m = makeOneSided(m);
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
        scene.materials.push_back(readMaterial(material, ctx, scene.materials));
        scene.materialNames.push_back(name);
    }
}

}  // namespace photon::scene_json
