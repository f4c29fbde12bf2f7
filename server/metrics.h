// Counters for the Prometheus text exposition at /metrics. Counters start at zero with the
// process, as Prometheus expects; job gauges are read from the job table when scraped.
#pragma once
#include <cstdint>
#include <map>
#include <optional>
#include <vector>
#include <mutex>
#include <string>
#include <utility>
#include "job.h"

namespace photon::server {

// The render farm's figures when the server uses one (docs/scale-out.md).
struct FarmFigures {
    int64_t queueDepth = 0;                 // work items waiting or being rendered
    int64_t results = 0, duplicates = 0, stale = 0;
    int64_t batches = 0;                    // merged
    double batchSeconds = 0;                // their latencies summed, queueing to result
    struct Worker {
        std::string name, host;
        int threads = 0;
        double passesPerSecond = 0;
        int64_t batches = 0, claimed = 0;
        bool busy = false;
        std::string job;  // the job of the item it renders; empty when idle
    };
    std::vector<Worker> workers;            // alive (heartbeat not expired)
};

class Metrics {
public:
    void addPass(int64_t photons, double renderSeconds);
    // `route` is the route template (e.g. "/api/v1/jobs/{id}"), never the raw path, so the
    // number of series stays bounded whatever clients request.
    void countRequest(const std::string& route, int status);
    std::string prometheusText(const std::map<JobStatus, int>& jobsByStatus,
                               const std::optional<FarmFigures>& farm = std::nullopt) const;

private:
    mutable std::mutex mutex_;
    int64_t passes_ = 0;
    int64_t photons_ = 0;
    double renderSeconds_ = 0;
    std::map<std::pair<std::string, int>, int64_t> requests_;
};

}  // namespace photon::server
