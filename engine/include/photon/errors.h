// The errors the engine's face throws besides std::runtime_error (I/O, OpenImageIO).
#pragma once
#include <stdexcept>
#include <string>

namespace photon {

// Every problem with a scene: `path` is the JSON path of the offending value
// (e.g. "shapes[3].radius"), empty for problems with the document as a whole.
class SceneError : public std::runtime_error {
public:
    SceneError(std::string path, const std::string& message)
        : std::runtime_error(path.empty() ? message : path + ": " + message), path_(std::move(path)) {}
    const std::string& path() const { return path_; }

private:
    std::string path_;
};

// A checkpoint that cannot be used: not one, cut short or damaged, another version, or
// made for another scene's settings or image size. The render is then as before the call.
class CheckpointError : public std::runtime_error {
public:
    using std::runtime_error::runtime_error;
};

}  // namespace photon
