#include "service_limits.h"

namespace photon::server {

const std::vector<LimitOption>& limitOptions() {
    constexpr int64_t kBig = int64_t(1) << 53;
    static const std::vector<LimitOption> options{
        {&Limits::maxPixels, "--max-pixels", "width*height of a job's image (413)", kBig},
        {&Limits::maxPasses, "--max-passes", "passes of a job (413)", kBig},
        {&Limits::maxPhotonsPerPass, "--max-photons", "photons per pass (413)", kBig},
        {&Limits::maxBodyBytes, "--max-body-bytes", "request body bytes (413)", kBig},
        {&Limits::maxAssetBytes, "--max-asset-bytes", "bytes of each uploaded asset file (422)", kBig},
        {&Limits::maxSceneBytes, "--max-scene-bytes", "bytes of the scene JSON (413)", kBig},
        {&Limits::maxUploadParts, "--max-upload-parts", "parts of a multipart upload, the scene's included (413)",
         1'000'000},
        {&Limits::maxTriangles, "--max-triangles", "triangles of all meshes of a scene (413)", kBig},
        {&Limits::maxTexturePixels, "--max-texture-pixels", "width*height of each uploaded texture image (413)",
         kBig},
        {&Limits::maxStreams, "--max-streams", "open event and image streams, all clients (503)", kMaxStreamsCap},
        {&Limits::maxJobsPerClient, "--max-jobs-per-client", "queued and running jobs of one remote address (429)",
         kBig},
        {&Limits::maxQueuedJobs, "--max-queued-jobs", "queued jobs, all clients (503)", kBig},
    };
    return options;
}

const char* optionOf(int64_t Limits::*field) {
    for (const LimitOption& o : limitOptions())
        if (o.field == field) return o.option;
    return "";
}

void checkLimit(ErrorKind kind, const std::string& what, int64_t value, int64_t limit, const char* option) {
    if (value <= limit) return;
    throw ServiceError(kind, what + " " + std::to_string(value) + " exceeds the server limit of " +
                                 std::to_string(limit) + " (" + option + ")");
}

void checkLimit(ErrorKind kind, const std::string& what, int64_t value, const Limits& limits,
                int64_t Limits::*field) {
    checkLimit(kind, what, value, limits.*field, optionOf(field));
}

}  // namespace photon::server
