#include <photon/scene_file.h>
#include "import/scene_import.h"
#include "scene/scene_loader.h"

namespace photon {

SceneFile SceneFile::parseJson(const std::string& text, const std::filesystem::path& baseDir,
                               const std::vector<SettingOverride>& overrides) {
    return SceneFile(loadSceneJson(text, baseDir, overrides));
}
SceneFile SceneFile::read(const std::filesystem::path& file, const std::vector<SettingOverride>& overrides,
                          const ImportOptions& options) {
    if (sceneFormatOf(file) == SceneFormat::Json) return SceneFile(loadSceneFile(file, overrides));
    ImportedScene imported = importSceneFile(file, options);
    const std::filesystem::path folder = file.parent_path().empty() ? std::filesystem::path(".") : file.parent_path();
    SceneFile scene(loadImportedScene(imported, folder, overrides));
    scene.warnings_ = std::move(imported.warnings);
    return scene;
}

SceneFile::SceneFile(SceneDescription description)
    : description_(std::make_unique<SceneDescription>(std::move(description))) {}
SceneFile::SceneFile(SceneFile&&) noexcept = default;
SceneFile& SceneFile::operator=(SceneFile&&) noexcept = default;
SceneFile::~SceneFile() = default;

RenderSettings& SceneFile::render() { return description_->render; }
const RenderSettings& SceneFile::render() const { return description_->render; }
int SceneFile::width() const { return description_->camera.width; }
int SceneFile::height() const { return description_->camera.height; }

int64_t SceneFile::triangleCount() const {
    int64_t total = 0;
    auto add = [&](const std::vector<ShapeDescription>& shapes) {
        for (const ShapeDescription& shape : shapes) {
            if (shape.kind == ShapeDescription::Kind::Mesh) total += int64_t(shape.mesh.triangleCount());
            if (shape.kind == ShapeDescription::Kind::Curves) total += int64_t(shape.curves.segmentCount());
        }
    };
    add(description_->shapes);
    for (const ObjectDescription& object : description_->objects) add(object.shapes);
    return total;
}

const std::vector<std::string>& SceneFile::files() const { return description_->files; }

std::vector<std::string> SceneFile::methodWarnings() const {
    const SceneDescription& d = *description_;
    if (d.render.integrator != IntegratorKind::Radiosity) return {};
    std::vector<bool> used(d.materials.size(), false);
    auto mark = [&](const std::vector<ShapeDescription>& shapes) {
        for (const ShapeDescription& shape : shapes)
            if (shape.material < used.size()) used[shape.material] = true;
    };
    mark(d.shapes);
    for (const ObjectDescription& object : d.objects) mark(object.shapes);
    std::string names;
    int count = 0;
    for (size_t i = 0; i < d.materials.size(); ++i)
        if (used[i] && !d.materials[i]->hasDiffuse()) {
            names += (names.empty() ? "\"" : ", \"") +
                     (i < d.materialNames.size() ? d.materialNames[i] : "material " + std::to_string(i)) + "\"";
            ++count;
        }
    if (count == 0) return {};
    // docs/radiosity.md: patches exist only where a surface reflects diffusely.
    return {"radiosity renders diffuse interreflection only: the material" + std::string(count > 1 ? "s " : " ") +
            names + (count > 1 ? " have" : " has") +
            " no diffuse part, so the light they reflect or refract (caustics, mirror images) is missing and their "
            "shapes cast full shadows; the sppm, path or photonmap integrator renders it"};
}

}  // namespace photon
