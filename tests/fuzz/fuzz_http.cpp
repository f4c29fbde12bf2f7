// Fuzzes the HTTP API in process: raw request bytes go through the connection guard's request
// relay (api/request_relay.h: bounded heads, framing, re-serialisation), as the server gets
// them, then through httplib's own request parser
// and router (Server::process_request over an in-memory Stream, no socket) into the real
// route table (registerRoutes) backed by a JobService on a scratch data folder that renders
// nothing (0 workers). Bodies, multipart uploads, headers and query strings all reach the
// handlers exactly as from a client.
//
// An input may hold several pipelined requests. The text "{id}" in it stands for the id of
// a cancelled job that always exists, so the per-job routes (image, events, stream, cancel,
// delete) reach past their 404; the job is made again after an input deletes it. Jobs an
// input creates are deleted after it, so every input starts from the same state.
//
// Findings: sanitizer reports, crashes, and any 500 response (an exception the handlers did
// not expect).
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <httplib.h>
#include <memory>
#include "api/request_relay.h"
#include "api/routes.h"
#include "api/sessions.h"
#include "api/stream_support.h"
#include "fuzz_support.h"
#include "server/errors.h"
#include "server/job_service.h"

namespace {

constexpr int kMaxRequestsPerInput = 4;
// Stream responses end when their job does; this caps any that would not.
constexpr int kMaxBodyChunks = 16;
constexpr const char* kJobScene = R"({"camera": {"position": [0, 0, 5], "look_at": [0, 0, 0], "fov": 40,
  "resolution": [8, 8]}, "materials": {"d": {"type": "diffuse"}},
  "shapes": [{"type": "sphere", "center": [0, 0, 0], "radius": 1, "material": "d"}],
  "lights": [{"type": "point", "position": [0, 2, 0], "intensity": [1, 1, 1]}],
  "render": {"passes": 1, "photons_per_pass": 10}})";

// httplib's server loop for one connection, minus the socket. Content providers run only
// while the server looks alive (svr_sock_ valid); a stream that keeps writing is cut off.
class InProcessServer : public httplib::Server {
public:
    InProcessServer() { svr_sock_ = 0; }  // never listened on: stop() and ~Server ignore it

    // Returns false when the connection would close (bad request, EOF, Connection: close).
    bool serveOne(httplib::Stream& stream) {
        bool closed = false;
        return process_request(stream, false, closed, nullptr) && !closed;
    }
};

// Reads the input; what the server writes (the responses) is dropped.
class BufferStream final : public httplib::Stream {
public:
    explicit BufferStream(std::string input) : input_(std::move(input)) {}
    bool is_readable() const override { return true; }
    bool is_writable() const override { return ++bodyChunks_ <= kMaxBodyChunks; }
    ssize_t read(char* ptr, size_t size) override {
        size_t n = std::min(size, input_.size() - pos_);
        std::copy_n(input_.data() + pos_, n, ptr);
        pos_ += n;
        return ssize_t(n);
    }
    ssize_t write(const char* ptr, size_t size) override {
        return ssize_t(size);
    }
    void get_remote_ip_and_port(std::string& ip, int& port) const override {
        ip = "127.0.0.1";
        port = 40000;
    }
    void get_local_ip_and_port(std::string& ip, int& port) const override {
        ip = "127.0.0.1";
        port = 8080;
    }
    socket_t socket() const override { return INVALID_SOCKET; }

    bool atEnd() const { return pos_ == input_.size(); }

private:
    std::string input_;
    size_t pos_ = 0;
    mutable int bodyChunks_ = 0;
};

struct Harness {
    photon::server::JobService service;
    photon::api::StreamSlots streams{48};
    photon::api::SessionStore sessions;
    photon::api::RouteContext context{service, streams, sessions, true};
    InProcessServer server;
    std::string fixtureId;

    explicit Harness(const photon::server::ServiceConfig& config) : service(config) {
        server.set_payload_max_length(service.limits().maxBodyBytes);
        // A 500 means a handler met an exception it did not map to a client error.
        server.set_logger([](const httplib::Request& req, const httplib::Response& res) {
            if (res.status != 500) return;
            std::fprintf(stderr, "500 for %s %s: %s\n", req.method.c_str(), req.path.c_str(), res.body.c_str());
            std::abort();
        });
        photon::api::registerRoutes(server, context);
    }

    // The cancelled job "{id}" names; made again if an input deleted it.
    void ensureFixtureJob() {
        if (!fixtureId.empty()) {
            try {
                service.get(fixtureId);
                return;
            } catch (const photon::server::ServiceError&) {
            }
        }
        std::unique_ptr<photon::server::StagedUpload> upload = service.newUpload();
        upload->sceneText() = kJobScene;
        fixtureId = service.submit(*upload, {}).job.id;
        service.cancel(fixtureId);
    }

    // Deletes every job but the fixture (inputs create queued jobs; cancel first).
    void removeCreatedJobs() {
        for (const photon::server::JobRecord& job : service.list({}, 1000, 0).jobs) {
            if (job.id == fixtureId) continue;
            try {
                service.cancel(job.id);
            } catch (const photon::server::ServiceError&) {
            }
            service.remove(job.id);
        }
    }
};

Harness& harness() {
    static Harness* h = [] {
        photon::server::ServiceConfig config;
        config.dataDir = photon::fuzz::scratchDir("photon-fuzz-http");
        config.workers = 0;
        return new Harness(config);  // lives for the process: the JobService owns threads
    }();
    return *h;
}

std::string withFixtureId(std::string text, const std::string& id) {
    for (size_t at = text.find("{id}"); at != std::string::npos; at = text.find("{id}", at + id.size()))
        text.replace(at, 4, id);
    return text;
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
    Harness& h = harness();
    h.ensureFixtureJob();
    std::string forwarded;
    photon::api::RequestRelay relay({}, "127.0.0.1");
    std::string input = withFixtureId(std::string(reinterpret_cast<const char*>(data), size), h.fixtureId);
    for (size_t at = 0, taken = 1; at < input.size() && taken > 0 && !relay.refusal(); at += taken)
        taken = relay.feed(std::string_view(input).substr(at), forwarded);
    BufferStream stream(std::move(forwarded));
    for (int i = 0; i < kMaxRequestsPerInput && !stream.atEnd(); ++i)
        if (!h.server.serveOne(stream)) break;
    h.removeCreatedJobs();
    return 0;
}
