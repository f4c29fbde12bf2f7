// Queued job ids in run order: higher priority first, then submission order. Workers block
// in pop() until a job arrives or the queue is closed for shutdown.
#pragma once
#include <condition_variable>
#include <cstdint>
#include <map>
#include <mutex>
#include <optional>
#include <set>
#include <string>
#include <tuple>

namespace photon::server {

class JobQueue {
public:
    void push(const std::string& id, int priority, int64_t seq);
    // False if the id was not queued (already taken by a worker).
    bool remove(const std::string& id);
    // The next job to run; nullopt once the queue is closed.
    std::optional<std::string> pop();
    void close();
    size_t size() const;

private:
    // Negated priority so that the set's ascending order is run order.
    using Key = std::tuple<int64_t, int64_t, std::string>;  // (-priority, seq, id)
    mutable std::mutex mutex_;
    std::condition_variable ready_;
    std::set<Key> order_;
    std::map<std::string, Key> keys_;
    bool closed_ = false;
};

}  // namespace photon::server
