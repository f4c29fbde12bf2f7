// FarmWorker: read or claim, render, publish, acknowledge. The result is published before
// the item is acknowledged, so a worker killed in between leaves the item pending and another
// renders it again: the coordinator merges a batch once however often it arrives.
#include "farm_worker.h"
#include <unistd.h>
#include <bit>
#include <cstdio>
#include <sstream>
#include <thread>
#include <photon/image_bytes.h>
#include <photon/render.h>
#include "farm_keys.h"
#include "farm_scene.h"
#include "item_watch.h"
#include "progress_fields.h"
#include "stream_entries.h"

namespace photon::farm {

struct FarmWorker::Job {
    std::string id;
    Renderer renderer;
};

std::string hostName() {
    char name[256] = {};
    gethostname(name, sizeof name - 1);
    return name;
}

std::string defaultWorkerName() { return hostName() + "-" + std::to_string(getpid()); }

FarmWorker::FarmWorker(WorkerOptions options)
    : options_(std::move(options)), redis_(options_.redis, std::chrono::seconds(5), options_.block * 2 + std::chrono::seconds(5)) {
    ensureGroup(redis_, kWorkStream, kWorkersGroup);
    redis_.command({"SADD", kWorkerSet, options_.name});
    heartbeat("");
}

FarmWorker::~FarmWorker() {
    try {
        redis_.command({"DEL", workerKey(options_.name)});
    } catch (const RedisError&) {
    }
}

void FarmWorker::heartbeat(const std::string& item) {
    const auto now = std::chrono::duration_cast<std::chrono::milliseconds>(
                         std::chrono::system_clock::now().time_since_epoch())
                         .count();
    redis_.command({"HSET", workerKey(options_.name), "host", hostName(), "threads", std::to_string(options_.threads),
                    "item", item, "passes_per_second", std::to_string(passesPerSecond_), "batches",
                    std::to_string(counters_.batches), "claimed", std::to_string(counters_.claimed), "updated",
                    std::to_string(now)});
    redis_.command({"PEXPIRE", workerKey(options_.name), std::to_string(heartbeatTtl().count())});
}

// Three missed beats and the worker is gone from the list.
std::chrono::milliseconds FarmWorker::heartbeatTtl() const {
    return std::max(3 * options_.block, std::chrono::milliseconds(3000));
}

bool FarmWorker::step() {
    std::vector<StreamEntry> entries = entriesOfClaim(
        redis_.command({"XAUTOCLAIM", kWorkStream, kWorkersGroup, options_.name,
                        std::to_string(options_.claimAfter.count()), "0-0", "COUNT", "1"}));
    const bool claimed = !entries.empty();
    if (!claimed)
        entries = entriesOfRead(redis_.command({"XREADGROUP", "GROUP", kWorkersGroup, options_.name, "COUNT", "1",
                                                "BLOCK", std::to_string(options_.block.count()), "STREAMS",
                                                kWorkStream, ">"}));
    if (entries.empty()) {
        heartbeat("");
        return false;
    }
    counters_.claimed += claimed;
    const StreamEntry& entry = entries.front();
    try {
        process(entry);
    } catch (const RedisError&) {
        throw;  // the connection: the item stays pending for another worker
    } catch (const std::exception& e) {
        // The scene does not load or the item is malformed: every worker would fail alike,
        // so the coordinator hears of it and the item is done.
        job_.reset();
        auto field = [&](const char* name) { return entry.fields.count(name) ? entry.fields.at(name) : std::string(); };
        redis_.command({"XADD", kResultStream, "*", "job", field("job"), "round", field("round"), "batch",
                        field("batch"), "worker", options_.name, "error", e.what()});
        redis_.command({"XACK", kWorkStream, kWorkersGroup, entry.id});
        redis_.command({"XDEL", kWorkStream, entry.id});
    }
    return true;
}

// Redis going away (a restart, the network) is waited out: the item in flight stays pending
// and is claimed by whoever reaches Redis first after claim-after. A consumer group lost
// with Redis's data (no append-only file) is made again.
void FarmWorker::run(const std::atomic<bool>& stop) {
    while (!stop.load()) {
        try {
            step();
        } catch (const RedisError& e) {
            std::fprintf(stderr, "photon-worker %s: %s; trying again\n", options_.name.c_str(), e.what());
            std::this_thread::sleep_for(std::chrono::seconds(1));
            try {
                ensureGroup(redis_, kWorkStream, kWorkersGroup);
                redis_.command({"SADD", kWorkerSet, options_.name});
            } catch (const RedisError&) {
            }
        }
    }
}

FarmWorker::Job* FarmWorker::jobFor(const std::string& id) {
    if (job_ && job_->id == id) return job_.get();
    job_.reset();
    std::optional<FarmScene> scene = FarmScene::load(redis_, id);
    if (!scene) return nullptr;
    const std::filesystem::path folder = options_.scratch / id;
    std::filesystem::remove_all(folder);
    const std::filesystem::path main = scene->unpack(folder);
    job_ = std::make_unique<Job>(Job{id, Renderer(scene->read(main))});
    return job_.get();
}

void FarmWorker::process(const StreamEntry& entry) {
    const std::string& jobId = entry.field("job");
    const bool cancelled = redis_.command({"EXISTS", cancelKey(jobId)}).integer > 0;
    const auto kind = entry.fields.find("kind");
    const bool done = kind != entry.fields.end() && kind->second == "job" ? !cancelled && renderJob(entry)
                                                                          : !cancelled && renderBatch(entry);
    if (!done) ++counters_.dropped;
    redis_.command({"XACK", kWorkStream, kWorkersGroup, entry.id});
    redis_.command({"XDEL", kWorkStream, entry.id});
}

WatchedItem FarmWorker::watched(const StreamEntry& entry) const {
    const auto round = entry.fields.find("round");
    return WatchedItem{entry.field("job"), round != entry.fields.end() ? round->second : "", entry.id, options_.name,
                       options_.claimAfter, heartbeatTtl()};
}

bool FarmWorker::renderBatch(const StreamEntry& entry) {
    const std::string& jobId = entry.field("job");
    const std::string& batch = entry.field("batch");
    Job* job = jobFor(jobId);
    if (!job) return false;
    heartbeat(jobId + "/" + batch);  // from here a cancel stops the batch
    const int64_t first = std::stoll(entry.field("first"));
    const int count = std::stoi(entry.field("count"));
    CancelToken cancel;
    std::optional<PassSums> sums;
    const auto start = std::chrono::steady_clock::now();
    {
        ItemWatch watch(options_.redis, watched(entry), cancel);
        sums = job->renderer.renderPasses(first, count, cancel);
    }
    if (!sums) {  // cancelled (or not independent passes: the coordinator never sends those)
        ++counters_.cancelled;
        return true;
    }
    const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    passesPerSecond_ = seconds > 0 ? count / seconds : 0;
    // Counted, and told in the heartbeat, before the result goes out: whoever sees the
    // batch merged sees this worker's count include it.
    ++counters_.batches;
    counters_.passes += count;
    heartbeat("");
    redis_.command({"XADD", kResultStream, "*", "job", jobId, "round", watched(entry).round, "batch", batch,
                    "worker", options_.name, "sums", sums->encode()});
    return true;
}

// A whole job: rendered from the last checkpoint in Redis (a worker before this one may
// have got that far), reporting a pass with its image at most every preview_seconds, and
// passes 1, 2, 4, ... and the last one always, and a checkpoint every checkpoint_seconds and at the end. The
// checkpoint is stored for whoever takes the item over only while the item's round is the
// job's (a script, so that the check and the write are one step).
bool FarmWorker::renderJob(const StreamEntry& entry) {
    const std::string& jobId = entry.field("job");
    const WatchedItem item = watched(entry);
    const double previewSeconds = std::stod(entry.field("preview_seconds"));
    const double checkpointSeconds = std::stod(entry.field("checkpoint_seconds"));
    std::optional<FarmScene> scene = FarmScene::load(redis_, jobId);
    if (!scene) return false;
    job_.reset();  // the batches' renderer: this job needs a fresh one
    const std::filesystem::path folder = options_.scratch / jobId;
    std::filesystem::remove_all(folder);
    Renderer renderer(scene->read(scene->unpack(folder)));
    if (const RedisReply checkpoint = redis_.command({"GET", checkpointKey(jobId)}); !checkpoint.nil()) {
        std::istringstream in(checkpoint.string);
        renderer.restoreCheckpoint(in);
    }
    heartbeat(jobId);
    auto publish = [&](std::vector<std::string> fields) {
        std::vector<std::string> args{"XADD", kResultStream, "*", "job", jobId, "round", item.round, "worker",
                                      options_.name};
        for (std::string& f : fields) args.push_back(std::move(f));
        redis_.command(args);
    };
    int64_t photons = 0;  // since the last report
    server::MethodFigures figures;
    int reported = renderer.progress().pass;
    auto report = [&](const RenderProgress& p) {
        std::vector<std::string> fields{"kind", "pass", "image", encodeImageBytes(renderer.rawSnapshot())};
        appendProgressFields(fields, p, photons, figures);
        publish(std::move(fields));
        photons = 0;
        reported = p.pass;
    };
    int checkpointed = renderer.progress().pass;
    auto checkpoint = [&] {
        std::ostringstream bytes;
        renderer.saveCheckpoint(bytes);
        const bool current = redis_.command({"EVAL",
                                             "if redis.call('GET', KEYS[1]) == ARGV[1] then "
                                             "redis.call('SET', KEYS[2], ARGV[2]) return 1 end return 0",
                                             "2", roundKey(jobId), checkpointKey(jobId), item.round, bytes.str()})
                                 .integer > 0;
        if (current)
            publish({"kind", "checkpoint", "pass", std::to_string(renderer.progress().pass), "checkpoint", bytes.str()});
        checkpointed = renderer.progress().pass;
    };
    CancelToken cancel;
    RenderOutcome outcome;
    {
        ItemWatch watch(options_.redis, item, cancel);
        auto lastReport = std::chrono::steady_clock::now(), lastCheckpoint = lastReport;
        outcome = renderer.run(cancel, [&](const RenderProgress& p) {
            photons += p.lastPass.photons;
            figures.update(p.lastPass);
            ++counters_.passes;
            passesPerSecond_ = p.elapsedSeconds > 0 ? p.pass / p.elapsedSeconds : 0;
            const auto now = std::chrono::steady_clock::now();
            // Powers of two too: the coordinator keeps those passes' images (kept_passes.h).
            if (std::chrono::duration<double>(now - lastReport).count() >= previewSeconds ||
                std::has_single_bit(unsigned(p.pass))) {
                report(p);
                lastReport = now;
            }
            if (std::chrono::duration<double>(now - lastCheckpoint).count() >= checkpointSeconds) {
                checkpoint();
                lastCheckpoint = now;
            }
        });
    }
    if (outcome == RenderOutcome::Cancelled) {
        ++counters_.cancelled;
        return true;
    }
    if (reported < renderer.progress().pass) report(renderer.progress());
    if (checkpointed < renderer.progress().pass || renderer.progress().pass == 0) checkpoint();
    ++counters_.batches;
    heartbeat("");
    publish({"kind", "done", "pass", std::to_string(renderer.progress().pass)});
    return true;
}

}  // namespace photon::farm
