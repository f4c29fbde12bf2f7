// "media": named homogeneous media that absorb and scatter, and a shape's "medium": the
// media on its two sides (docs/scene-format.md#media).
#include "scene/json_scene_parts.h"

namespace photon::scene_json {

void readMedia(const JsonValue& value, LoadContext& ctx, SceneDescription& scene) {
    JsonObject media = value.object();
    for (auto& [name, medium] : media.members()) {
        JsonObject obj = medium.object();
        MediumDescription m;
        m.name = name;
        // Per unit of scene length; the scale lets a file keep a measured colour's ratios.
        const float scale = obj.number("scale", 1.0f, Range::nonNegative());
        auto coefficient = [&](std::string_view key) {
            auto v = obj.optional(key);
            return v ? v->vec3(Range::nonNegative()) * scale : Color(0.0f);
        };
        if (!obj.has("absorption") && !obj.has("scattering"))
            medium.fail("a medium needs \"absorption\", \"scattering\" or both");
        m.absorption = coefficient("absorption");
        m.scattering = coefficient("scattering");
        if (auto g = obj.optional("g")) m.g = g->number(Range::open(-1.0f, 1.0f));
        obj.finish();
        ctx.mediumIndex[name] = int32_t(scene.media.size());
        scene.media.push_back(std::move(m));
    }
}

int32_t mediumNamed(const JsonValue& value, const LoadContext& ctx) {
    auto it = ctx.mediumIndex.find(value.string());
    if (it == ctx.mediumIndex.end()) value.fail("unknown medium \"" + value.string() + "\" (define it under \"media\")");
    return it->second;
}

void readShapeMedia(const JsonValue& value, const LoadContext& ctx, ShapeDescription& shape) {
    JsonObject obj = value.object();
    auto side = [&](std::string_view key) {
        auto v = obj.optional(key);
        return v ? mediumNamed(*v, ctx) : -1;
    };
    shape.insideMedium = side("inside");
    shape.outsideMedium = side("outside");
    obj.finish();
    if (!shape.boundsMedium()) value.fail("\"inside\" and \"outside\" are the same: the shape bounds no medium");
}

}  // namespace photon::scene_json
