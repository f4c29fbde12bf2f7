// Settings overridden from outside the scene file (photon-render -D key=value), applied to
// the document before it is read, so that each value is checked and reported exactly as the
// scene's own would be.
#include <sstream>
#include "scene/json_scene_parts.h"

namespace photon::scene_json {

void applySettingOverrides(Json& doc, const std::vector<SettingOverride>& overrides) {
    for (const SettingOverride& o : overrides) {
        std::vector<std::string> keys;
        std::stringstream parts(o.key);
        for (std::string part; std::getline(parts, part, '.');) keys.push_back(part);
        const bool settings = !keys.empty() && (keys[0] == "render" || keys[0] == "camera");
        if (!settings || keys.size() < 2 || o.key.back() == '.')
            throw SceneError(o.key, "only render.* and camera.* settings can be overridden");
        Json* node = &doc;
        for (size_t i = 0; i + 1 < keys.size(); ++i) {
            if (keys[i].empty()) throw SceneError(o.key, "empty name in the setting's path");
            Json& next = (*node)[keys[i]];
            if (next.is_null()) next = Json::object();
            if (!next.is_object()) throw SceneError(o.key, keys[i] + " is not an object in the scene");
            node = &next;
        }
        // The value as JSON if it is JSON ("16", "[640, 480]", "true"), else as a string.
        Json value = Json::parse(o.value, nullptr, false);
        (*node)[keys.back()] = value.is_discarded() ? Json(o.value) : value;
    }
}

}  // namespace photon::scene_json
