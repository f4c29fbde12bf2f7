// The "lights" section: point, spot, directional and environment lights (constant or an image).
#include "description/portal.h"
#include "scene/json_scene_parts.h"

namespace photon::scene_json {

namespace {

using Kind = LightDescription::Kind;

Color power(JsonObject& obj, std::string_view key) { return obj.required(key).vec3(Range::nonNegative()); }

// Angles are half-angles from the axis: full intensity inside falloff_angle, fading to
// zero at cone_angle.
void readSpotAngles(JsonObject& obj, LightDescription& l) {
    l.coneAngleDegrees = obj.number("cone_angle", 30, Range::openClosed(0, 90));
    // 5/6 of the cone (25 for the default 30) is valid for any cone angle.
    l.falloffAngleDegrees = l.coneAngleDegrees * 5.0f / 6.0f;
    if (auto falloff = obj.optional("falloff_angle")) {
        l.falloffAngleDegrees = falloff->number(Range::nonNegative());
        if (l.falloffAngleDegrees > l.coneAngleDegrees) falloff->fail("must be <= cone_angle");
    }
}

// An image over the sphere of directions, `image`, with its "layout", "scale" and "rotate" or
// "matrix" (the light's frame to the world): an environment's radiance or a point light's
// intensity profile (docs/scene-format.md).
void readDirectionImage(const JsonValue& image, JsonObject& obj, LoadContext& ctx, LightDescription& l) {
    LightDescription::EnvironmentImage& e = l.environment;
    e.image = loadImage(image, ImageChannels::Color, ctx);
    // In the order of EnvironmentLayout.
    e.layout = EnvironmentLayout(obj.choice("layout", 0, {"latlong", "equal_area"}, "layout"));
    if (e.layout == EnvironmentLayout::EqualArea && e.image->width() != e.image->height())
        image.fail("an equal-area image must be square, not " + std::to_string(e.image->width()) + "x" +
                    std::to_string(e.image->height()));
    e.scale = obj.number("scale", 1, Range::nonNegative());
    if (auto rotate = obj.optional("rotate")) e.toWorld = readRotation(*rotate);
    if (auto matrix = obj.optional("matrix")) {
        if (obj.has("rotate")) matrix->fail("give \"rotate\" or \"matrix\", not both");
        e.toWorld = readOrientation(*matrix);
    }
}

// Without an "image", the fields that go with one are refused.
void refuseImageFields(JsonObject& obj, std::initializer_list<std::string_view> keys) {
    for (std::string_view key : keys)
        if (auto v = obj.optional(key)) v->fail("is only allowed with \"image\"");
}

// A constant "radiance", or an "image" (readDirectionImage) and its "illuminance".
void readEnvironment(JsonObject& obj, LoadContext& ctx, LightDescription& l) {
    auto image = obj.optional("image");
    if (!image) {
        refuseImageFields(obj, {"layout", "scale", "rotate", "matrix", "illuminance"});
        l.radiance = power(obj, "radiance");
        return;
    }
    if (auto radiance = obj.optional("radiance")) radiance->fail("is not allowed with \"image\" (use \"scale\")");
    readDirectionImage(*image, obj, ctx, l);
    l.environment.illuminance = obj.number("illuminance", 0, Range::nonNegative());
}

// Four corners in order, a rectangle: the light comes in through it from the side of
// cross(p3 - p0, p1 - p0) (pbrt-v4's portal convention).
std::array<Vec3, 4> readPortal(const JsonValue& value) {
    const std::vector<JsonValue> corners = value.elements();
    if (corners.size() != 4) value.fail("must be 4 corners, not " + std::to_string(corners.size()));
    std::array<Vec3, 4> q;
    for (size_t i = 0; i < 4; ++i) q[i] = corners[i].vec3();
    if (auto problem = portalProblem(q)) value.fail(*problem);
    return q;
}

LightDescription readLight(const JsonValue& value, LoadContext& ctx) {
    JsonObject obj = value.object();
    LightDescription l;
    // In the order of LightDescription::Kind.
    l.kind = Kind(obj.required("type").choice({"point", "spot", "directional", "environment", "projection"}, "type"));
    // A point or spot light may sit in an absorbing medium, where its photons start.
    if (l.kind == Kind::Point || l.kind == Kind::Spot || l.kind == Kind::Projection)
        if (auto medium = obj.optional("medium")) l.medium = mediumNamed(*medium, ctx);
    switch (l.kind) {
        case Kind::Point:
            l.position = obj.required("position").vec3();
            l.intensity = power(obj, "intensity");
            // An intensity profile: the intensity times the image's texel toward each direction.
            if (auto image = obj.optional("image")) readDirectionImage(*image, obj, ctx, l);
            else refuseImageFields(obj, {"layout", "scale", "rotate", "matrix"});
            break;
        case Kind::Spot:
            l.position = obj.required("position").vec3();
            l.direction = obj.required("direction").direction();
            l.intensity = power(obj, "intensity");
            readSpotAngles(obj, l);
            break;
        case Kind::Directional:
            l.direction = obj.required("direction").direction();
            l.irradiance = power(obj, "irradiance");
            break;
        case Kind::Projection:
            l.position = obj.required("position").vec3();
            l.intensity = power(obj, "intensity");
            l.projectionFovDegrees = obj.number("fov", 90, Range::open(0, 180));
            if (auto layout = obj.optional("layout")) layout->fail("does not apply to a projection (its image lies flat)");
            readDirectionImage(obj.required("image"), obj, ctx, l);
            break;
        case Kind::Environment:
            readEnvironment(obj, ctx, l);
            if (auto portal = obj.optional("portal")) l.portal = readPortal(*portal);
            break;
    }
    obj.finish();
    return l;
}

}  // namespace

// Environment lights add up: rays that leave the scene see their sum (a scene lit through
// two windows has one behind each, each with its portal).
void readLights(const JsonValue& value, LoadContext& ctx, SceneDescription& scene) {
    for (const JsonValue& light : value.elements()) scene.lights.push_back(readLight(light, ctx));
}

}  // namespace photon::scene_json
