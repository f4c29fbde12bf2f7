// Where the render farm keeps things in Redis (docs/scale-out.md): one stream of work items
// read by the workers' consumer group, one stream of results read by the coordinator's, and
// per job its scene and its cancellation mark; per worker a heartbeat hash that expires.
#pragma once
#include <string>

namespace photon::farm {

inline const std::string kWorkStream = "photon:work";          // items: job, batch, first, count
inline const std::string kWorkersGroup = "workers";
inline const std::string kResultStream = "photon:results";     // job, batch, worker, sums
inline const std::string kCoordinatorGroup = "coordinator";
inline const std::string kWorkerSet = "photon:workers";        // names of workers seen
inline const std::string kRoundCounter = "photon:rounds";      // numbers each submission of a job
// Hash: "main" the scene's main file name, "overrides" a JSON object of setting overrides,
// "file:PATH" each file's bytes by its path relative to the scene's folder.
inline std::string sceneKey(const std::string& job) { return "photon:job:" + job + ":scene"; }
// Exists while the job is cancelled or deleted: workers drop its items and stop its batch.
inline std::string cancelKey(const std::string& job) { return "photon:job:" + job + ":cancelled"; }
// Hash: host, threads, item, passes_per_second, batches, updated; expires without heartbeats.
inline std::string workerKey(const std::string& name) { return "photon:worker:" + name; }

}  // namespace photon::farm
