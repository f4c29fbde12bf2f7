// Durable job records in SQLite (DIR/jobs.db). The in-memory table is what requests read;
// the store is written on every state change so a restart finds the same jobs.
#pragma once
#include <filesystem>
#include <mutex>
#include <vector>
#include "job.h"
#include "sqlite.h"

namespace photon::server {

class JobStore {
public:
    explicit JobStore(const std::filesystem::path& databaseFile);

    // Inserts a new job and returns its submission sequence number.
    int64_t insert(const JobRecord& job);
    // Writes the fields that change after submission (status, timestamps, progress, error).
    void update(const JobRecord& job);
    void remove(const std::string& id);
    // Every stored job in submission order.
    std::vector<JobRecord> loadAll();

private:
    std::mutex mutex_;  // one connection, shared by request and worker threads
    sql::Database db_;
    sql::Statement insert_, update_, remove_, selectAll_;
};

}  // namespace photon::server
