// Internal to the glTF importer: the document being read, the scene being made of it, and
// what every part needs (errors and warnings at JSON pointers, node matrices).
#pragma once
#include <array>
#include <string>
#include <nlohmann/json.hpp>
#include <tiny_gltf.h>
#include "description/imported_scene.h"

namespace photon::gltf {

using Json = nlohmann::ordered_json;

// A 4x4 affine matrix applied to column vectors (x, y, z, 1), m[row][column]; doubles, as
// node chains multiply many of them.
struct Matrix4 {
    std::array<std::array<double, 4>, 4> m{};

    static Matrix4 identity();
    // glTF 2.0 sec. 3.5.3: a node's `matrix` (16 numbers, column-major) or T * R * S.
    static Matrix4 ofNode(const tinygltf::Node& node);
    Matrix4 operator*(const Matrix4& b) const;
    std::array<double, 3> point(double x, double y, double z) const;
    std::array<double, 3> direction(double x, double y, double z) const;
    double determinant3() const;  // of the upper-left 3x3
    // The 16 numbers row by row, as photon's {"matrix": [...]} takes them.
    Json rowMajor() const;
};

struct Context {
    const tinygltf::Model& model;
    std::string fileName;  // the file's name, first in every message
    ImportedScene& out;

    // A SceneError at "file: pointer" (the file alone for an empty pointer).
    [[noreturn]] void fail(const std::string& pointer, const std::string& message) const;
    void warn(const std::string& pointer, const std::string& message);
};

// "/name/index", the JSON pointer to an element of a top-level array.
// Appended piece by piece: GCC 12 warns falsely (-Wrestrict) about "/" + std::string&&.
inline std::string pointerTo(const char* array, int index) {
    std::string pointer = "/";
    pointer.append(array).append("/").append(std::to_string(index));
    return pointer;
}

// A number of an extension's object, or `fallback` when it is absent or not a number.
double numberIn(const tinygltf::Value& object, const char* key, double fallback);

}  // namespace photon::gltf
