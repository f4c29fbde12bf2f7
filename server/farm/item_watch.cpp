#include "item_watch.h"
#include <optional>
#include "farm_keys.h"

namespace photon::farm {

ItemWatch::ItemWatch(const RedisAddress& address, WatchedItem item, CancelToken& cancel)
    : item_(std::move(item)), thread_([this, address, &cancel] { watch(address, cancel); }) {}

ItemWatch::~ItemWatch() {
    done_.store(true);
    thread_.join();
}

// Polls every 50 ms, so a cancel reaches the render within a pass of it. Redis away is
// waited out: the render goes on, and its result is published once Redis is back.
void ItemWatch::watch(const RedisAddress& address, CancelToken& cancel) {
    const auto poll = std::chrono::milliseconds(50);
    // Three refreshes within the claim time: an item is claimed only if none came.
    const auto refreshEvery = std::min(item_.claimAfter / 3, item_.heartbeatTtl / 3);
    auto lastRefresh = std::chrono::steady_clock::now();
    std::optional<RedisClient> redis;
    while (!done_.load()) {
        try {
            if (!redis) redis.emplace(address, std::chrono::seconds(2), std::chrono::seconds(5));
            if (redis->command({"EXISTS", cancelKey(item_.job)}).integer > 0) return cancel.cancel();
            if (!item_.round.empty()) {
                const RedisReply round = redis->command({"GET", roundKey(item_.job)});
                if (!round.nil() && round.string != item_.round) return cancel.cancel();
            }
            const auto now = std::chrono::steady_clock::now();
            if (now - lastRefresh >= refreshEvery) {
                redis->command({"XCLAIM", kWorkStream, kWorkersGroup, item_.worker, "0", item_.entryId, "JUSTID"});
                redis->command({"PEXPIRE", workerKey(item_.worker), std::to_string(item_.heartbeatTtl.count())});
                lastRefresh = now;
            }
        } catch (const RedisError&) {
            redis.reset();  // connect again on the next poll
        }
        std::this_thread::sleep_for(poll);
    }
}

}  // namespace photon::farm
