// photon-server: the HTTP render service. Wires the job service (server/) to the HTTP
// front (api/), prints the address it listens on, and shuts down cleanly on SIGINT or
// SIGTERM: streams end, renders in flight are interrupted (and resume on the next start).
#include <pthread.h>
#include <spdlog/sinks/stdout_sinks.h>
#include <spdlog/spdlog.h>
#include <atomic>
#include <chrono>
#include <csignal>
#include <cstdio>
#include <cstring>
#include <thread>
#include "api/http_server.h"
#include "api/routes.h"
#include "app/options.h"

namespace {

using namespace photon;

void printRoutes() {
    for (const api::Route& r : api::routeTable()) std::printf("%s %s\n", r.method, r.path);
}

// Signals are taken by one thread with sigtimedwait instead of a handler: stopping the
// HTTP server and waking streams is not async-signal-safe.
sigset_t stopSignals() {
    sigset_t set;
    sigemptyset(&set);
    sigaddset(&set, SIGINT);
    sigaddset(&set, SIGTERM);
    return set;
}

// Log lines go to stderr (stdout carries only the start line, which scripts read), each with
// its time in UTC and level; requests are logged at info by the API's access log.
void setUpLogging(const std::string& level) {
    auto logger = spdlog::stderr_logger_mt("photon-server");
    logger->set_pattern("%Y-%m-%dT%H:%M:%S.%eZ %l %v", spdlog::pattern_time_type::utc);
    logger->set_level(spdlog::level::from_str(level));
    logger->flush_on(spdlog::level::info);
    spdlog::set_default_logger(std::move(logger));
}

int serve(const app::ServerOptions& options) {
    server::JobService service(options.service);
    const server::Limits& limits = options.service.limits;
    api::GuardLimits connections{{size_t(limits.maxHeaderBytes), size_t(limits.maxHeaderFields)},
                                 double(limits.requestHeadSeconds),
                                 limits.minBodyBytesPerSecond,
                                 limits.maxConnectionsPerClient,
                                 limits.maxConnections};
    api::HttpServer http(service, {options.token, options.webRoot, size_t(limits.maxBodyBytes), int(limits.maxStreams),
                                   options.allowedHosts, options.allowedOrigins, connections});
    int port = http.bind(options.host, options.port);
    if (port < 0) {
        spdlog::critical("cannot listen on {}:{}", options.host, options.port);
        return 1;
    }
    // IPv6 literals need brackets in a URL.
    std::string host = options.host.find(':') == std::string::npos ? options.host : "[" + options.host + "]";
    std::printf("photon-server listening on http://%s:%d/\n", host.c_str(), port);
    std::fflush(stdout);
    spdlog::info("listening on http://{}:{}/ with data in {}", host, port, options.service.dataDir.string());

    std::atomic<bool> stopped{false};
    std::thread signals([&] {
        sigset_t set = stopSignals();
        timespec poll{0, 200'000'000};
        while (!stopped) {
            if (sigtimedwait(&set, nullptr, &poll) < 0) continue;
            service.events().shutdown();  // end event streams first: they hold HTTP threads
            // ...and let them write their last chunk: stopping the server would cut it.
            if (!http.waitForStreams(std::chrono::seconds(2))) spdlog::warn("streams still open at shutdown");
            // stop() is a no-op until the listen loop runs; a signal can come before that.
            while (!http.running() && !stopped) std::this_thread::sleep_for(std::chrono::milliseconds(10));
            http.stop();
            break;
        }
    });
    bool ok = http.listen();
    stopped = true;
    signals.join();
    service.shutdown();
    return ok ? 0 : 1;
}

}  // namespace

int main(int argc, char** argv) {
    app::ServerOptions options;
    if (int exit = app::parseCommandLine(argc, argv, options); exit >= 0) return exit;
    if (options.printRoutes) {
        printRoutes();
        return 0;
    }
    setUpLogging(options.logLevel);
    // A client that disconnects mid-response must cost a failed write, not the process.
    std::signal(SIGPIPE, SIG_IGN);
    // Blocked before any thread starts, so every thread inherits the mask and only the
    // signal thread receives them.
    sigset_t set = stopSignals();
    pthread_sigmask(SIG_BLOCK, &set, nullptr);
    try {
        return serve(options);
    } catch (const std::exception& e) {
        spdlog::critical("{}", e.what());
        return 1;
    }
}
