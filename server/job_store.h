// Durable job records in SQLite (DIR/jobs.db). The in-memory table is what requests read;
// the store is written on every state change so a restart finds the same jobs.
#pragma once
#include <filesystem>
#include <mutex>
#include <optional>
#include <vector>
#include "idempotency.h"
#include "job.h"
#include "sqlite.h"

namespace photon::server {

struct IdempotencyEntry {
    std::string key;
    std::string requestHash;  // RequestDigest::hex() of the request that created the job
    std::string jobId;
    int64_t createdUnix = 0;
};

class JobStore {
public:
    // Opens (creating or migrating the schema of) the database; throws if it cannot.
    explicit JobStore(const std::filesystem::path& databaseFile);

    // Inserts a new job, and its idempotency key if any, in one transaction (keys older
    // than a day are forgotten on the way); returns the job's submission sequence number.
    int64_t insert(const JobRecord& job, const std::optional<IdempotencyEntry>& key = std::nullopt);
    // The key's entry if it was stored less than kIdempotencyKeySeconds before `nowUnix`.
    std::optional<IdempotencyEntry> findKey(const std::string& key, int64_t nowUnix);
    // Writes the fields that change after submission (status, timestamps, progress, error).
    void update(const JobRecord& job);
    // Removes the job and any idempotency key that names it.
    void remove(const std::string& id);
    // Every stored job in submission order.
    std::vector<JobRecord> loadAll();

private:
    std::mutex mutex_;  // one connection, shared by request and worker threads
    sql::Database db_;
    sql::Statement insert_, update_, remove_, selectAll_;
    sql::Statement removeKeysOf_, forgetKeys_, insertKey_, findKey_;
};

}  // namespace photon::server
