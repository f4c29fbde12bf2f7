// The fixture every server test uses: a fresh data directory, the real photon-server on an
// ephemeral port, an HTTP client, small scenes and helpers for jobs, events and images.
#pragma once
#include <gtest/gtest.h>
#include <httplib.h>
#include <chrono>
#include <filesystem>
#include <functional>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>
#include <photon/image.h>
#include "server_process.h"

namespace photon::test {

using nlohmann::json;

struct SseEvent {
    std::string type, id;
    json data;
};
std::vector<SseEvent> parseSse(const std::string& stream);

// The Cornell box (scenes/cornell-box.json) at a small size: fast enough for many tests.
json smallScene(int passes = 3, int64_t photonsPerPass = 2000, int resolution = 32);
// The same scene with passes enough to run for minutes: for cancel, delete and restart.
json longScene();

// Passes of `scene` (its integrator and settings) that take about `seconds` on this machine,
// measured in process (at least 20): a job that must still be running after some time lasts
// that long however many cores render it.
int passesLasting(double seconds, json scene);
// The same for smallScene(.., photonsPerPass, resolution).
int passesLasting(double seconds, int64_t photonsPerPass, int resolution);

// The image the engine renders in-process for the same scene: the server must serve exactly
// this (renders are deterministic for a seed).
Image renderInProcess(const json& scene);

// Decodes PNG or EXR bytes with OpenImageIO (through a temporary file).
Image decodeImage(const std::string& bytes, const std::string& extension);

// Sends `bytes` to the server on a new connection and returns all it answers until it closes
// the connection (or `timeoutSeconds` pass without a byte).
std::string rawExchange(int port, const std::string& bytes, int timeoutSeconds = 20);
// The RFC 9457 problem an error answer carries, checked for what every one must have:
// Content-Type application/problem+json, a type, a title, the answer's status, and a detail
// (also under "error", as earlier clients read it). From a whole raw HTTP answer, or a result.
json problemOf(const std::string& rawAnswer);
json problemOf(const httplib::Result& r);

// A new connection to the server on 127.0.0.1 (blocking), or -1.
int connectTo(int port);
// Reads until the peer closes or `timeoutSeconds` pass without a byte.
std::string readUntilClosed(int fd, int timeoutSeconds = 20);

class ServerTest : public ::testing::Test {
protected:
    void SetUp() override;
    void TearDown() override;

    // Starts photon-server on dataDir() with `args` (after --data DIR).
    void startServer(const std::vector<std::string>& args = {});
    int stopServer() { return server_.stop(); }
    void killServer() { server_.kill(); }

    httplib::Client client() const;
    httplib::Headers auth() const;
    void setToken(const std::string& token) { token_ = token; }

    // POST the scene as JSON; `query` like "?passes=5".
    httplib::Result submit(const json& scene, const std::string& query = "");
    // Submits and returns the new job's id, asserting 201.
    std::string submitOk(const json& scene, const std::string& query = "");
    json getJob(const std::string& id);
    // Polls until `done(job)` or the timeout; returns the last record.
    json waitFor(const std::string& id, const std::function<bool(const json&)>& done,
                 std::chrono::milliseconds timeout = std::chrono::seconds(20));
    json waitForStatus(const std::string& id, const std::string& status) {
        return waitFor(id, [&](const json& j) { return j["status"] == status; });
    }
    // Reads the job's event stream until the server ends it.
    std::vector<SseEvent> followEvents(const std::string& id, const httplib::Headers& extra = {});

    const std::filesystem::path& dataDir() const { return dataDir_; }
    int port() const { return server_.port(); }
    // The server process's resident memory (VmRSS), in bytes.
    int64_t serverMemoryBytes() const;

private:
    std::filesystem::path dataDir_;
    ServerProcess server_;
    std::string token_;
};

}  // namespace photon::test
