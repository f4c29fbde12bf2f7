// Writing an imported scene (pbrt-v4, glTF 2.0) as photon's own JSON scene, so that what
// was imported can be read, edited and rendered as any scene (docs/import.md).
#pragma once
#include <filesystem>
#include <string>
#include <vector>
#include <photon/scene_file.h>

namespace photon {

struct ConversionReport {
    std::vector<std::string> warnings;  // the importer's, as SceneFile::warnings
    std::vector<std::string> written;   // files written besides the JSON, relative to its folder
};

// Imports `input` and writes its photon JSON scene to `output`. Meshes the import made
// (a pbrt trianglemesh, a glTF primitive) are written beside it as binary PLY files, and
// images it held in memory (a .glb's) as they were; the document names them by relative
// path, never inlines them. If `output` is in another folder than `input`, the files the
// scene names there (PLY meshes, textures) are copied along. An existing file is never
// overwritten with other contents unless `overwrite`. Throws SceneError for the scene and
// std::runtime_error for the files.
ConversionReport convertScene(const std::filesystem::path& input, const std::filesystem::path& output,
                              const ImportOptions& options = {}, bool overwrite = false);

}  // namespace photon
