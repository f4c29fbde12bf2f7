// FarmWorker: read or claim, render, publish, acknowledge. The result is published before
// the item is acknowledged, so a worker killed in between leaves the item pending and another
// renders it again: the coordinator merges a batch once however often it arrives.
#include "farm_worker.h"
#include <unistd.h>
#include <cstdio>
#include <thread>
#include <photon/render.h>
#include "farm_keys.h"
#include "farm_scene.h"
#include "stream_entries.h"

namespace photon::farm {

struct FarmWorker::Job {
    std::string id;
    Renderer renderer;
};

namespace {

std::string hostName() {
    char name[256] = {};
    gethostname(name, sizeof name - 1);
    return name;
}

// Sets `cancel` when the job's cancellation mark appears, polling on its own connection
// until the batch ends.
class CancelWatch {
public:
    CancelWatch(const RedisAddress& address, const std::string& job, CancelToken& cancel)
        : thread_([this, address, job, &cancel] {
              RedisClient redis(address);
              while (!done_.load()) {
                  if (redis.command({"EXISTS", cancelKey(job)}).integer > 0) {
                      cancel.cancel();
                      return;
                  }
                  std::this_thread::sleep_for(std::chrono::milliseconds(50));
              }
          }) {}
    ~CancelWatch() {
        done_.store(true);
        thread_.join();
    }

private:
    std::atomic<bool> done_{false};
    std::thread thread_;
};

}  // namespace

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
    // Three missed beats and the worker is gone from the list.
    const auto ttl = std::max<int64_t>(3 * options_.block.count(), 3000);
    redis_.command({"PEXPIRE", workerKey(options_.name), std::to_string(ttl)});
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
    const std::string& batch = entry.field("batch");
    auto finish = [&] {
        redis_.command({"XACK", kWorkStream, kWorkersGroup, entry.id});
        redis_.command({"XDEL", kWorkStream, entry.id});
    };
    Job* job = redis_.command({"EXISTS", cancelKey(jobId)}).integer > 0 ? nullptr : jobFor(jobId);
    if (!job) {
        ++counters_.dropped;
        finish();
        return;
    }
    heartbeat(jobId + "/" + batch);  // from here a cancel stops the batch
    const int64_t first = std::stoll(entry.field("first"));
    const int count = std::stoi(entry.field("count"));
    CancelToken cancel;
    std::optional<PassSums> sums;
    const auto start = std::chrono::steady_clock::now();
    {
        CancelWatch watch(options_.redis, jobId, cancel);
        sums = job->renderer.renderPasses(first, count, cancel);
    }
    if (!sums) {  // cancelled (or not independent passes: the coordinator never sends those)
        ++counters_.cancelled;
        finish();
        return;
    }
    const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    passesPerSecond_ = seconds > 0 ? count / seconds : 0;
    // Counted, and told in the heartbeat, before the result goes out: whoever sees the
    // batch merged sees this worker's count include it.
    ++counters_.batches;
    counters_.passes += count;
    heartbeat("");
    const auto round = entry.fields.find("round");
    redis_.command({"XADD", kResultStream, "*", "job", jobId, "round", round != entry.fields.end() ? round->second : "",
                    "batch", batch, "worker", options_.name, "sums", sums->encode()});
    finish();
}

}  // namespace photon::farm
