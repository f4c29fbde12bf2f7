// The "objects" section: named groups of shapes, each built once and placed in the world
// by any number of {"type": "instance"} shapes.
#include "scene/json_scene_parts.h"

namespace photon::scene_json {

void readObjects(const JsonValue& value, LoadContext& ctx, SceneDescription& scene) {
    JsonObject objects = value.object();
    for (auto& [name, entry] : objects.members()) {
        JsonObject obj = entry.object();
        ObjectDescription object;
        object.name = name;
        const JsonValue shapes = obj.required("shapes");
        auto elements = shapes.elements();
        if (elements.empty()) shapes.fail("must contain at least one shape");
        for (const JsonValue& shape : elements) object.shapes.push_back(readShape(shape, ctx));
        obj.finish();
        ctx.objectIndex.emplace(name, static_cast<uint32_t>(scene.objects.size()));
        scene.objects.push_back(std::move(object));
    }
}

}  // namespace photon::scene_json
