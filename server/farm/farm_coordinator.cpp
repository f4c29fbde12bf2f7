#include "farm_coordinator.h"
#include <cstdlib>
#include <photon/image_bytes.h>
#include "farm_keys.h"
#include "progress_fields.h"
#include "stream_entries.h"

namespace photon::farm {

FarmCoordinator::FarmCoordinator(const RedisAddress& address, std::string name)
    : redis_(address, std::chrono::seconds(5), std::chrono::seconds(60)), name_(std::move(name)) {
    ensureGroups();
}

void FarmCoordinator::ensureGroups() {
    ensureGroup(redis_, kWorkStream, kWorkersGroup);
    ensureGroup(redis_, kResultStream, kCoordinatorGroup);
}

std::string FarmCoordinator::beginRound(const std::string& job, const FarmScene& scene) {
    redis_.command({"DEL", cancelKey(job), sceneKey(job), checkpointKey(job)});
    dropQueuedItems(job);
    scene.store(redis_, job);
    const std::string round = std::to_string(redis_.command({"INCR", kRoundCounter}).integer);
    redis_.command({"SET", roundKey(job), round});
    return round;
}

void FarmCoordinator::submitJob(const std::string& job, const FarmScene& scene, const WholeJobPlan& plan,
                                const std::optional<std::string>& checkpoint) {
    const std::string round = beginRound(job, scene);
    if (checkpoint) redis_.command({"SET", checkpointKey(job), *checkpoint});
    jobs_[job] = Submitted{round, {}, std::chrono::steady_clock::now(), {}, 0, {}};
    redis_.command({"XADD", kWorkStream, "*", "job", job, "round", round, "kind", "job", "checkpoint_seconds",
                    std::to_string(plan.checkpointSeconds), "preview_seconds", std::to_string(plan.previewSeconds)});
}

void FarmCoordinator::submit(const std::string& job, const FarmScene& scene, const BatchPlan& plan,
                             const std::set<int64_t>& merged) {
    const std::string round = beginRound(job, scene);
    Submitted& s = jobs_[job] = Submitted{round, merged, std::chrono::steady_clock::now(), plan, 0, {}};
    for (int64_t i = 0; i < plan.ahead; ++i) queueNext(job, s);
}

void FarmCoordinator::queueNext(const std::string& job, Submitted& s) {
    while (s.next < s.plan.batches() && s.handedOn.count(s.next)) ++s.next;
    if (s.next >= s.plan.batches()) return;
    const int64_t b = s.next++;
    s.queuedAt[b] = std::chrono::steady_clock::now();
    redis_.command({"XADD", kWorkStream, "*", "job", job, "round", s.round, "batch", std::to_string(b), "first",
                    std::to_string(s.plan.first(b)), "count", std::to_string(s.plan.count(b))});
}

size_t FarmCoordinator::collect(std::chrono::milliseconds wait, const std::function<void(Result&&)>& onResult) {
    // Results read before a restart but never acknowledged come first ("0"), then new ones.
    std::vector<StreamEntry> entries = entriesOfRead(redis_.command(
        {"XREADGROUP", "GROUP", kCoordinatorGroup, name_, "COUNT", "64", "STREAMS", kResultStream, "0"}));
    if (entries.empty())
        entries = entriesOfRead(redis_.command({"XREADGROUP", "GROUP", kCoordinatorGroup, name_, "COUNT", "64",
                                                "BLOCK", std::to_string(wait.count()), "STREAMS", kResultStream,
                                                ">"}));
    size_t handed = 0;
    for (const StreamEntry& e : entries) {
        ++counters_.results;
        Result r;
        r.job = e.field("job");
        r.worker = e.field("worker");
        auto known = jobs_.find(r.job);
        auto round = e.fields.find("round");
        if (known != jobs_.end() && round != e.fields.end() && round->second != known->second.round) {
            ++counters_.stale;
        } else if (known != jobs_.end() && readResult(e, known->second, r)) {
            onResult(std::move(r));
            ++handed;
        }
        redis_.command({"XACK", kResultStream, kCoordinatorGroup, e.id});
        redis_.command({"XDEL", kResultStream, e.id});
    }
    return handed;
}

bool FarmCoordinator::readResult(const StreamEntry& e, Submitted& job, Result& r) {
    const auto kind = e.fields.find("kind");
    const bool batch = !e.fields.count("batch") ? false : !e.fields.at("batch").empty();
    if (batch) {
        try {
            r.batch = std::stoll(e.field("batch"));
        } catch (const std::exception&) {
            r.error = "worker " + r.worker + " sent a batch number that is not one: " + e.field("batch");
            return true;
        }
        if (!job.handedOn.insert(r.batch).second) {
            ++counters_.duplicates;
            return false;
        }
        ++counters_.batches;
        const auto queued = job.queuedAt.find(r.batch);
        counters_.batchSeconds += std::chrono::duration<double>(std::chrono::steady_clock::now() -
                                                                (queued != job.queuedAt.end() ? queued->second : job.at))
                                      .count();
        if (queued != job.queuedAt.end()) job.queuedAt.erase(queued);
        queueNext(r.job, job);
    }
    try {
        if (auto error = e.fields.find("error"); error != e.fields.end()) {
            r.error = error->second;
        } else if (batch) {
            r.sums = PassSums::decode(e.field("sums"));
        } else if (kind != e.fields.end() && kind->second == "pass") {
            r.kind = Result::Kind::Pass;
            r.progress = progressOfFields(e);
            r.image = decodeImageBytes(e.field("image"));
        } else if (kind != e.fields.end() && kind->second == "checkpoint") {
            r.kind = Result::Kind::Checkpoint;
            r.progress.pass = std::stoi(e.field("pass"));
            r.checkpoint = e.field("checkpoint");
        } else if (kind != e.fields.end() && kind->second == "done") {
            r.kind = Result::Kind::Done;
            r.progress.pass = std::stoi(e.field("pass"));
        } else {
            r.error = "a result of no known kind";
        }
    } catch (const std::exception& bad) {
        r.error = std::string("worker ") + r.worker + " sent " + bad.what();
    }
    return true;
}

// The mark outlives any batch in flight by far, then goes.
void FarmCoordinator::cancel(const std::string& job) { redis_.command({"SET", cancelKey(job), "1", "EX", "86400"}); }

void FarmCoordinator::forget(const std::string& job) {
    cancel(job);
    redis_.command({"DEL", sceneKey(job), roundKey(job), checkpointKey(job)});
    jobs_.erase(job);
    dropQueuedItems(job);
}

// The stream holds one entry per batch in flight, so a scan is short.
void FarmCoordinator::dropQueuedItems(const std::string& job) {
    for (const StreamEntry& e : entriesOfRange(redis_.command({"XRANGE", kWorkStream, "-", "+"})))
        if (e.fields.count("job") && e.fields.at("job") == job) redis_.command({"XDEL", kWorkStream, e.id});
}

std::vector<WorkerInfo> FarmCoordinator::workers() {
    std::vector<WorkerInfo> out;
    for (const RedisReply& name : redis_.command({"SMEMBERS", kWorkerSet}).elements) {
        RedisReply fields = redis_.command({"HGETALL", workerKey(name.string)});
        if (fields.elements.empty()) {  // expired: gone
            redis_.command({"SREM", kWorkerSet, name.string});
            continue;
        }
        std::map<std::string, std::string> f;
        for (size_t i = 0; i + 1 < fields.elements.size(); i += 2) f[fields.elements[i].string] = fields.elements[i + 1].string;
        WorkerInfo w;
        w.name = name.string;
        w.host = f["host"];
        w.item = f["item"];
        w.threads = std::atoi(f["threads"].c_str());
        w.passesPerSecond = std::atof(f["passes_per_second"].c_str());
        w.batches = std::atoll(f["batches"].c_str());
        w.claimed = std::atoll(f["claimed"].c_str());
        out.push_back(std::move(w));
    }
    return out;
}

int64_t FarmCoordinator::queueDepth() { return redis_.command({"XLEN", kWorkStream}).integer; }

}  // namespace photon::farm
