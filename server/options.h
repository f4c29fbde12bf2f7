// The photon-server command line.
#pragma once
#include <string>
#include "job_service.h"

namespace photon::server {

struct ServerOptions {
    std::string host = "127.0.0.1";  // loopback unless the operator opts in to more
    int port = 8080;                 // 0: any free port (the start line shows which)
    std::string token;               // non-empty: require "Authorization: Bearer <token>"
    // Static files for "/" if the folder exists: by default the page in the source tree.
    std::string webRoot = PHOTON_DEFAULT_WEB_ROOT;
    bool printRoutes = false;
    ServiceConfig service;
};

extern const char* const kUsage;

// Throws std::invalid_argument with a message for the user on bad arguments.
ServerOptions parseOptions(int argc, char** argv);

}  // namespace photon::server
