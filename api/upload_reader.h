// Reads the body of POST /api/v1/jobs into a staged upload. Two forms:
//   - the scene JSON itself (any content type but multipart);
//   - multipart/form-data with a part named "scene" (the scene JSON, or a .pbrt, .gltf or
//     .glb file by its file name's extension; its bytes kept as sent) and one file part per
//     asset, whose filename is the relative path the scene uses (e.g. "meshes/x.obj"), and
//     optionally text fields "name", "label" (repeated), "camera" and "lenient" for the job.
// Asset bytes stream straight to the staging folder; nothing large is held in memory. The
// scene text is held to its own limit, and every part (name, file name, bytes) feeds a
// digest that recognises a retried request.
#pragma once
#include <cstddef>
#include <optional>
#include <string>
#include <vector>
#include "server/idempotency.h"
#include "server/staged_upload.h"

namespace httplib {
class ContentReader;
struct Request;
struct Response;
}  // namespace httplib

namespace photon::api {

struct UploadLimits {
    size_t maxBodyBytes = 0;
    size_t maxSceneBytes = 0;
    size_t maxParts = 0;  // of a multipart upload: each asset part is a file staged on disk
};

// The form fields of a multipart upload besides the scene and its files.
struct UploadFields {
    std::optional<std::string> name;  // a "name" field
    std::vector<std::string> labels;  // each "label" field
    std::optional<std::string> camera;  // a "camera" field: an imported glTF's camera
    std::optional<std::string> lenient;  // a "lenient" field: "true" or "false"
    std::string sceneFileName;        // the scene part's file name, if it has one
};

// Throws ServiceError: BadRequest (bad multipart, unsafe names, unreadable body),
// PayloadTooLarge (body over maxBodyBytes, scene over maxSceneBytes), LimitExceeded (an
// asset over its limit).
UploadFields readUpload(const httplib::Request& req, httplib::Response& res, const httplib::ContentReader& reader,
                server::StagedUpload& upload, const UploadLimits& limits, server::RequestDigest& digest);

}  // namespace photon::api
