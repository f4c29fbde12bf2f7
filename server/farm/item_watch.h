// What a worker keeps an eye on while it renders one work item, on a Redis connection of
// its own: the job's cancellation mark and its round (a newer submission supersedes the
// item), either of which cancels the render; and, so that a long item (a whole job, a slow
// batch) is not taken for a dead worker's, it keeps the item's idle time in the pending list
// short (XCLAIM to itself) and the worker's heartbeat hash from expiring.
#pragma once
#include <atomic>
#include <chrono>
#include <string>
#include <thread>
#include <photon/progress.h>
#include "redis_client.h"

namespace photon::farm {

struct WatchedItem {
    std::string job, round, entryId;  // round: empty for items without one
    std::string worker;               // the consumer holding the item
    std::chrono::milliseconds claimAfter{30000};
    std::chrono::milliseconds heartbeatTtl{3000};
};

class ItemWatch {
public:
    ItemWatch(const RedisAddress& address, WatchedItem item, CancelToken& cancel);
    ~ItemWatch();  // stops watching
    ItemWatch(const ItemWatch&) = delete;
    ItemWatch& operator=(const ItemWatch&) = delete;

private:
    void watch(const RedisAddress& address, CancelToken& cancel);

    WatchedItem item_;
    std::atomic<bool> done_{false};
    std::thread thread_;
};

}  // namespace photon::farm
