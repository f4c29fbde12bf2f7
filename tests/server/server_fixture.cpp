#include "server_fixture.h"
#include <photon/render.h>
#include <arpa/inet.h>
#include <netinet/in.h>
#include <sys/socket.h>
#include <unistd.h>
#include <algorithm>
#include <cmath>
#include <fstream>
#include <mutex>
#include <sstream>
#include <thread>
#include <photon/image_io.h>

namespace photon::test {

namespace fs = std::filesystem;

namespace {

fs::path makeTempDir(const std::string& prefix) {
    std::string pattern = (fs::temp_directory_path() / (prefix + "XXXXXX")).string();
    if (!::mkdtemp(pattern.data())) throw std::runtime_error("mkdtemp failed");
    return pattern;
}

json readJsonFile(const fs::path& file) {
    std::ifstream in(file);
    return json::parse(in);
}

}  // namespace

std::vector<SseEvent> parseSse(const std::string& stream) {
    std::vector<SseEvent> events;
    std::istringstream in(stream);
    std::string line;
    SseEvent current;
    std::string data;
    while (std::getline(in, line)) {
        if (line.empty()) {
            if (!current.type.empty() || !data.empty()) {
                current.data = data.empty() ? json() : json::parse(data);
                events.push_back(current);
            }
            current = SseEvent{};
            data.clear();
        } else if (line.rfind("event: ", 0) == 0) current.type = line.substr(7);
        else if (line.rfind("id: ", 0) == 0) current.id = line.substr(4);
        else if (line.rfind("data: ", 0) == 0) data += line.substr(6);
    }
    return events;
}

json smallScene(int passes, int64_t photonsPerPass, int resolution) {
    json scene = readJsonFile(fs::path(PHOTON_SOURCE_DIR) / "scenes" / "cornell-box.json");
    scene["camera"]["resolution"] = {resolution, resolution};
    scene["render"]["passes"] = passes;
    scene["render"]["photons_per_pass"] = photonsPerPass;
    // Every pass traces photonsPerPass: the tests count photons and time passes by it.
    scene["render"]["adaptive_photons"] = false;
    scene["render"]["seed"] = 7;
    return scene;
}

json longScene() { return smallScene(50000, 20000, 48); }

int passesLasting(double seconds, int64_t photonsPerPass, int resolution) {
    return passesLasting(seconds, smallScene(4, photonsPerPass, resolution));
}

int passesLasting(double seconds, json scene) {
    scene["render"]["passes"] = 4;
    Renderer renderer(SceneFile::parseJson(scene.dump(), PHOTON_SOURCE_DIR));
    CancelToken cancel;
    renderer.renderPass(cancel);  // the first pass also builds caches
    auto start = std::chrono::steady_clock::now();
    for (int i = 0; i < 3; ++i) renderer.renderPass(cancel);
    double pass = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count() / 3;
    return int(std::clamp(std::ceil(seconds / pass), 20.0, 100000.0));
}

Image renderInProcess(const json& scene) {
    Renderer renderer(SceneFile::parseJson(scene.dump(), PHOTON_SOURCE_DIR));
    CancelToken cancel;
    EXPECT_EQ(renderer.run(cancel), RenderOutcome::Completed);
    return renderer.snapshot();
}

Image decodeImage(const std::string& bytes, const std::string& extension) {
    fs::path dir = makeTempDir("photon-image-");
    fs::path file = dir / ("image." + extension);
    {
        std::ofstream out(file, std::ios::binary);
        out.write(bytes.data(), std::streamsize(bytes.size()));
    }
    Image image = readImage(file);
    fs::remove_all(dir);
    return image;
}

namespace {

json checkedProblem(int status, const std::string& contentType, const std::string& body) {
    EXPECT_EQ(contentType, "application/problem+json") << body;
    json problem = json::parse(body, nullptr, false);
    EXPECT_TRUE(problem.is_object()) << body;
    if (!problem.is_object()) return json::object();
    EXPECT_TRUE(problem["type"].is_string()) << body;
    EXPECT_TRUE(problem["title"].is_string()) << body;
    EXPECT_EQ(problem["status"], status) << body;
    EXPECT_TRUE(problem["detail"].is_string()) << body;
    EXPECT_EQ(problem["error"], problem["detail"]) << body;
    return problem;
}

}  // namespace

json problemOf(const std::string& answer) {
    size_t headEnd = answer.find("\r\n\r\n");
    EXPECT_NE(headEnd, std::string::npos) << answer;
    if (headEnd == std::string::npos) return json::object();
    int status = std::atoi(answer.substr(9, 3).c_str());
    std::string contentType;
    const std::string field = "\r\nContent-Type: ";
    if (size_t at = answer.find(field); at < headEnd)
        contentType = answer.substr(at + field.size(), answer.find("\r\n", at + field.size()) - at - field.size());
    return checkedProblem(status, contentType, answer.substr(headEnd + 4));
}

json problemOf(const httplib::Result& r) {
    EXPECT_TRUE(r);
    if (!r) return json::object();
    return checkedProblem(r->status, r->get_header_value("Content-Type"), r->body);
}

int connectTo(int port) {
    int fd = ::socket(AF_INET, SOCK_STREAM, 0);
    sockaddr_in addr{};
    addr.sin_family = AF_INET;
    addr.sin_port = htons(uint16_t(port));
    addr.sin_addr.s_addr = htonl(INADDR_LOOPBACK);
    if (fd >= 0 && ::connect(fd, reinterpret_cast<sockaddr*>(&addr), sizeof addr) == 0) return fd;
    if (fd >= 0) ::close(fd);
    return -1;
}

std::string readUntilClosed(int fd, int timeoutSeconds) {
    timeval timeout{timeoutSeconds, 0};
    ::setsockopt(fd, SOL_SOCKET, SO_RCVTIMEO, &timeout, sizeof timeout);
    std::string answer;
    char buffer[4096];
    for (ssize_t n; (n = ::recv(fd, buffer, sizeof buffer, 0)) > 0;) answer.append(buffer, size_t(n));
    return answer;
}

std::string rawExchange(int port, const std::string& bytes, int timeoutSeconds) {
    int fd = connectTo(port);
    std::string answer;
    if (fd >= 0 && ::send(fd, bytes.data(), bytes.size(), MSG_NOSIGNAL) == ssize_t(bytes.size()))
        answer = readUntilClosed(fd, timeoutSeconds);
    if (fd >= 0) ::close(fd);
    return answer;
}

int64_t ServerTest::serverMemoryBytes() const {
    std::ifstream status("/proc/" + std::to_string(server_.pid()) + "/status");
    for (std::string line; std::getline(status, line);)
        if (line.rfind("VmRSS:", 0) == 0) return std::stoll(line.substr(6)) * 1024;  // in kB
    return -1;
}

void ServerTest::SetUp() { dataDir_ = makeTempDir("photon-server-test-"); }

void ServerTest::TearDown() {
    server_.stop();
    std::error_code ignored;
    fs::remove_all(dataDir_, ignored);
}

void ServerTest::startServer(const std::vector<std::string>& args) {
    std::vector<std::string> all{"--data", dataDir_.string()};
    all.insert(all.end(), args.begin(), args.end());
    server_.start(all);
}

namespace {

// Every answer the tests' HTTP clients get, one JSON line each, when PHOTON_API_RESPONSE_LOG
// names a folder: tests/web/openapi.test.mjs then checks each against api/openapi.yaml (its
// route, status, content type and body schema). One file per test, rewritten when it runs.
class ResponseLog {
public:
    static ResponseLog& instance() {
        static ResponseLog log;
        return log;
    }
    void record(const httplib::Request& req, const httplib::Response& res) {
        if (!enabled_) return;
        std::string contentType = res.get_header_value("Content-Type");
        json line{{"method", req.method},
                  {"path", req.path.substr(0, req.path.find('?'))},
                  {"status", res.status},
                  {"content_type", contentType}};
        // Bodies the schemas describe: JSON. Streams arrive in pieces and are not kept.
        if (contentType.find("json") != std::string::npos && !res.body.empty()) line["body"] = res.body;
        std::lock_guard lock(mutex_);
        if (!out_.is_open()) {
            const ::testing::TestInfo* test = ::testing::UnitTest::GetInstance()->current_test_info();
            std::string name = test ? std::string(test->test_suite_name()) + "." + test->name() : "outside-tests";
            fs::create_directories(folder_);
            out_.open(folder_ / (name + ".jsonl"), std::ios::trunc);
        }
        out_ << line.dump(-1, ' ', false, json::error_handler_t::replace) << "\n" << std::flush;
    }

private:
    ResponseLog() {
        const char* folder = std::getenv("PHOTON_API_RESPONSE_LOG");
        enabled_ = folder && *folder;
        if (enabled_) folder_ = folder;
    }
    bool enabled_ = false;
    fs::path folder_;
    std::mutex mutex_;
    std::ofstream out_;
};

}  // namespace

httplib::Client ServerTest::client() const {
    httplib::Client c("127.0.0.1", server_.port());
    c.set_read_timeout(std::chrono::seconds(30));
    c.set_default_headers(auth());
    c.set_logger([](const httplib::Request& req, const httplib::Response& res) {
        ResponseLog::instance().record(req, res);
    });
    return c;
}

httplib::Headers ServerTest::auth() const {
    if (token_.empty()) return {};
    return {{"Authorization", "Bearer " + token_}};
}

httplib::Result ServerTest::submit(const json& scene, const std::string& query) {
    return client().Post(("/api/v1/jobs" + query).c_str(), scene.dump(), "application/json");
}

std::string ServerTest::submitOk(const json& scene, const std::string& query) {
    httplib::Result r = submit(scene, query);
    if (!r) throw std::runtime_error("submit: no response");
    EXPECT_EQ(r->status, 201) << r->body;
    return json::parse(r->body).at("id");
}

json ServerTest::getJob(const std::string& id) {
    httplib::Result r = client().Get(("/api/v1/jobs/" + id).c_str());
    if (!r || r->status != 200) throw std::runtime_error("GET job " + id + " failed");
    return json::parse(r->body);
}

json ServerTest::waitFor(const std::string& id, const std::function<bool(const json&)>& done,
                         std::chrono::milliseconds timeout) {
    auto deadline = std::chrono::steady_clock::now() + timeout;
    json job = getJob(id);
    while (!done(job) && std::chrono::steady_clock::now() < deadline) {
        std::this_thread::sleep_for(std::chrono::milliseconds(20));
        job = getJob(id);
    }
    return job;
}

std::vector<SseEvent> ServerTest::followEvents(const std::string& id, const httplib::Headers& extra) {
    std::string stream;
    httplib::Client c = client();
    // The client adds the Authorization header itself (default headers).
    httplib::Result r = c.Get(("/api/v1/jobs/" + id + "/events").c_str(), extra,
                              [&](const char* data, size_t size) {
                                  stream.append(data, size);
                                  return true;
                              });
    EXPECT_TRUE(r) << "events request failed";
    if (r) {
        EXPECT_EQ(r->status, 200);
        EXPECT_EQ(r->get_header_value("Content-Type"), "text/event-stream");
    }
    return parseSse(stream);
}

}  // namespace photon::test
