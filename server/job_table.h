// The live set of jobs: the record every request reads, plus each running job's cancel
// token. One mutex; every operation is a short read-modify-write of one entry, and the
// state transitions (queued -> running -> finished, cancel, delete) are decided here so
// that they are atomic with respect to each other.
#pragma once
#include <map>
#include <memory>
#include <mutex>
#include <optional>
#include <string>
#include <unordered_map>
#include <vector>
#include <photon/progress.h>
#include "job.h"

namespace photon::server {

// Which jobs a list shows: all of the conditions given.
struct JobFilter {
    std::vector<JobStatus> statuses;   // any of these; empty: any status
    std::string nameContains;          // in the name, ignoring case; empty: any name
    std::vector<std::string> labels;   // every one of these
    std::optional<int64_t> afterSeq;   // a cursor: jobs submitted before this one
    bool matches(const JobRecord& job) const;
};

class JobTable {
public:
    void insert(JobRecord job);
    bool contains(const std::string& id) const;
    std::optional<JobRecord> find(const std::string& id) const;

    struct Page {
        std::vector<JobRecord> jobs;           // newest first
        size_t total = 0;                      // matching jobs before the cursor, limit and offset
        std::optional<int64_t> nextAfterSeq;   // the next page's cursor, when there is one
    };
    // `offset` applies when the filter has no cursor.
    Page list(const JobFilter& filter, size_t limit, size_t offset) const;
    std::map<JobStatus, int> countByStatus() const;
    // Queued and running jobs submitted from `client`.
    int64_t activeJobsOf(const std::string& client) const;
    // Bytes of the scenes and assets of those jobs.
    int64_t activeBytesOf(const std::string& client) const;

    struct Started {
        JobRecord job;
        std::shared_ptr<CancelToken> cancel;
    };
    // Queued -> running. nullopt if the job is gone or no longer queued (cancelled meanwhile).
    std::optional<Started> start(const std::string& id, const std::string& now);
    JobRecord setProgress(const std::string& id, const JobProgress& progress);
    // Notes that the image of `pass` is kept (JobFolders::keptPassFile).
    void addKeptPass(const std::string& id, int pass);
    // Running -> completed/failed/cancelled.
    JobRecord finish(const std::string& id, JobStatus status, const std::string& error, const std::string& now);

    enum class CancelResult { NotFound, AlreadyFinished, CancelledNow, Requested };
    // Queued jobs are cancelled at once; running ones get their token set and finish later.
    CancelResult cancel(const std::string& id, const std::string& now, JobRecord& job);
    bool cancelRequested(const std::string& id) const;

    // Queued -> paused at once; running -> paused after its current pass (the runner asks
    // pauseRequested and calls markPaused).
    enum class PauseResult { NotFound, NotPausable, PausedNow, Requested };
    PauseResult pause(const std::string& id, const std::string& now, JobRecord& job);
    bool pauseRequested(const std::string& id) const;
    JobRecord markPaused(const std::string& id, const std::string& now);
    // Paused -> queued.
    enum class ResumeResult { NotFound, NotPaused, Resumed };
    ResumeResult resume(const std::string& id, const std::string& now, JobRecord& job);
    // Completed -> queued with `morePasses` more passes to render.
    enum class ContinueResult { NotFound, NotCompleted, Continued };
    ContinueResult continueWith(const std::string& id, int morePasses, const std::string& now, JobRecord& job);

    enum class ChangeResult { NotFound, NotQueued, Changed };
    // A queued job's priority; `job` is the record after (or as it is, when not changed).
    ChangeResult setPriority(const std::string& id, int priority, const std::string& now, JobRecord& job);

    enum class RemoveResult { NotFound, NotFinished, Removed };
    RemoveResult remove(const std::string& id);

    // Shutdown: stop every render without marking it cancelled (it is resumed on restart).
    void interruptAll();

private:
    struct Entry {
        JobRecord job;
        std::shared_ptr<CancelToken> cancel;  // set while running
        bool cancelRequested = false;         // by a client, as opposed to shutdown
        bool pauseRequested = false;          // by a client: stop after the pass, keep the state
    };
    Entry& at(const std::string& id);
    // Sum of `value(job)` over the queued and running jobs of `client`.
    template <typename Value>
    int64_t sumOverActive(const std::string& client, Value value) const {
        std::lock_guard lock(mutex_);
        int64_t total = 0;
        for (const auto& [id, entry] : entries_)
            if (entry.job.client == client && !isFinished(entry.job.status)) total += value(entry.job);
        return total;
    }

    mutable std::mutex mutex_;
    std::unordered_map<std::string, Entry> entries_;
};

}  // namespace photon::server
