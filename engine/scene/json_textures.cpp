// Colour and float parameters that take a constant or a texture: images (with a uv
// scale and offset, or mapped from the point), checkerboards (2D or solid), bilinear
// blends, products and mixes, nested as deep as a scene likes.
// The grammar is in docs/scene-format.md ("Textures").
#include "scene/json_scene_parts.h"
#include "texture/image_texture.h"
#include "texture/textures.h"

namespace photon::scene_json {

namespace {

// What a parameter's constants may be, and how an image's channels are read for it.
struct ParamKind {
    bool color;              // [r, g, b] constants (else numbers)
    Range range;             // every constant inside it
    ImageChannels channels;  // images: colour or alpha
};

UvMapping readUvMapping(JsonObject& obj) {
    UvMapping m;
    if (auto s = obj.optional("uv_scale")) m.scale = s->vec2(Range::any());
    if (auto o = obj.optional("uv_offset")) m.offset = o->vec2(Range::any());
    if (auto r = obj.optional("uv_rotation")) m.rotation = r->number(Range::closed(-360, 360)) * kPi / 180.0f;
    return m;
}

// "mapping": {"type": "spherical" | "cylindrical" | "planar" | "uv", "transform": T,
// planar's "s" and "t" axes}: where the texture's (s, t) come from, T placing the
// texture's space in the world (its inverse takes hit points there); then the uv_* fields.
TextureMapping readMapping(JsonObject& obj) {
    TextureMapping m(readUvMapping(obj));
    auto value = obj.optional("mapping");
    if (!value) return m;
    JsonObject mapping = value->object();
    constexpr TextureMapping::Kind kKinds[] = {TextureMapping::Kind::Uv, TextureMapping::Kind::Spherical,
                                               TextureMapping::Kind::Cylindrical, TextureMapping::Kind::Planar};
    m.kind = kKinds[mapping.required("type").choice({"uv", "spherical", "cylindrical", "planar"}, "mapping type")];
    if (m.kind != TextureMapping::Kind::Uv)
        if (auto t = mapping.optional("transform")) m.textureFromWorld = readTransform(*t).inverse();
    if (m.kind == TextureMapping::Kind::Planar) {
        if (auto s = mapping.optional("s")) m.planarS = s->vec3();
        if (auto t = mapping.optional("t")) m.planarT = t->vec3();
    }
    mapping.finish();
    return m;
}

// A solid texture's "mapping": {"type": "solid", "transform": T}: the texture's space
// placed in the world by T (the identity without it); returns T's inverse.
Transform readSolidMapping(JsonObject& obj) {
    for (const char* key : {"uv_scale", "uv_offset", "uv_rotation"})
        if (auto given = obj.optional(key)) given->fail("a solid texture is read at the point, not at uv");
    JsonObject mapping = obj.required("mapping").object();
    mapping.required("type").choice({"solid"}, "mapping type");
    Transform textureFromWorld;
    if (auto t = mapping.optional("transform")) textureFromWorld = readTransform(*t).inverse();
    mapping.finish();
    return textureFromWorld;
}

// A solid texture's optional "mapping" ({"type": "solid", "transform": T}); the identity
// without one.
Transform readOptionalSolidMapping(JsonObject& obj) {
    return obj.has("mapping") || obj.has("uv_scale") || obj.has("uv_offset") || obj.has("uv_rotation")
               ? readSolidMapping(obj)
               : Transform();
}

// Whether the texture's "mapping" is {"type": "solid", ...}.
bool solidMapping(JsonObject& obj) {
    auto mapping = obj.optional("mapping");
    if (!mapping) return false;
    const auto& m = mapping->json();
    return m.is_object() && m.contains("type") && m.at("type") == "solid";
}

ColorParam readParam(const JsonValue& value, LoadContext& ctx, const ParamKind& kind);

// An image's "channel": "r", "g", "b" or "a" reads that one channel, as stored (data such as
// a glTF's packed roughness and metallic); without it, what the parameter reads (`kind`).
ImageChannels readChannels(JsonObject& obj, const ParamKind& kind) {
    auto channel = obj.optional("channel");
    if (!channel) return kind.channels;
    constexpr ImageChannels kChannels[] = {ImageChannels::R, ImageChannels::G, ImageChannels::B, ImageChannels::A};
    return kChannels[channel->choice({"r", "g", "b", "a"}, "channel")];
}

// {"texture": file} or {"type": "image", "file": file}, with a uv mapping and a channel.
// "wrap": "repeat" (the default), "clamp" or "black" outside the unit square; "invert": true
// reads max(0, 1 - value).
// "encoding": "linear" reads an integer image's colour as stored instead of through the
// sRGB curve, "gamma" with "gamma": g as stored to the power g (pbrt-v4's imagemap
// "encoding"); a single channel is read as stored unless "srgb" or "gamma" is given for it.
// A float image is linear.
std::shared_ptr<const Texture> readImage(JsonObject& obj, const char* fileKey, LoadContext& ctx, const ParamKind& kind) {
    ImageChannels channels = readChannels(obj, kind);
    ImageEncoding encoding;
    enum Given { Srgb, Linear, Gamma, None };
    switch (Given(obj.choice("encoding", None, {"srgb", "linear", "gamma"}, "encoding"))) {
        case Srgb: encoding.kind = ImageEncoding::Srgb; break;
        case Linear:
            if (channels == ImageChannels::Color) channels = ImageChannels::Data;
            break;
        case Gamma: encoding = {ImageEncoding::Gamma, obj.required("gamma").number(Range::open(0, 10))}; break;
        case None: break;
    }
    if (encoding.kind != ImageEncoding::Gamma)
        if (auto g = obj.optional("gamma")) g->fail("needs \"encoding\": \"gamma\"");
    auto image = loadImage(obj.required(fileKey), channels, ctx, encoding);
    constexpr ImageWrap kWraps[] = {ImageWrap::Repeat, ImageWrap::Clamp, ImageWrap::Black};
    const ImageWrap wrap = kWraps[obj.choice("wrap", 0, {"repeat", "clamp", "black"}, "wrap")];
    const bool invert = obj.boolean("invert", false);
    return makeMappedTexture(makeImageLookupTexture(std::move(image), wrap, invert), readMapping(obj));
}

std::shared_ptr<const Texture> readTexture(JsonObject& obj, LoadContext& ctx, const ParamKind& kind) {
    if (!obj.has("type")) return readImage(obj, "texture", ctx, kind);  // {"texture": "file.png"}
    enum Type { Image, Checkerboard, Bilerp, Dots, Fbm, Wrinkled, Windy, Marble, Product, Mix, DirectionMix };
    const Type type = Type(obj.required("type").choice(
        {"image", "checkerboard", "bilerp", "dots", "fbm", "wrinkled", "windy", "marble", "product", "mix", "direction_mix"}, "texture type"));
    switch (type) {
        case Image: return readImage(obj, "file", ctx, kind);
        case Checkerboard: {
            ColorParam even = readParam(obj.required("even"), ctx, kind);
            ColorParam odd = readParam(obj.required("odd"), ctx, kind);
            if (solidMapping(obj)) return makeSolidCheckerboardTexture(std::move(even), std::move(odd), readSolidMapping(obj));
            return makeCheckerboardTexture(std::move(even), std::move(odd), readMapping(obj));
        }
        case Bilerp: {
            ColorParam v00 = readParam(obj.required("v00"), ctx, kind);
            ColorParam v01 = readParam(obj.required("v01"), ctx, kind);
            ColorParam v10 = readParam(obj.required("v10"), ctx, kind);
            ColorParam v11 = readParam(obj.required("v11"), ctx, kind);
            return makeBilerpTexture(std::move(v00), std::move(v01), std::move(v10), std::move(v11), readMapping(obj));
        }
        case Dots: {
            ColorParam inside = readParam(obj.required("inside"), ctx, kind);
            ColorParam outside = readParam(obj.required("outside"), ctx, kind);
            return makeDotsTexture(std::move(inside), std::move(outside), readMapping(obj));
        }
        case Fbm:
        case Wrinkled: {
            const int octaves = int(obj.integer("octaves", 8, 1, 30));
            const float roughness = obj.number("roughness", 0.5f, Range::closed(0, 1));
            const Transform textureFromWorld = readOptionalSolidMapping(obj);
            return type == Fbm ? makeFbmTexture(textureFromWorld, octaves, roughness)
                               : makeWrinkledTexture(textureFromWorld, octaves, roughness);
        }
        case Windy: return makeWindyTexture(readOptionalSolidMapping(obj));
        case Marble: {
            const int octaves = int(obj.integer("octaves", 8, 1, 30));
            const float roughness = obj.number("roughness", 0.5f, Range::closed(0, 1));
            const float scale = obj.number("scale", 1.0f, Range::positive());
            const float variation = obj.number("variation", 0.2f, Range::nonNegative());
            return makeMarbleTexture(readOptionalSolidMapping(obj), octaves, roughness, scale, variation);
        }
        case Product: {
            ColorParam a = readParam(obj.required("a"), ctx, kind);
            ColorParam b = readParam(obj.required("b"), ctx, kind);
            return makeProductTexture(std::move(a), std::move(b));
        }
        case Mix: {
            ColorParam a = readParam(obj.required("a"), ctx, kind);
            ColorParam b = readParam(obj.required("b"), ctx, kind);
            FloatParam amount = readFloatParam(obj.required("amount"), ctx, Range::closed(0, 1));
            return makeMixTexture(std::move(a), std::move(b), std::move(amount));
        }
        case DirectionMix: {
            ColorParam along = readParam(obj.required("along"), ctx, kind);
            ColorParam across = readParam(obj.required("across"), ctx, kind);
            return makeDirectionMixTexture(std::move(along), std::move(across), obj.required("direction").direction());
        }
    }
    return nullptr;  // unreachable: choice() accepts only the names above
}

ColorParam readParam(const JsonValue& value, LoadContext& ctx, const ParamKind& kind) {
    if (value.json().is_object()) {
        JsonObject obj = value.object();
        auto texture = readTexture(obj, ctx, kind);
        obj.finish();
        return ColorParam(std::move(texture));
    }
    if (kind.color) {
        if (!value.json().is_array()) value.fail("must be an array of 3 numbers or a texture object");
        return ColorParam(value.vec3(kind.range));
    }
    if (!value.json().is_number()) value.fail("must be a number or a texture object");
    return ColorParam(Color(value.number(kind.range)));
}

}  // namespace

std::shared_ptr<const ImageTexture> loadImage(const JsonValue& value, ImageChannels channels, LoadContext& ctx,
                                              ImageEncoding encoding) {
    std::filesystem::path file = resolveFile(value, ctx);
    auto key = std::make_tuple(file, channels, encoding);
    auto cached = ctx.textures.find(key);
    if (cached != ctx.textures.end()) return cached->second;
    try {
        return ctx.textures[key] = ImageTexture::load(file, channels, ctx.importedFile(value.string()), encoding);
    } catch (const std::exception& e) {
        failWithLibraryError(value, e, ctx);
    }
}

ColorParam readColorParam(const JsonValue& value, LoadContext& ctx, const Range& range) {
    return readParam(value, ctx, {true, range, ImageChannels::Color});
}

FloatParam readFloatParam(const JsonValue& value, LoadContext& ctx, const Range& range, ImageChannels channels) {
    ColorParam p = readParam(value, ctx, {false, range, channels});
    return p.textured() ? FloatParam(p.texture) : FloatParam(p.value.x);
}

}  // namespace photon::scene_json
