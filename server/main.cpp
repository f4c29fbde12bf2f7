// photon-server: the HTTP render service. Wires the job service (server/) to the HTTP
// front (api/), prints the address it listens on, and shuts down cleanly on SIGINT or
// SIGTERM: streams end, renders in flight are interrupted (and resume on the next start).
#include <pthread.h>
#include <atomic>
#include <chrono>
#include <csignal>
#include <cstdio>
#include <cstring>
#include <thread>
#include "api/http_server.h"
#include "api/routes.h"
#include "options.h"

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

int serve(const server::ServerOptions& options) {
    server::JobService service(options.service);
    const server::Limits& limits = options.service.limits;
    api::HttpServer http(service, {options.token, options.webRoot, limits.maxBodyBytes, limits.maxStreams});
    int port = http.bind(options.host, options.port);
    if (port < 0) {
        std::fprintf(stderr, "photon-server: cannot listen on %s:%d\n", options.host.c_str(), options.port);
        return 1;
    }
    // IPv6 literals need brackets in a URL.
    std::string host = options.host.find(':') == std::string::npos ? options.host : "[" + options.host + "]";
    std::printf("photon-server listening on http://%s:%d/\n", host.c_str(), port);
    std::fflush(stdout);

    std::atomic<bool> stopped{false};
    std::thread signals([&] {
        sigset_t set = stopSignals();
        timespec poll{0, 200'000'000};
        while (!stopped) {
            if (sigtimedwait(&set, nullptr, &poll) < 0) continue;
            service.events().shutdown();  // end event streams first: they hold HTTP threads
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
    for (int i = 1; i < argc; ++i)
        if (!std::strcmp(argv[i], "-h") || !std::strcmp(argv[i], "--help")) {
            std::fputs(server::kUsage, stdout);
            return 0;
        }
    server::ServerOptions options;
    try {
        options = server::parseOptions(argc, argv);
    } catch (const std::exception& e) {
        std::fprintf(stderr, "photon-server: %s\n%s", e.what(), server::kUsage);
        return 2;
    }
    if (options.printRoutes) {
        printRoutes();
        return 0;
    }
    // A client that disconnects mid-response must cost a failed write, not the process.
    std::signal(SIGPIPE, SIG_IGN);
    // Blocked before any thread starts, so every thread inherits the mask and only the
    // signal thread receives them.
    sigset_t set = stopSignals();
    pthread_sigmask(SIG_BLOCK, &set, nullptr);
    try {
        return serve(options);
    } catch (const std::exception& e) {
        std::fprintf(stderr, "photon-server: %s\n", e.what());
        return 1;
    }
}
