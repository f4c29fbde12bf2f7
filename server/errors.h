// Failures of service operations that a client caused or can act on. The API layer maps
// the kind to an HTTP status; the service itself knows nothing of HTTP.
#pragma once
#include <optional>
#include <stdexcept>
#include <string>

namespace photon::server {

enum class ErrorKind {
    BadRequest,       // malformed input, bad scene, unsafe asset name
    NotFound,         // no such job
    NotReady,         // the job exists but has nothing of that kind yet (no image); retry later
    Conflict,         // the job is in the wrong state for the operation
    PayloadTooLarge,  // the upload exceeds the body limit
    LimitExceeded,    // a well-formed request asks for more than the server allows
    Unavailable,      // the server is at capacity (open streams, a full queue) or its data
                      // directory is read-only; retry later
    TooManyRequests,  // this client has as many jobs waiting or running as it may
    StorageFull,      // the data directory's disk has no room for the upload or its records
};

class ServiceError : public std::runtime_error {
public:
    ServiceError(ErrorKind kind, const std::string& message, std::optional<std::string> scenePath = std::nullopt,
                 bool scenePathIsJson = true)
        : std::runtime_error(message), kind_(kind), scenePath_(std::move(scenePath)), scenePathIsJson_(scenePathIsJson) {}
    ErrorKind kind() const { return kind_; }
    // Where in the scene the error is, for scene errors: the JSON path of the offending
    // value (may be empty for problems with the document as a whole), or for an imported
    // file its own place ("scene.pbrt:12", "scene.gltf: /meshes/0"), not a JSON path.
    const std::optional<std::string>& scenePath() const { return scenePath_; }
    bool scenePathIsJson() const { return scenePathIsJson_; }

private:
    ErrorKind kind_;
    std::optional<std::string> scenePath_;
    bool scenePathIsJson_;
};

}  // namespace photon::server
