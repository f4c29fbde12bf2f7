#include "job_queue.h"

namespace photon::server {

void JobQueue::push(const std::string& id, int priority, int64_t seq) {
    {
        std::lock_guard lock(mutex_);
        Key key{-int64_t(priority), seq, id};
        order_.insert(key);
        keys_[id] = key;
    }
    ready_.notify_one();
}

bool JobQueue::remove(const std::string& id) {
    std::lock_guard lock(mutex_);
    auto it = keys_.find(id);
    if (it == keys_.end()) return false;
    order_.erase(it->second);
    keys_.erase(it);
    return true;
}

std::optional<std::string> JobQueue::pop() {
    std::unique_lock lock(mutex_);
    ready_.wait(lock, [&] { return closed_ || !order_.empty(); });
    if (closed_) return std::nullopt;
    std::string id = std::get<2>(*order_.begin());
    order_.erase(order_.begin());
    keys_.erase(id);
    return id;
}

void JobQueue::close() {
    {
        std::lock_guard lock(mutex_);
        closed_ = true;
    }
    ready_.notify_all();
}

size_t JobQueue::size() const {
    std::lock_guard lock(mutex_);
    return order_.size();
}

}  // namespace photon::server
