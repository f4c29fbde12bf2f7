// Fan-out of job state changes to waiting stream connections (SSE and image streams).
// Each job has a current state and a short numbered log of events: one `progress` per
// finished pass and a final done/failed/cancelled. A connection remembers the last event
// number it sent and waits for newer ones, so it sees every pass even when it wakes late,
// and a reconnecting client can resume from Last-Event-ID.
#pragma once
#include <chrono>
#include <condition_variable>
#include <cstdint>
#include <deque>
#include <mutex>
#include <optional>
#include <string>
#include <unordered_map>
#include <vector>
#include "job.h"

namespace photon::server {

enum class EventType { Progress, Done, Failed, Cancelled };
const char* toString(EventType type);
// The event that ends a finished job's stream; Progress for jobs still queued or running.
EventType eventTypeFor(JobStatus status);

struct JobEvent {
    uint64_t seq = 0;  // 1, 2, ... per job
    EventType type = EventType::Progress;
    JobRecord job;
};

// A change to any job, for the one stream of all jobs (GET /api/v1/events): every publish,
// whether or not it is one of the job's own events, and every deletion.
struct ServiceEvent {
    enum class Kind { Changed, Deleted } kind = Kind::Changed;
    uint64_t seq = 0;                    // 1, 2, ... over all jobs
    std::optional<EventType> jobEvent;   // when the change is one of the job's own events
    JobRecord job;                       // for Deleted, only its id
};

class EventHub {
public:
    // Sets the job's current state. With `emit`, also appends it to the log and wakes waiters.
    void publish(const JobRecord& job, std::optional<EventType> emit);

    struct Snapshot {
        JobRecord job;
        uint64_t seq = 0;        // the newest event number (0: none yet)
        uint64_t oldestSeq = 0;  // the oldest event still in the log (0: none)
    };
    std::optional<Snapshot> current(const std::string& id) const;

    struct Wait {
        std::vector<JobEvent> events;  // newer than the given number, oldest first
        bool closed = false;           // the job was deleted or the server is stopping
    };
    // Returns as soon as there are events after `afterSeq`, or when `timeout` passes (with no
    // events), or when the job is forgotten or the hub shut down (closed).
    Wait waitAfter(const std::string& id, uint64_t afterSeq, std::chrono::milliseconds timeout) const;

    struct ServiceWait {
        std::vector<ServiceEvent> events;  // newer than the given number, oldest first
        bool missed = false;               // some were dropped from the log: start over from a list
        bool closed = false;               // the server is stopping
        uint64_t seq = 0;                  // the newest number now
    };
    // The same for every job's changes.
    ServiceWait waitAnyAfter(uint64_t afterSeq, std::chrono::milliseconds timeout) const;
    uint64_t serviceSeq() const;

    void forget(const std::string& id);
    // Wakes every waiter for good: stream connections end so the HTTP server can stop.
    void shutdown();

    // Events kept per job: enough for any client that keeps up at all; older passes are only
    // history.
    static constexpr size_t kLogLength = 1024;
    // Finished jobs keep their full log for a while (a client may still be catching up or
    // reconnecting); beyond this many, a finished job keeps only its final event.
    static constexpr size_t kFinishedLogsKept = 32;
    // Changes kept for the stream of all jobs: a client that falls further behind is told to
    // list the jobs again.
    static constexpr size_t kServiceLogLength = 4096;

private:
    struct Channel {
        JobRecord job;
        uint64_t seq = 0;
        std::deque<JobEvent> log;
    };
    void retireLogs(const std::string& finishedId);

    mutable std::mutex mutex_;
    mutable std::condition_variable changed_;
    std::unordered_map<std::string, Channel> channels_;
    void logServiceEvent(ServiceEvent event);

    std::deque<std::string> finishedWithLogs_;  // oldest first
    std::deque<ServiceEvent> serviceLog_;
    uint64_t serviceSeq_ = 0;
    bool shutdown_ = false;
};

}  // namespace photon::server
