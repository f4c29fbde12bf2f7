#include "app/options.h"
#include <fstream>
#include "cli/option_checks.h"

namespace photon::app {

namespace {

std::string tokenCheck(const std::string& token) {
    if (token.empty()) return "must not be empty";
    return token.find_first_of(" \t\r\n") == std::string::npos ? "" : "must not contain whitespace";
}

// The token from --token-file: its first line, without the line end.
std::string readTokenFile(const std::string& file) {
    std::ifstream in(file);
    std::string line;
    if (!std::getline(in, line)) throw std::runtime_error("--token-file " + file + ": cannot read a line");
    if (!line.empty() && line.back() == '\r') line.pop_back();
    if (std::string problem = tokenCheck(line); !problem.empty())
        throw std::runtime_error("--token-file " + file + ": the token " + problem);
    return line;
}

void declareOptions(CLI::App& app, ServerOptions& o) {
    using cli::integerIn;
    app.add_option("--host", o.host, "address to listen on")->capture_default_str();
    app.add_option("--port", o.port, "port; 0 picks a free one")->type_name("N")->check(integerIn(0, 65535))->capture_default_str();
    app.add_option("--data", o.service.dataDir, "folder of the job store, scenes and images")->capture_default_str();
    app.add_option("--workers", o.service.workers,
                   "jobs rendered at once; 0 stores jobs without rendering (with --redis: render farm workers "
                   "run in this process; 0 renders nothing here)")
        ->type_name("N")->check(integerIn(0, 256))
        ->capture_default_str();
    CLI::Option* token =
        app.add_option("--token", o.token,
                       "require \"Authorization: Bearer TOKEN\" on every API request (seen by ps: prefer "
                       "--token-file or the PHOTON_TOKEN environment variable)")
            ->envname("PHOTON_TOKEN")
            ->check(tokenCheck);
    app.add_option("--token-file", o.tokenFile, "read the token from the first line of this file")
        ->check(CLI::ExistingFile)
        ->excludes(token);
    app.add_option("--web-root", o.webRoot, "folder of the page served at /")->capture_default_str();
    app.add_option("--allow-host", o.allowedHosts,
                   "another name (NAME or NAME:PORT) the server may be reached by, e.g. behind a reverse "
                   "proxy; repeatable (by default only the listening address, and loopback names when it "
                   "is a loopback address)")
        ->allow_extra_args(false);
    app.add_option("--allow-origin", o.allowedOrigins,
                   "a web origin (e.g. https://farm.example.com) whose pages may submit and change jobs; "
                   "repeatable (by default only the server's own page)")
        ->allow_extra_args(false);
    app.add_option("--checkpoint-seconds", o.service.checkpointSeconds, "seconds between a render's checkpoints")
        ->type_name("N")->check(integerIn(1, 86400))
        ->capture_default_str();
    app.add_option_function<std::string>(
           "--redis",
           [&o](const std::string& url) { o.service.redis = farm::RedisAddress::parse(url); },
           "render every job on the render farm at redis://HOST:PORT (photon-worker processes, and --workers "
           "of this process's own): jobs whose passes are independent (render.radius_schedule \"global\") in "
           "batches of passes, others whole")
        ->type_name("URL")
        ->check([](const std::string& url) {
            try {
                farm::RedisAddress::parse(url);
                return std::string();
            } catch (const std::invalid_argument& e) {
                return std::string(e.what());
            }
        });
    app.add_option("--farm-batch-passes", o.service.farmBatchPasses, "passes in one work item of the render farm")
        ->type_name("N")->check(integerIn(1, 100000))
        ->capture_default_str();
    app.add_option("--farm-jobs", o.service.farmJobs, "jobs on the render farm at once")
        ->type_name("N")->check(integerIn(1, 4096))
        ->capture_default_str();
    app.add_option("--log-level", o.logLevel, "trace, debug, info (each request), warn, error or off")
        ->check(CLI::IsMember({"trace", "debug", "info", "warn", "error", "off"}))
        ->capture_default_str();
    app.add_flag("--print-routes", o.printRoutes, "print the API's routes and exit");
    for (const server::LimitOption& limit : server::limitOptions()) {
        int64_t& value = o.service.limits.*limit.field;
        app.add_option(limit.option, value, limit.help)
            ->type_name("N")->check(integerIn(1, limit.max))
            ->group("Limits (a request over one is refused, naming it)")
            ->capture_default_str();
    }
}

}  // namespace

int parseCommandLine(int argc, char** argv, ServerOptions& options) {
    CLI::App app("The photon render service: REST API, job queue and the page.", "photon-server");
    declareOptions(app, options);
    if (int exit = cli::parseCommandLine(app, argc, argv); exit >= 0) return exit;
    try {
        if (!options.tokenFile.empty()) options.token = readTokenFile(options.tokenFile);
    } catch (const std::exception& e) {
        std::fprintf(stderr, "photon-server: %s\n", e.what());
        return 2;
    }
    return -1;
}

}  // namespace photon::app
