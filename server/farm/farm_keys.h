// Where the render farm keeps things in Redis (docs/scale-out.md): one stream of work items
// read by the workers' consumer group, one stream of results read by the coordinator's, and
// per job its scene and its cancellation mark; per worker a heartbeat hash that expires.
#pragma once
#include <string>

namespace photon::farm {

// Items: job, round, and either batch, first, count (a batch of independent passes) or
// kind "job", checkpoint_seconds, preview_seconds (a whole job: docs/scale-out.md).
inline const std::string kWorkStream = "photon:work";
inline const std::string kWorkersGroup = "workers";
// Results: job, round, worker, then batch and sums; or kind "pass" (progress and image),
// "checkpoint" (pass and bytes) or "done" of a whole job; or error.
inline const std::string kResultStream = "photon:results";
inline const std::string kCoordinatorGroup = "coordinator";
inline const std::string kWorkerSet = "photon:workers";        // names of workers seen
inline const std::string kRoundCounter = "photon:rounds";      // numbers each submission of a job
// Hash: "main" the scene's main file name, "overrides" a JSON object of setting overrides,
// "file:PATH" each file's bytes by its path relative to the scene's folder.
inline std::string sceneKey(const std::string& job) { return "photon:job:" + job + ":scene"; }
// Exists while the job is cancelled or deleted: workers drop its items and stop its batch.
inline std::string cancelKey(const std::string& job) { return "photon:job:" + job + ":cancelled"; }
// The job's current round: a worker whose item is of another round stops rendering it.
inline std::string roundKey(const std::string& job) { return "photon:job:" + job + ":round"; }
// A whole job's last checkpoint, from which a worker taking over its item resumes.
inline std::string checkpointKey(const std::string& job) { return "photon:job:" + job + ":checkpoint"; }
// Hash: host, threads, item, passes_per_second, batches, updated; expires without heartbeats.
inline std::string workerKey(const std::string& name) { return "photon:worker:" + name; }

}  // namespace photon::farm
