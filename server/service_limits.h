// What one client may ask of the server: keeps a single request from exhausting memory,
// disk or render time. Every limit is a command-line option; a request over one is refused
// with a message naming the value, the limit and that option. Each limit's default is
// written in Limits, its option, help and greatest value in limitOptions(), once.
#pragma once
#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>
#include "errors.h"

namespace photon::server {

struct Limits {
    int64_t maxPixels = 4096LL * 4096;
    int64_t maxPasses = 100000;
    int64_t maxPhotonsPerPass = 100000000;
    int64_t maxBodyBytes = 64 << 20;
    int64_t maxAssetBytes = 64 << 20;
    int64_t maxSceneBytes = 8 << 20;
    int64_t maxUploadParts = 1000;
    int64_t maxTriangles = 20'000'000;
    int64_t maxTexturePixels = 64LL << 20;
    int64_t maxStreams = 128;
    int64_t maxJobsPerClient = 100;
    int64_t maxClientBytes = 2LL << 30;
    int64_t maxQueuedJobs = 1000;
    // Of connections, before a request reaches a route (api/connection_guard.h).
    int64_t maxHeaderBytes = 64 << 10;
    int64_t maxHeaderFields = 100;
    int64_t requestHeadSeconds = 10;
    int64_t minBodyBytesPerSecond = 1024;
    int64_t maxConnectionsPerClient = 256;
    int64_t maxConnections = 4096;
};

// Each open stream holds one of the 256 HTTP threads: at least 64 stay for ordinary requests.
constexpr int kMaxStreamsCap = 192;

struct LimitOption {
    int64_t Limits::*field;
    const char* option;  // e.g. "--max-pixels"
    const char* help;    // what it bounds, and the HTTP status beyond it
    int64_t max;         // the most an operator may set it to
};
// Every limit, in the order --help lists them.
const std::vector<LimitOption>& limitOptions();
// The option that sets `field`, for messages: "--max-pixels" for &Limits::maxPixels.
const char* optionOf(int64_t Limits::*field);

// Throws ServiceError(kind) when value > limit, in words a submitter understands and naming
// the option for whoever runs the server: "<what> is <value>, more than this server takes
// (<limit>); its administrator sets that limit with <option>". `what` is a plain phrase,
// e.g. "the image's pixel count (width x height)".
void checkLimit(ErrorKind kind, const std::string& what, int64_t value, int64_t limit, const char* option);
// The same for a limit held in `limits`.
void checkLimit(ErrorKind kind, const std::string& what, int64_t value, const Limits& limits,
                int64_t Limits::*field);

}  // namespace photon::server
