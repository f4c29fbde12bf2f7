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
        {&Limits::maxClientBytes, "--max-client-bytes",
         "bytes of the scenes and assets of one remote address's queued and running jobs (429)", kBig},
        {&Limits::maxQueuedJobs, "--max-queued-jobs", "queued jobs, all clients (503)", kBig},
        {&Limits::maxHeaderBytes, "--max-header-bytes", "bytes of a request's line and header fields (414, 431)",
         16 << 20},
        {&Limits::maxHeaderFields, "--max-header-fields", "header fields of a request (431)", 10000},
        {&Limits::requestHeadSeconds, "--request-head-seconds",
         "seconds to send a whole request head (408), and before a body must keep up --min-body-rate", 3600},
        {&Limits::minBodyBytesPerSecond, "--min-body-rate",
         "bytes per second a request body must average after that grace, or its connection closes", kBig},
        {&Limits::maxConnectionsPerClient, "--max-connections-per-client",
         "open connections of one remote address; beyond, its oldest one without a request closes (503 if none)",
         100000},
        {&Limits::maxConnections, "--max-connections", "open connections, all clients (the same)", 100000},
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
    throw ServiceError(kind, what + " is " + std::to_string(value) + ", more than this server takes (" +
                                 std::to_string(limit) + "); its administrator sets that limit with " + option);
}

void checkLimit(ErrorKind kind, const std::string& what, int64_t value, const Limits& limits,
                int64_t Limits::*field) {
    checkLimit(kind, what, value, limits.*field, optionOf(field));
}

}  // namespace photon::server
