#include "event_hub.h"

namespace photon::server {

const char* toString(EventType type) {
    switch (type) {
        case EventType::Progress: return "progress";
        case EventType::Done: return "done";
        case EventType::Failed: return "failed";
        case EventType::Cancelled: return "cancelled";
    }
    return "progress";
}

EventType eventTypeFor(JobStatus status) {
    switch (status) {
        case JobStatus::Completed: return EventType::Done;
        case JobStatus::Failed: return EventType::Failed;
        case JobStatus::Cancelled: return EventType::Cancelled;
        default: return EventType::Progress;
    }
}

void EventHub::publish(const JobRecord& job, std::optional<EventType> emit) {
    {
        std::lock_guard lock(mutex_);
        Channel& c = channels_[job.id];
        c.job = job;
        logServiceEvent({ServiceEvent::Kind::Changed, 0, emit, job});
        if (emit) {
            c.log.push_back(JobEvent{++c.seq, *emit, job});
            if (c.log.size() > kLogLength) c.log.pop_front();
            if (*emit != EventType::Progress) retireLogs(job.id);
        }
    }
    changed_.notify_all();
}

void EventHub::logServiceEvent(ServiceEvent event) {
    event.seq = ++serviceSeq_;
    serviceLog_.push_back(std::move(event));
    if (serviceLog_.size() > kServiceLogLength) serviceLog_.pop_front();
}

uint64_t EventHub::serviceSeq() const {
    std::lock_guard lock(mutex_);
    return serviceSeq_;
}

EventHub::ServiceWait EventHub::waitAnyAfter(uint64_t afterSeq, std::chrono::milliseconds timeout) const {
    ServiceWait result;
    std::unique_lock lock(mutex_);
    changed_.wait_for(lock, timeout, [&] { return shutdown_ || serviceSeq_ > afterSeq; });
    result.closed = shutdown_;
    result.seq = serviceSeq_;
    if (shutdown_ || serviceSeq_ <= afterSeq) return result;
    result.missed = serviceLog_.empty() || serviceLog_.front().seq > afterSeq + 1;
    if (result.missed) return result;
    for (const ServiceEvent& e : serviceLog_)
        if (e.seq > afterSeq) result.events.push_back(e);
    return result;
}

void EventHub::retireLogs(const std::string& finishedId) {
    finishedWithLogs_.push_back(finishedId);
    if (finishedWithLogs_.size() <= kFinishedLogsKept) return;
    auto it = channels_.find(finishedWithLogs_.front());
    finishedWithLogs_.pop_front();
    if (it == channels_.end() || it->second.log.size() <= 1) return;
    std::deque<JobEvent>& log = it->second.log;
    log.erase(log.begin(), log.end() - 1);
}

std::optional<EventHub::Snapshot> EventHub::current(const std::string& id) const {
    std::lock_guard lock(mutex_);
    auto it = channels_.find(id);
    if (it == channels_.end()) return std::nullopt;
    const Channel& c = it->second;
    return Snapshot{c.job, c.seq, c.log.empty() ? 0 : c.log.front().seq};
}

EventHub::Wait EventHub::waitAfter(const std::string& id, uint64_t afterSeq, std::chrono::milliseconds timeout) const {
    Wait result;
    std::unique_lock lock(mutex_);
    auto channel = [&]() -> const Channel* {
        auto it = channels_.find(id);
        return it == channels_.end() ? nullptr : &it->second;
    };
    changed_.wait_for(lock, timeout, [&] {
        const Channel* c = channel();
        return shutdown_ || !c || c->seq > afterSeq;
    });
    const Channel* c = channel();
    if (shutdown_ || !c) {
        result.closed = true;
        return result;
    }
    for (const JobEvent& e : c->log)
        if (e.seq > afterSeq) result.events.push_back(e);
    return result;
}

void EventHub::forget(const std::string& id) {
    {
        std::lock_guard lock(mutex_);
        channels_.erase(id);
        JobRecord gone;
        gone.id = id;
        logServiceEvent({ServiceEvent::Kind::Deleted, 0, std::nullopt, std::move(gone)});
    }
    changed_.notify_all();
}

void EventHub::shutdown() {
    {
        std::lock_guard lock(mutex_);
        shutdown_ = true;
    }
    changed_.notify_all();
}

}  // namespace photon::server
