// What one client may ask of the server: keeps a single request from exhausting memory,
// disk or render time. Every limit is a command-line option (options.cpp); a request over
// one is refused with a message naming the value, the limit and that option.
#pragma once
#include <cstddef>
#include <cstdint>
#include <string>
#include "errors.h"

namespace photon::server {

struct Limits {
    int64_t maxPixels = 4096LL * 4096;       // width * height
    int64_t maxPasses = 100000;
    int64_t maxPhotonsPerPass = 100000000;   // 10^8
    size_t maxBodyBytes = 64u << 20;         // whole request body (HTTP 413 beyond)
    size_t maxAssetBytes = 64u << 20;        // each uploaded asset file (HTTP 422 beyond)
    size_t maxSceneBytes = 8u << 20;         // the scene JSON itself (HTTP 413 beyond)
    int64_t maxTriangles = 20'000'000;       // all meshes of one scene together
    int64_t maxTexturePixels = 64LL << 20;   // width * height of each texture image
    int maxStreams = 128;                    // open event and image streams, all clients together
    int64_t maxJobsPerClient = 100;          // queued + running jobs of one remote address
    int64_t maxQueuedJobs = 1000;            // queued jobs, all clients together
};

// Each open stream holds one of the 256 HTTP threads: at least 64 stay for ordinary requests.
constexpr int kMaxStreamsCap = 192;

// Throws ServiceError(kind) "<what> <value> exceeds the server limit of <limit> (<option>)"
// when value > limit.
void checkLimit(ErrorKind kind, const std::string& what, int64_t value, int64_t limit, const char* option);

}  // namespace photon::server
