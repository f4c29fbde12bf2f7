// Cameras (glTF 2.0 sec. 3.10) and KHR_lights_punctual lights, placed by their nodes.
// Both look or shine along their node's -Z, with +Y up (sec. 3.10.1; the extension's
// "Adding Light Instances to Nodes").
#include <cmath>
#include <numbers>
#include "import/gltf/gltf_parts.h"

namespace photon::gltf {
namespace {

Json vec(const std::array<double, 3>& v) { return {v[0], v[1], v[2]}; }

std::array<double, 3> normalised(std::array<double, 3> v) {
    const double n = std::sqrt(v[0] * v[0] + v[1] * v[1] + v[2] * v[2]);
    return {v[0] / n, v[1] / n, v[2] / n};
}

double degrees(double radians) { return radians * 180.0 / std::numbers::pi; }

}  // namespace

Json cameraJson(Context& ctx, int node, const Matrix4& toWorld) {
    const int index = ctx.model.nodes[node].camera;
    if (index < 0 || size_t(index) >= ctx.model.cameras.size())
        ctx.fail(pointerTo("nodes", node) + "/camera", "names camera " + std::to_string(index) + ", which does not exist");
    const tinygltf::Camera& camera = ctx.model.cameras[index];
    const std::string pointer = pointerTo("cameras", index);
    const bool orthographic = camera.type == "orthographic";
    if (camera.type != "perspective" && !orthographic)
        ctx.fail(pointer + "/type", "\"" + camera.type + "\" cameras are not supported (photon's cameras are perspective or orthographic)");
    const double yfov = camera.perspective.yfov, xmag = camera.orthographic.xmag, ymag = camera.orthographic.ymag;
    if (!orthographic && !(yfov > 0 && yfov < std::numbers::pi)) ctx.fail(pointer + "/perspective/yfov", "must be in (0, pi)");
    if (orthographic && !(xmag > 0 && ymag > 0))
        ctx.fail(pointer + "/orthographic", "xmag and ymag must be > 0 for photon (the view's half width and height)");
    // Without an aspect ratio glTF leaves it to the viewport; photon's default viewport is
    // 1280 x 720. With one (an orthographic camera's xmag / ymag): 720 rows and as many
    // columns as it asks for.
    int width = 1280, height = 720;
    if (const double aspect = orthographic ? xmag / ymag : camera.perspective.aspectRatio; aspect > 0)
        width = int(std::clamp(std::lround(720 * aspect), 1L, 16384L));
    const auto position = toWorld.point(0, 0, 0);
    const auto forward = normalised(toWorld.direction(0, 0, -1));
    const auto up = normalised(toWorld.direction(0, 1, 0));
    if (!std::isfinite(forward[0] + forward[1] + forward[2]) || !std::isfinite(up[0] + up[1] + up[2]))
        ctx.fail(pointerTo("nodes", node), "the camera's node matrix is degenerate");
    Json cam = {{"type", orthographic ? "orthographic" : "perspective"},
                {"position", vec(position)},
                {"look_at", vec({position[0] + forward[0], position[1] + forward[1], position[2] + forward[2]})},
                {"up", vec(up)}};
    if (orthographic) cam["view_height"] = 2 * ymag;
    else cam["fov"] = degrees(yfov);
    cam["resolution"] = {width, height};
    return cam;
}

Json lightJson(Context& ctx, int index, int node, const Matrix4& toWorld) {
    if (index < 0 || size_t(index) >= ctx.model.lights.size())
        ctx.fail(pointerTo("nodes", node) + "/extensions/KHR_lights_punctual/light",
                 "names light " + std::to_string(index) + ", which does not exist");
    const tinygltf::Light& light = ctx.model.lights[index];
    const std::string pointer = "/extensions/KHR_lights_punctual/lights/" + std::to_string(index);
    if (light.range > 0) ctx.warn(pointer + "/range", "ignored: photon's lights fall off with the inverse square alone");
    // photon takes the extension's photometric values (cd, lux) as its radiometric units one
    // to one, as it does glTF's emission (docs/import-gltf.md, "Units").
    Json power = Json::array();
    for (int c = 0; c < 3; ++c)
        power.push_back(std::max(light.color.size() == 3 ? light.color[c] : 1.0, 0.0) * std::max(light.intensity, 0.0));
    const auto direction = normalised(toWorld.direction(0, 0, -1));
    if (light.type == "directional") return {{"type", "directional"}, {"direction", vec(direction)}, {"irradiance", power}};
    const Json position = vec(toWorld.point(0, 0, 0));
    if (light.type == "point") return {{"type", "point"}, {"position", position}, {"intensity", power}};
    if (light.type != "spot") ctx.fail(pointer + "/type", "unknown light type \"" + light.type + "\"");
    const double outer = std::clamp(degrees(light.spot.outerConeAngle), 1e-3, 90.0);
    const double inner = std::clamp(degrees(light.spot.innerConeAngle), 0.0, outer);
    return {{"type", "spot"},     {"position", position},    {"direction", vec(direction)},
            {"intensity", power}, {"cone_angle", outer}, {"falloff_angle", inner}};
}

}  // namespace photon::gltf
