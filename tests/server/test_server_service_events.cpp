// GET /api/v1/events: one stream of every job's changes, so a list of jobs stays current
// without polling: a job submitted, started, each pass, its end and its deletion, in order,
// numbered so that a client that reconnects picks up where it was.
#include <atomic>
#include <memory>
#include <mutex>
#include <thread>
#include "server_fixture.h"

namespace photon::test {
namespace {

class ServiceEventsTest : public ServerTest {
protected:
    // Reads /api/v1/events on a thread until `until` holds for what arrived.
    struct Follower {
        std::unique_ptr<httplib::Client> client;
        std::thread thread;
        std::mutex mutex;
        std::string text;
        std::atomic<bool> stop{false};
        std::string snapshot() {
            std::lock_guard lock(mutex);
            return text;
        }
    };
    void follow(Follower& f, const httplib::Headers& headers = {}) {
        f.client = std::make_unique<httplib::Client>(client());
        f.thread = std::thread([&f, headers] {
            f.client->Get("/api/v1/events", headers, [&](const char* data, size_t size) {
                std::lock_guard lock(f.mutex);
                f.text.append(data, size);
                return !f.stop.load();
            });
        });
    }
    std::vector<SseEvent> waitFor(Follower& f, const std::string& needle) {
        for (int i = 0; i < 400 && f.snapshot().find(needle) == std::string::npos; ++i)
            std::this_thread::sleep_for(std::chrono::milliseconds(25));
        return parseSse(f.snapshot());
    }
    static void end(Follower& f) {
        f.stop = true;
        f.client->stop();  // closes the connection: the stream would only write again in 15 s
        f.thread.join();
    }
};

TEST_F(ServiceEventsTest, EveryChangeOfEveryJobInOrder) {
    startServer({"--workers", "1"});
    Follower f;
    follow(f);
    ASSERT_EQ(waitFor(f, "event: ready").size(), 1u);
    std::string id = submitOk(smallScene(2, 2000));
    waitForStatus(id, "completed");
    ASSERT_EQ(client().Delete(("/api/v1/jobs/" + id).c_str())->status, 204);
    std::vector<SseEvent> events = waitFor(f, "event: deleted");
    end(f);
    std::vector<std::string> types;
    for (const SseEvent& e : events) types.push_back(e.type);
    EXPECT_EQ(types, (std::vector<std::string>{"ready", "changed", "changed", "progress", "progress", "done", "deleted"}));
    ASSERT_EQ(events.size(), 7u);
    EXPECT_EQ(events[1].data["status"], "queued");
    EXPECT_EQ(events[2].data["status"], "running");
    EXPECT_EQ(events[3].data["pass"], 1);
    EXPECT_EQ(events[5].data["status"], "completed");
    EXPECT_EQ(events[6].data, json({{"id", id}}));
    for (size_t i = 0; i < events.size(); ++i) EXPECT_EQ(events[i].id, std::to_string(i)) << i;  // "ready" is 0
}

TEST_F(ServiceEventsTest, AReconnectingClientResumesAfterItsLastEvent) {
    startServer({"--workers", "0"});
    std::string first = submitOk(smallScene());
    std::string second = submitOk(smallScene());
    ASSERT_EQ(client().Patch(("/api/v1/jobs/" + second).c_str(), R"({"priority": 3})", "application/json")->status, 200);
    // Seen up to the first submission (event 1): the rest follows, without "ready".
    Follower f;
    follow(f, {{"Last-Event-ID", "1"}});
    std::vector<SseEvent> events = waitFor(f, "\"priority\":3");
    end(f);
    ASSERT_EQ(events.size(), 2u);
    EXPECT_EQ(events[0].type, "changed");
    EXPECT_EQ(events[0].id, "2");
    EXPECT_EQ(events[0].data["id"], second);
    EXPECT_EQ(events[1].id, "3");
    EXPECT_EQ(events[1].data["priority"], 3);
}

}  // namespace
}  // namespace photon::test
