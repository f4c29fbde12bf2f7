#include "options.h"
#include <stdexcept>

namespace photon::server {

const char* const kUsage =
    "usage: photon-server [--host 127.0.0.1] [--port 8080] [--data DIR] [--workers N] [--token TOKEN]\n"
    "                     [--max-pixels N] [--max-passes N] [--max-photons N] [--max-body-bytes N]\n"
    "                     [--max-asset-bytes N] [--max-scene-bytes N] [--max-triangles N]\n"
    "                     [--max-texture-pixels N] [--max-streams N] [--max-jobs-per-client N]\n"
    "                     [--max-queued-jobs N] [--web-root DIR] [--checkpoint-seconds N] [--print-routes]\n"
    "limits (a request over one gets 413, 422, 429 or 503 naming it):\n"
    "  --max-pixels N           width*height of a job's image (default 16777216)\n"
    "  --max-passes N           passes of a job (default 100000)\n"
    "  --max-photons N          photons per pass (default 100000000)\n"
    "  --max-body-bytes N       request body (default 67108864)\n"
    "  --max-asset-bytes N      each uploaded asset file (default 67108864)\n"
    "  --max-scene-bytes N      the scene JSON (default 8388608)\n"
    "  --max-triangles N        triangles of all meshes of a scene (default 20000000)\n"
    "  --max-texture-pixels N   width*height of each uploaded texture image (default 67108864)\n"
    "  --max-streams N          open event and image streams, all clients (default 128, at most 192)\n"
    "  --max-jobs-per-client N  queued and running jobs of one remote address (default 100)\n"
    "  --max-queued-jobs N      queued jobs, all clients (default 1000)\n";

namespace {

long long parseInteger(const std::string& flag, const std::string& v, long long lo, long long hi) {
    try {
        size_t used = 0;
        long long n = std::stoll(v, &used);
        if (used == v.size() && n >= lo && n <= hi) return n;
    } catch (const std::exception&) {
    }
    throw std::invalid_argument(flag + ": expected an integer in [" + std::to_string(lo) + ", " + std::to_string(hi) +
                                "], got \"" + v + "\"");
}

}  // namespace

ServerOptions parseOptions(int argc, char** argv) {
    constexpr long long kBig = 1LL << 53;
    constexpr long long kMaxStreams = kMaxStreamsCap;
    ServerOptions o;
    Limits& limits = o.service.limits;
    for (int i = 1; i < argc; ++i) {
        std::string a = argv[i];
        auto value = [&]() -> std::string {
            if (i + 1 >= argc) throw std::invalid_argument(a + ": missing value");
            return argv[++i];
        };
        if (a == "--host") o.host = value();
        else if (a == "--port") o.port = int(parseInteger(a, value(), 0, 65535));
        else if (a == "--data") o.service.dataDir = value();
        else if (a == "--workers") o.service.workers = int(parseInteger(a, value(), 0, 256));
        else if (a == "--token") o.token = value();
        else if (a == "--max-pixels") limits.maxPixels = parseInteger(a, value(), 1, kBig);
        else if (a == "--max-passes") limits.maxPasses = parseInteger(a, value(), 1, kBig);
        else if (a == "--max-photons") limits.maxPhotonsPerPass = parseInteger(a, value(), 1, kBig);
        else if (a == "--max-body-bytes") limits.maxBodyBytes = size_t(parseInteger(a, value(), 1, kBig));
        else if (a == "--max-asset-bytes") limits.maxAssetBytes = size_t(parseInteger(a, value(), 1, kBig));
        else if (a == "--max-scene-bytes") limits.maxSceneBytes = size_t(parseInteger(a, value(), 1, kBig));
        else if (a == "--max-triangles") limits.maxTriangles = parseInteger(a, value(), 1, kBig);
        else if (a == "--max-texture-pixels") limits.maxTexturePixels = parseInteger(a, value(), 1, kBig);
        else if (a == "--max-streams") limits.maxStreams = int(parseInteger(a, value(), 1, kMaxStreams));
        else if (a == "--max-jobs-per-client") limits.maxJobsPerClient = parseInteger(a, value(), 1, kBig);
        else if (a == "--max-queued-jobs") limits.maxQueuedJobs = parseInteger(a, value(), 1, kBig);
        else if (a == "--web-root") o.webRoot = value();
        else if (a == "--checkpoint-seconds")
            o.service.checkpointSeconds = static_cast<double>(parseInteger(a, value(), 1, 86400));
        else if (a == "--print-routes") o.printRoutes = true;
        else throw std::invalid_argument("unknown argument " + a);
    }
    if (o.token.find_first_of(" \t\r\n") != std::string::npos)
        throw std::invalid_argument("--token: must not contain whitespace");
    return o;
}

}  // namespace photon::server
