// photon-convert: a pbrt-v4 or glTF 2.0 scene as photon's JSON scene, with the meshes and
// images the import made written beside it (docs/import.md).
//   photon-convert IN.pbrt|IN.gltf|IN.glb -o OUT.json [--camera NAME] [--overwrite] [--lenient]
#include <cstdio>
#include <string>
#include <CLI/CLI.hpp>
#include <photon/errors.h>
#include <photon/scene_convert.h>
#include "cli/option_checks.h"

int main(int argc, char** argv) {
    CLI::App app("Writes a pbrt-v4 or glTF 2.0 scene as photon's JSON scene.", "photon-convert");
    std::string input, output, camera;
    bool overwrite = false, lenient = false;
    app.add_option("scene", input, "the scene to convert: .pbrt, .gltf or .glb")->required()->check(CLI::ExistingFile);
    app.add_option("-o,--output", output, "the JSON scene to write (meshes and images go beside it)")->required();
    app.add_option("--camera", camera, "glTF: the camera to keep, by name (default: the first)");
    app.add_flag("--overwrite", overwrite, "replace files of the same names that hold something else");
    app.add_flag("--lenient", lenient, "pbrt: leave out or replace what photon cannot render (media that scatter, unknown materials, textures, shapes, lights), with a warning for each, instead of refusing the scene");
    if (int exit = photon::cli::parseCommandLine(app, argc, argv); exit >= 0) return exit;
    if (photon::sceneFormatOf(input) == photon::SceneFormat::Json) {
        std::fprintf(stderr, "photon-convert: %s: not a format to convert (.pbrt, .gltf, .glb)\n", input.c_str());
        return 2;
    }
    try {
        photon::ConversionReport report = photon::convertScene(input, output, {camera, lenient}, overwrite);
        for (const std::string& w : report.warnings) std::fprintf(stderr, "photon-convert: warning: %s\n", w.c_str());
        std::printf("wrote %s and %zu file(s) beside it\n", output.c_str(), report.written.size());
        return 0;
    } catch (const photon::SceneError& e) {
        std::fprintf(stderr, "photon-convert: %s: %s\n", input.c_str(), e.what());
    } catch (const std::exception& e) {
        std::fprintf(stderr, "photon-convert: %s\n", e.what());
    }
    return 1;
}
