// Entry points of the JSON scene format (docs/scene-format.md): the document as a whole,
// the files it names, and the checks that need more than one section.
#include <cerrno>
#include <cstring>
#include <fstream>
#include <sstream>
#include "scene/json_scene_parts.h"
#include "scene/scene_loader.h"
#include "scene/scene_paths.h"

namespace photon {

namespace fs = std::filesystem;

namespace scene_json {

const TriangleMesh* LoadContext::importedMesh(const std::string& relative) const {
    if (!imported) return nullptr;
    auto it = imported->meshes.find(relative);
    return it == imported->meshes.end() ? nullptr : &it->second;
}

const std::string* LoadContext::importedFile(const std::string& relative) const {
    if (!imported) return nullptr;
    auto it = imported->files.find(relative);
    return it == imported->files.end() ? nullptr : &it->second;
}

fs::path resolveFile(const JsonValue& value, const LoadContext& ctx) {
    const std::string& relative = value.string();
    if (auto why = checkRelativePath(relative)) value.fail(*why);
    fs::path full = ctx.baseDir / relative;
    // Held in memory by the importer: nothing on disk to check.
    if (ctx.importedMesh(relative) || ctx.importedFile(relative)) return full;
    std::error_code ec;
    if (!fs::exists(full, ec)) value.fail("file not found: " + relative);
    // The lexical checks above cannot see a symlink that leads out of the folder.
    if (!isInsideFolder(full, ctx.baseDir)) value.fail("must be a relative path inside the scene folder");
    if (!fs::is_regular_file(full, ec)) value.fail("not a regular file: " + relative);
    ctx.files.insert(fs::path(relative).lexically_normal().generic_string());
    return full;
}

void failWithLibraryError(const JsonValue& value, const std::exception& e, const LoadContext& ctx) {
    std::string message = e.what();
    // Libraries quote the full path; a scene (perhaps from a web upload) should only see
    // the names it wrote itself, not where the server keeps it.
    for (const fs::path& dir : {ctx.baseDir, fs::absolute(ctx.baseDir.empty() ? "." : ctx.baseDir)}) {
        std::string prefix = (dir / "").string();
        if (prefix.size() <= 1) continue;
        for (size_t at; (at = message.find(prefix)) != std::string::npos;) message.erase(at, prefix.size());
    }
    value.fail(message.empty() ? "cannot read file" : message);
}

namespace {

bool emits(const LightDescription& l) {
    switch (l.kind) {
        case LightDescription::Kind::Point:
            if (l.environment.image && !(l.environment.scale > 0 && !isBlack(l.environment.image->average()))) return false;
            return !isBlack(l.intensity);
        case LightDescription::Kind::Spot: return !isBlack(l.intensity);
        case LightDescription::Kind::Projection:
            return !isBlack(l.intensity) && l.environment.scale > 0 && !isBlack(l.environment.image->average());
        case LightDescription::Kind::Directional: return !isBlack(l.irradiance);
        case LightDescription::Kind::Environment:
            if (l.environment.image) return l.environment.scale > 0 && !isBlack(l.environment.image->average());
            return !isBlack(l.radiance);
    }
    return false;
}

// A homogeneous medium that emits sends its photons from the box around the shapes it is
// inside of (Scene::boxAroundShapesHolding): one that fills the space around the shapes (the
// camera's, their outside, a light's) has no such box. One that nothing names is left dark.
void checkEmittingMediaHaveAPlace(const SceneDescription& scene) {
    for (size_t i = 0; i < scene.media.size(); ++i) {
        const MediumDescription& m = scene.media[i];
        if (!m.emits() || m.emissionRegion()) continue;
        const int32_t index = int32_t(i);
        bool inside = false, around = scene.camera.medium == index;
        for (const ShapeDescription& s : scene.shapes) {
            if (!s.boundsMedium()) continue;
            inside = inside || s.insideMedium == index;
            around = around || s.outsideMedium == index;
        }
        for (const LightDescription& l : scene.lights) around = around || (l.medium == index && !inside);
        if (around && !inside)
            throw SceneError("media." + m.name + ".emission",
                             "a homogeneous medium that emits must lie inside shapes that bound it (its light leaves "
                             "from their box), or have a \"density\" or emission \"grid\" to say where it is");
    }
}

// Without any light the render is black by construction: almost certainly a mistake,
// and photon tracing would have no power to distribute.
void checkHasLight(const SceneDescription& scene) {
    for (const LightDescription& l : scene.lights)
        if (emits(l)) return;
    for (const ShapeDescription& s : scene.shapes)
        if (!isBlack(s.emission)) return;
    for (const InstanceDescription& instance : scene.instances)
        for (const ShapeDescription& s : scene.objects[instance.object].shapes)
            if (!isBlack(s.emission)) return;
    for (const MediumDescription& m : scene.media)
        if (m.emits()) return;
    throw SceneError("lights", "scene has no light (add a light, an emissive shape or a medium that emits)");
}

}  // namespace

}  // namespace scene_json

namespace {

SceneDescription loadSceneDocument(Json& doc, const fs::path& baseDir,
                                   const std::vector<SettingOverride>& overrides, const ImportedScene* imported) {
    using namespace scene_json;
    if (!doc.is_object()) throw SceneError("", "the scene must be a JSON object");
    applySettingOverrides(doc, overrides);
    JsonObject top(doc, "");
    LoadContext ctx;
    ctx.baseDir = baseDir;
    ctx.imported = imported;
    SceneDescription scene;
    // Media first: the camera, lights and shapes name the media they are in or bound.
    auto media = top.optional("media");
    if (media) readMedia(*media, ctx, scene);
    scene.camera = readCamera(top.required("camera"), ctx);
    // Materials before shapes: shapes refer to them by name.
    readMaterials(top.required("materials"), ctx, scene);
    // Objects before shapes: instances among the shapes refer to them by name.
    if (auto objects = top.optional("objects")) readObjects(*objects, ctx, scene);
    readShapes(top.required("shapes"), ctx, scene);
    if (auto lights = top.optional("lights")) readLights(*lights, ctx, scene);
    if (auto render = top.optional("render")) scene.render = readRender(*render);
    // Only the integrators that follow paths one by one carry the medium along them.
    if (media && !scene.media.empty() && scene.render.integrator != IntegratorKind::Sppm &&
        scene.render.integrator != IntegratorKind::Path)
        media->fail("media are rendered by the \"sppm\" and \"path\" integrators only");
    // Lightweight SPPM's camera paths (sppm_lightweight_camera_pass.cpp) cross media
    // unscattered: the light a medium scatters toward them would be missed.
    if (media && scene.render.lightweight &&
        std::any_of(scene.media.begin(), scene.media.end(), [](const MediumDescription& m) { return m.scatters(); }))
        media->fail("media that scatter are not rendered with \"render.lightweight\"");
    // So are curves: a fibre's frame runs along it (Material::alignsToTangent), which the
    // photon map's and radiosity's stored points do not keep.
    if (scene.render.integrator != IntegratorKind::Sppm && scene.render.integrator != IntegratorKind::Path) {
        auto refuseCurves = [](const std::vector<ShapeDescription>& shapes) {
            for (const ShapeDescription& s : shapes)
                if (s.kind == ShapeDescription::Kind::Curves)
                    throw SceneError(s.name, "curves are rendered by the \"sppm\" and \"path\" integrators only");
        };
        refuseCurves(scene.shapes);
        for (const ObjectDescription& o : scene.objects) refuseCurves(o.shapes);
    }
    top.finish();
    checkEmittingMediaHaveAPlace(scene);
    checkHasLight(scene);
    scene.files.assign(ctx.files.begin(), ctx.files.end());
    return scene;
}

}  // namespace

SceneDescription loadSceneJson(const std::string& text, const fs::path& baseDir,
                               const std::vector<SettingOverride>& overrides) {
    Json doc = parseJsonDocument(text);
    return loadSceneDocument(doc, baseDir, overrides, nullptr);
}

SceneDescription loadImportedScene(const ImportedScene& imported, const fs::path& baseDir,
                                   const std::vector<SettingOverride>& overrides) {
    // Through the document's text, as a converted scene's JSON would be read (numbers
    // rounded to float alike), so that the two render the same image.
    Json doc = parseJsonDocument(imported.document.dump());
    return loadSceneDocument(doc, baseDir, overrides, &imported);
}

SceneDescription loadSceneFile(const fs::path& file, const std::vector<SettingOverride>& overrides) {
    std::string prefix = "cannot read scene file \"" + file.string() + "\": ";
    std::error_code ec;
    if (fs::is_directory(file, ec)) throw SceneError("", prefix + "it is a directory");
    std::ifstream in(file, std::ios::binary);
    if (!in) throw SceneError("", prefix + std::strerror(errno));
    std::ostringstream text;
    text << in.rdbuf();
    if (in.bad()) throw SceneError("", prefix + std::strerror(errno));
    return loadSceneJson(text.str(), file.parent_path(), overrides);
}

}  // namespace photon
