// The syntax of pbrt scene files (https://pbrt.org/fileformat-v4, and the pbrt-v3 files
// still in use): each directive with its positional values and typed parameters, Include
// and Import inlined, in file order. What the directives mean (graphics state, materials,
// shapes) is the semantic layer's business; this layer knows only each directive's shape
// and each parameter type's kind of value, and reports anything else with its file:line.
#pragma once
#include <cstddef>
#include <filesystem>
#include <functional>
#include <stdexcept>
#include <string>
#include <string_view>
#include <vector>

#include "import/pbrt/pbrt_tokenizer.h"  // Location, ParseError

namespace photon::pbrt {

// One parameter: "float fov" [45] -> type "float", name "fov", numbers {45}.
struct Param {
    // As written: "float", "integer", "rgb", "spectrum", "point3", "point2", "normal",
    // "normal3", "vector3", "point", "vector", "color", "string", "texture", "bool", "blackbody".
    std::string type;
    std::string name;
    std::vector<double> numbers;       // numeric values in order (bool params: empty)
    std::vector<std::string> strings;  // string values in order (string, texture, and spectrum given by name or file)
    std::vector<bool> bools;           // bool values (written true/false, bare or quoted "true")
    Location where;                    // the "type name" declaration
    mutable bool used = false;         // set by the semantic layer when it reads the param
};

struct Directive {
    std::string name;  // "Shape", "LookAt", "AttributeBegin", ...
    Location where;    // the directive's name
    // Positional numbers: LookAt 9, Translate 3, Scale 3, Rotate 4, Transform 16,
    // ConcatTransform 16, TransformTimes 2.
    std::vector<double> numbers;
    // Positional strings: Shape "sphere" -> {"sphere"}; Texture "name" "spectrum" "imagemap"
    // -> 3; MakeNamedMaterial, ObjectBegin, NamedMaterial, CoordinateSystem, ... -> 1;
    // ActiveTransform All -> {"All"}; MediumInterface "a" "b" -> 1 or 2.
    std::vector<std::string> strings;
    std::vector<Param> params;

    const Param* find(std::string_view name) const;  // first param with that name, or null
};

// Bounds on what a scene may make the parser read, so that no file can exhaust the stack
// (Include nesting) or the memory (files that include each other many times over).
struct ParseLimits {
    size_t maxIncludeDepth = 16;
    size_t maxFiles = 1000;
    size_t maxTotalBytes = 1ull << 31;
};

// Parses `file` and, in place, every file it Includes or Imports (both are inlined; paths
// relative to the including file's folder, must stay inside `root` -- the main file's
// folder -- after resolving "..", symlinks included; absolute paths refused), calling `sink`
// for each directive in file order. Include/Import directives themselves are not passed on.
// Throws ParseError (what(): "file:line: message") for any error, including one the sink
// throws as ParseError; other exceptions from the sink pass through unchanged.
void parseFile(const std::filesystem::path& file, const std::filesystem::path& root,
               const std::function<void(Directive&&)>& sink, const ParseLimits& limits = {});

// The same for text already in memory (`name` as it should appear in locations, and as the
// text's path relative to `root`, which its includes resolve against).
void parseText(std::string_view text, const std::string& name, const std::filesystem::path& root,
               const std::function<void(Directive&&)>& sink, const ParseLimits& limits = {});

}  // namespace photon::pbrt
