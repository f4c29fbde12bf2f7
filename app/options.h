// The photon-server command line, declared once with CLI11: the parser and --help come from
// the same declarations (the limits from server/service_limits.h's table).
#pragma once
#include <string>
#include <vector>
#include "server/job_service.h"

namespace photon::app {

struct ServerOptions {
    std::string host = "127.0.0.1";  // loopback unless the operator opts in to more
    int port = 8080;                 // 0: any free port (the start line shows which)
    std::string token;               // non-empty: require "Authorization: Bearer <token>"
    std::string tokenFile;           // --token-file: where the token was read from
    // Static files for "/" if the folder exists: by default the page in the source tree.
    std::string webRoot = PHOTON_DEFAULT_WEB_ROOT;
    std::vector<std::string> allowedHosts;    // --allow-host
    std::vector<std::string> allowedOrigins;  // --allow-origin
    std::string logLevel = "info";   // spdlog level name: trace, debug, info, warn, error, off
    bool printRoutes = false;
    server::ServiceConfig service;
};

// Reads argv into `options`. Returns -1 to go on, or the code to exit with: 0 after --help,
// 2 after printing what is wrong and the usage.
int parseCommandLine(int argc, char** argv, ServerOptions& options);

}  // namespace photon::app
