// Internal to the JSON scene loader: one reader per top-level section, each in its own
// file (json_settings.cpp, json_materials.cpp, json_shapes.cpp, json_transform.cpp,
// json_lights.cpp), sharing the load context defined here.
#pragma once
#include <filesystem>
#include <map>
#include <memory>
#include <optional>
#include <set>
#include <string>
#include <tuple>
#include <unordered_map>
#include <vector>
#include <photon/scene_file.h>
#include "math/transform.h"
#include "materials/measured_brdf.h"
#include "texture/color_param.h"
#include "texture/float_param.h"
#include "texture/image_texture.h"
#include "scene/json_reader.h"
#include "description/scene_description.h"
#include "description/imported_scene.h"

namespace photon::scene_json {

struct LoadContext {
    std::filesystem::path baseDir;  // files resolve against it; empty: the working directory
    // Images by resolved path and the channels read, so parameters sharing an image share
    // one copy (the scene's texture cache).
    std::map<std::tuple<std::filesystem::path, ImageChannels, ImageEncoding>, std::shared_ptr<const ImageTexture>> textures;
    // Material name -> index, for shapes that refer to materials by name.
    std::unordered_map<std::string, uint32_t> materialIndex;
    // Roughness ladders by material family and index, shared by textured roughnesses.
    std::map<std::pair<int, float>, std::shared_ptr<const RoughnessLevels>> roughnessLevels;
    // Measured BRDFs by resolved path, read once however many materials name them.
    std::map<std::filesystem::path, std::shared_ptr<const MeasuredBrdf>> measuredBrdfs;
    // Medium name -> index, for shapes' "medium".
    std::unordered_map<std::string, int32_t> mediumIndex;
    // Object name -> index, for instances.
    std::unordered_map<std::string, uint32_t> objectIndex;
    // Every file resolveFile was asked for, relative and in normal form: a record of what was
    // read, kept as the context is passed along read-only.
    mutable std::set<std::string> files;
    // An imported scene's meshes and files held in memory, found by the names the document
    // gives them before the disk is looked at (null: a scene read from disk alone).
    const ImportedScene* imported = nullptr;
    const TriangleMesh* importedMesh(const std::string& relative) const;
    const std::string* importedFile(const std::string& relative) const;
};

// A file named by the string `value`: relative, without "..", inside the scene folder
// (symlinks resolved) and existing. Errors are SceneErrors at value's path.
std::filesystem::path resolveFile(const JsonValue& value, const LoadContext& ctx);
// The image file named by the string `value` (through resolveFile), its `channels` read once
// per scene however often it is named (json_textures.cpp), decoded by `encoding`.
std::shared_ptr<const ImageTexture> loadImage(const JsonValue& value, ImageChannels channels, LoadContext& ctx,
                                              ImageEncoding encoding = {});
// Rethrows a library failure (Assimp, OpenImageIO) as a SceneError at value's path, with
// the scene folder removed from the message so only the scene's own names show.
[[noreturn]] void failWithLibraryError(const JsonValue& value, const std::exception& e, const LoadContext& ctx);

// Sets each override's key (a dotted path under "render" or "camera") in the document,
// creating the objects on the way; throws SceneError at the key for any other key.
void applySettingOverrides(Json& doc, const std::vector<SettingOverride>& overrides);

// A colour parameter: [r, g, b] inside `range`, or a texture object (json_textures.cpp).
ColorParam readColorParam(const JsonValue& value, LoadContext& ctx, const Range& range);
// A float parameter: a number inside `range`, or a texture object whose images are read
// for `channels` (alpha for cutouts).
FloatParam readFloatParam(const JsonValue& value, LoadContext& ctx, const Range& range,
                          ImageChannels channels = ImageChannels::Color);

// The camera; its "medium" names one of the media read before it.
CameraDescription readCamera(const JsonValue& value, const LoadContext& ctx);
RenderSettings readRender(const JsonValue& value);
void readMaterials(const JsonValue& value, LoadContext& ctx, SceneDescription& scene);
// The world's shapes and instances of objects ("shapes").
void readShapes(const JsonValue& value, LoadContext& ctx, SceneDescription& scene);
// One shape that is not an instance, in the frame its transform is relative to.
ShapeDescription readShape(const JsonValue& value, LoadContext& ctx);
// The strands, basis and profile of a "curves" shape (json_curves.cpp).
CurveSet readCurves(JsonObject& obj, LoadContext& ctx);
// Named groups of shapes that instances place ("objects", json_objects.cpp).
void readObjects(const JsonValue& value, LoadContext& ctx, SceneDescription& scene);
void readLights(const JsonValue& value, LoadContext& ctx, SceneDescription& scene);
// "media" (json_media.cpp), and a shape's "medium" {"inside", "outside"}.
void readMedia(const JsonValue& value, LoadContext& ctx, SceneDescription& scene);
void readShapeMedia(const JsonValue& value, const LoadContext& ctx, ShapeDescription& shape);
// The index of the medium the string `value` names.
int32_t mediumNamed(const JsonValue& value, const LoadContext& ctx);

// {"axis": [x, y, z], "angle": degrees}: a rotation about the axis (right-handed).
Transform readRotation(const JsonValue& value);
// 16 numbers, row-major, whose linear part is a rotation or a mirror image and whose
// translation is 0: an environment's frame.
Transform readOrientation(const JsonValue& value);
// {"scale", "rotate", "translate"} or {"matrix"}; the result is invertible.
Transform readTransform(const JsonValue& value);

}  // namespace photon::scene_json
