// What the pbrt importer's tests share: a scratch folder, scene files written into it, the
// header scene (a camera, an area light and a floor) and the import's result or error.
#pragma once
#include <unistd.h>
#include <filesystem>
#include <fstream>
#include <string>
#include <gtest/gtest.h>
#include <nlohmann/json.hpp>
#include <photon/errors.h>
#include "import/pbrt/pbrt_import.h"

namespace photon::test::pbrt_import {

namespace fs = std::filesystem;
using Json = nlohmann::ordered_json;

inline fs::path scratch() {
    static const fs::path dir = [] {
        fs::path d = fs::temp_directory_path() / ("photon-pbrt-import-" + std::to_string(getpid()));
        fs::remove_all(d);
        fs::create_directories(d);
        return d;
    }();
    return dir;
}

inline fs::path writeScene(const std::string& name, const std::string& text) {
    const fs::path file = scratch() / name;
    fs::create_directories(file.parent_path());
    std::ofstream(file) << text;
    return file;
}

// A camera looking down -z from (0, 1, 5) with a 2:1 film, an area light, a floor.
inline const std::string kHeader = R"(
LookAt 0 1 5  0 1 0  0 1 0
Camera "perspective" "float fov" [30]
Film "rgb" "integer xresolution" [64] "integer yresolution" [32] "string filename" "x.exr"
Sampler "halton" "integer pixelsamples" [4]
WorldBegin
AttributeBegin
  AreaLightSource "diffuse" "rgb L" [4 4 4]
  Shape "trianglemesh" "point3 P" [-0.5 2 -0.5  0.5 2 -0.5  0.5 2 0.5  -0.5 2 0.5] "integer indices" [0 1 2 0 2 3]
AttributeEnd
Shape "trianglemesh" "point3 P" [-5 0 -5  5 0 -5  5 0 5  -5 0 5] "integer indices" [0 2 1 0 3 2]
)";

// The header followed by `body`, imported.
inline ImportedScene import(const std::string& body, const std::string& name = "scene.pbrt") {
    return importPbrt(writeScene(name, kHeader + body));
}

// The SceneError importing `text` (as bad.pbrt) raises; a test failure if it imports.
inline SceneError importError(const std::string& text) {
    try {
        importPbrt(writeScene("bad.pbrt", text));
    } catch (const SceneError& e) {
        return e;
    }
    ADD_FAILURE() << "imported without error";
    return SceneError("?", "?");
}

inline Vec3 vec(const Json& j) { return {j[0].get<float>(), j[1].get<float>(), j[2].get<float>()}; }

}  // namespace photon::test::pbrt_import
