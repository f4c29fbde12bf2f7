// What an importer makes of a scene in another format (pbrt-v4, glTF 2.0): the equivalent
// photon JSON scene, the meshes and files it names that exist only in memory, and what
// was approximated or left out. Rendering it goes through the JSON loader like any scene,
// so an imported scene and its converted JSON (photon-convert) are one scene.
#pragma once
#include <map>
#include <set>
#include <string>
#include <vector>
#include <nlohmann/json.hpp>
#include "description/scene_description.h"

namespace photon {

struct ImportedScene {
    // A photon JSON scene (docs/scene-format.md); its file names are relative to the
    // imported file's folder.
    nlohmann::ordered_json document;
    // Meshes the document names by "file" that are not on disk (a pbrt trianglemesh, a
    // glTF primitive): relative path ("meshes/3.ply") -> triangles, in the shape's own frame.
    // photon-convert writes them as binary PLY files under those names.
    std::map<std::string, TriangleMesh> meshes;
    // Those of `meshes` that are exactly a file on disk under the same name (a PLY file read
    // to check its orientation): photon-convert references them rather than writing them.
    std::set<std::string> meshesOnDisk;
    // Other files the document names that are not on disk (a glTF's embedded images):
    // relative path -> the file's bytes, written as they are by photon-convert.
    std::map<std::string, std::string> files;
    // What the importer approximated or ignored, each naming where (file:line, JSON pointer).
    std::vector<std::string> warnings;
};

}  // namespace photon
