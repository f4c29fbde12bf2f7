// POST /api/v1/jobs with an Idempotency-Key: a retry returns the job the first attempt
// created (200, same id and Location), a different request under the key is 422, keys
// survive restarts, expire after 24 hours, and concurrent retries create one job.
#include <sqlite3.h>
#include <algorithm>
#include <fstream>
#include <atomic>
#include <thread>
#include "server_fixture.h"

namespace photon::test {
namespace {

namespace fs = std::filesystem;

class IdempotencyTest : public ServerTest {
protected:
    httplib::Result post(const json& scene, const std::string& key, const std::string& query = "") {
        return client().Post(("/api/v1/jobs" + query).c_str(), {{"Idempotency-Key", key}}, scene.dump(),
                             "application/json");
    }
    size_t jobCount() { return json::parse(client().Get("/api/v1/jobs")->body)["total"].get<size_t>(); }
};

// Runs SQL on the server's database (with the server stopped).
void execSql(const fs::path& db, const std::string& sql) {
    sqlite3* handle = nullptr;
    ASSERT_EQ(sqlite3_open(db.c_str(), &handle), SQLITE_OK);
    char* error = nullptr;
    int rc = sqlite3_exec(handle, sql.c_str(), nullptr, nullptr, &error);
    EXPECT_EQ(rc, SQLITE_OK) << (error ? error : "");
    sqlite3_free(error);
    sqlite3_close(handle);
}

int64_t queryInteger(const fs::path& db, const std::string& sql) {
    sqlite3* handle = nullptr;
    sqlite3_open(db.c_str(), &handle);
    sqlite3_stmt* stmt = nullptr;
    sqlite3_prepare_v2(handle, sql.c_str(), -1, &stmt, nullptr);
    int64_t value = sqlite3_step(stmt) == SQLITE_ROW ? sqlite3_column_int64(stmt, 0) : -1;
    sqlite3_finalize(stmt);
    sqlite3_close(handle);
    return value;
}

TEST_F(IdempotencyTest, ARetryReturnsTheFirstJob) {
    startServer({"--workers", "0"});
    httplib::Result first = post(smallScene(), "retry-1");
    ASSERT_TRUE(first);
    ASSERT_EQ(first->status, 201) << first->body;
    std::string id = json::parse(first->body)["id"];
    httplib::Result again = post(smallScene(), "retry-1");
    ASSERT_TRUE(again);
    EXPECT_EQ(again->status, 200) << again->body;
    EXPECT_EQ(json::parse(again->body)["id"], id);
    EXPECT_EQ(again->get_header_value("Location"), "/api/v1/jobs/" + id);
    EXPECT_EQ(jobCount(), 1u);
    // Another key is another job; no key at all always is.
    EXPECT_EQ(post(smallScene(), "retry-2")->status, 201);
    EXPECT_EQ(submit(smallScene())->status, 201);
    EXPECT_EQ(jobCount(), 3u);
}

TEST_F(IdempotencyTest, AKeyReusedForAnotherRequestIs422) {
    startServer({"--workers", "0"});
    ASSERT_EQ(post(smallScene(), "k", "?passes=2")->status, 201);
    for (auto [scene, query] : {std::pair{smallScene(4), std::string("?passes=2")}, std::pair{smallScene(), std::string("?passes=3")},
                                std::pair{smallScene(), std::string()}}) {
        httplib::Result r = post(scene, "k", query);
        ASSERT_TRUE(r);
        EXPECT_EQ(r->status, 422) << query;
        EXPECT_EQ(json::parse(r->body)["error"], "Idempotency-Key reused with a different request");
    }
    // The multipart form of the same request is recognised too (the boundary may differ).
    httplib::MultipartFormDataItems items{{"scene", smallScene().dump(), "", "application/json"}};
    httplib::Result m1 = client().Post("/api/v1/jobs", {{"Idempotency-Key", "m"}}, items);
    httplib::Result m2 = client().Post("/api/v1/jobs", {{"Idempotency-Key", "m"}}, items);
    ASSERT_TRUE(m1 && m2);
    EXPECT_EQ(m1->status, 201);
    EXPECT_EQ(m2->status, 200);
    EXPECT_EQ(json::parse(m1->body)["id"], json::parse(m2->body)["id"]);
    EXPECT_EQ(jobCount(), 2u);
}

TEST_F(IdempotencyTest, MalformedKeysAre400) {
    startServer({"--workers", "0"});
    const std::vector<std::pair<std::string, std::string>> bad{
        {std::string(256, 'k'), "Idempotency-Key: must be 1 to 255 characters, got 256"},
        {"tab\there", "Idempotency-Key: must be printable ASCII characters"},
        {"caf\xc3\xa9", "Idempotency-Key: must be printable ASCII characters"},
    };
    for (const auto& [key, message] : bad) {
        httplib::Result r = post(smallScene(), key);
        ASSERT_TRUE(r) << key;
        EXPECT_EQ(r->status, 400) << key;
        EXPECT_EQ(json::parse(r->body)["error"], message) << key;
    }
    // An empty key (which httplib's parser drops: the guard names it) is no key at all.
    const std::string scene = smallScene().dump();
    std::string empty = rawExchange(port(), "POST /api/v1/jobs HTTP/1.1\r\nHost: 127.0.0.1:" + std::to_string(port()) +
                                                "\r\nContent-Type: application/json\r\nIdempotency-Key: \r\nContent-Length: " +
                                                std::to_string(scene.size()) + "\r\nConnection: close\r\n\r\n" + scene);
    EXPECT_EQ(empty.rfind("HTTP/1.1 400 Bad Request\r\n", 0), 0u) << empty;
    EXPECT_EQ(problemOf(empty)["detail"], "Idempotency-Key: must be 1 to 255 characters, got 0");
    EXPECT_EQ(post(smallScene(), std::string(255, '~'))->status, 201);
    EXPECT_EQ(jobCount(), 1u);
}

TEST_F(IdempotencyTest, ConcurrentRetriesCreateOneJob) {
    startServer({"--workers", "0"});
    constexpr int kClients = 8;
    std::vector<std::thread> threads;
    std::vector<int> statuses(kClients);
    std::vector<std::string> ids(kClients);
    for (int i = 0; i < kClients; ++i)
        threads.emplace_back([&, i] {
            httplib::Result r = post(smallScene(), "same-key");
            if (!r) return;
            statuses[i] = r->status;
            ids[i] = json::parse(r->body).value("id", "");
        });
    for (std::thread& t : threads) t.join();
    EXPECT_EQ(std::count(statuses.begin(), statuses.end(), 201), 1);
    EXPECT_EQ(std::count(statuses.begin(), statuses.end(), 200), kClients - 1);
    for (const std::string& id : ids) EXPECT_EQ(id, ids[0]);
    EXPECT_EQ(jobCount(), 1u);
}

TEST_F(IdempotencyTest, KeysSurviveARestartAndExpireAfterADay) {
    startServer({"--workers", "0"});
    std::string id = json::parse(post(smallScene(), "durable")->body)["id"];
    std::string other = json::parse(post(smallScene(), "aging")->body)["id"];
    ASSERT_EQ(stopServer(), 0);
    // "aging" was stored 24 h and 1 s ago.
    execSql(dataDir() / "jobs.db",
            "UPDATE idempotency_keys SET created_unix = created_unix - 86401 WHERE key = 'aging'");
    startServer({"--workers", "0"});
    httplib::Result again = post(smallScene(), "durable");
    EXPECT_EQ(again->status, 200);
    EXPECT_EQ(json::parse(again->body)["id"], id);
    httplib::Result expired = post(smallScene(), "aging");
    EXPECT_EQ(expired->status, 201);
    EXPECT_NE(json::parse(expired->body)["id"], other);
    // Storing the new key forgot the expired entry.
    ASSERT_EQ(stopServer(), 0);
    EXPECT_EQ(queryInteger(dataDir() / "jobs.db", "SELECT COUNT(*) FROM idempotency_keys"), 2);
}

TEST_F(IdempotencyTest, DeletingTheJobForgetsItsKey) {
    startServer({"--workers", "0"});
    std::string id = json::parse(post(smallScene(), "gone")->body)["id"];
    ASSERT_EQ(client().Post(("/api/v1/jobs/" + id + "/cancel").c_str())->status, 200);
    ASSERT_EQ(client().Delete(("/api/v1/jobs/" + id).c_str())->status, 204);
    httplib::Result r = post(smallScene(), "gone");
    EXPECT_EQ(r->status, 201);
    EXPECT_NE(json::parse(r->body)["id"], id);
}

// A data directory written before keys existed (schema version 1) opens, keeps its jobs
// and is migrated in place.
TEST_F(IdempotencyTest, AVersion1DatabaseIsMigrated) {
    const std::string id = "00000000000000aa";
    fs::create_directories(dataDir() / "jobs" / id);
    std::ofstream(dataDir() / "jobs" / id / "scene.json") << smallScene().dump();
    execSql(dataDir() / "jobs.db", R"sql(
        CREATE TABLE jobs (
            seq INTEGER PRIMARY KEY AUTOINCREMENT, id TEXT NOT NULL UNIQUE, status TEXT NOT NULL,
            priority INTEGER NOT NULL, created_at TEXT NOT NULL, started_at TEXT, finished_at TEXT,
            passes INTEGER NOT NULL, photons_per_pass INTEGER NOT NULL, seed INTEGER NOT NULL,
            integrator TEXT NOT NULL, width INTEGER NOT NULL, height INTEGER NOT NULL,
            pass INTEGER NOT NULL DEFAULT 0, photons_traced INTEGER NOT NULL DEFAULT 0,
            mean_radius REAL NOT NULL DEFAULT 0, elapsed_seconds REAL NOT NULL DEFAULT 0,
            eta_seconds REAL NOT NULL DEFAULT 0, error TEXT);
        INSERT INTO jobs (id, status, priority, created_at, started_at, finished_at, passes, photons_per_pass,
                          seed, integrator, width, height, pass)
            VALUES ('00000000000000aa', 'cancelled', 0, '2024-01-01T00:00:00.000Z', NULL,
                    '2024-01-01T00:00:01.000Z', 3, 2000, 7, 'sppm', 32, 32, 0);
        PRAGMA user_version = 1;)sql");
    startServer({"--workers", "0"});
    json job = getJob(id);
    EXPECT_EQ(job["status"], "cancelled");
    EXPECT_EQ(job["settings"]["photons_per_pass"], 2000);
    EXPECT_EQ(post(smallScene(), "after-migration")->status, 201);
    EXPECT_EQ(post(smallScene(), "after-migration")->status, 200);
    EXPECT_EQ(jobCount(), 2u);
    ASSERT_EQ(stopServer(), 0);
    EXPECT_EQ(queryInteger(dataDir() / "jobs.db", "PRAGMA user_version"), 7);
    // And it opens again as the current version.
    startServer({"--workers", "0"});
    EXPECT_EQ(jobCount(), 2u);
}

}  // namespace
}  // namespace photon::test
