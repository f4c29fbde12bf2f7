#include "options.h"
#include <stdexcept>

namespace photon::server {

const char* const kUsage =
    "usage: photon-server [--host 127.0.0.1] [--port 8080] [--data DIR] [--workers N] [--token TOKEN]\n"
    "                     [--max-pixels N] [--max-passes N] [--max-photons N] [--max-body-bytes N]\n"
    "                     [--max-asset-bytes N] [--web-root DIR] [--checkpoint-seconds N] [--print-routes]\n";

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
