// The "lights" section: point, spot, directional and environment lights.
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

LightDescription readLight(const JsonValue& value) {
    JsonObject obj = value.object();
    LightDescription l;
    // In the order of LightDescription::Kind.
    l.kind = Kind(obj.required("type").choice({"point", "spot", "directional", "environment"}, "type"));
    switch (l.kind) {
        case Kind::Point:
            l.position = obj.required("position").vec3();
            l.intensity = power(obj, "intensity");
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
        case Kind::Environment: l.radiance = power(obj, "radiance"); break;
    }
    obj.finish();
    return l;
}

}  // namespace

void readLights(const JsonValue& value, SceneDescription& scene) {
    bool haveEnvironment = false;
    for (const JsonValue& light : value.elements()) {
        scene.lights.push_back(readLight(light));
        if (scene.lights.back().kind != Kind::Environment) continue;
        // The environment is what rays that leave the scene see: there is only one.
        if (haveEnvironment) light.fail("only one environment light is allowed");
        haveEnvironment = true;
    }
}

}  // namespace photon::scene_json
