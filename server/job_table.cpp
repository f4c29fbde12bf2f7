#include "job_table.h"
#include <algorithm>
#include <cctype>
#include <stdexcept>
#include "clock.h"

namespace photon::server {

JobTable::Entry& JobTable::at(const std::string& id) {
    auto it = entries_.find(id);
    if (it == entries_.end()) throw std::logic_error("job " + id + " is not in the table");
    return it->second;
}

void JobTable::insert(JobRecord job) {
    std::lock_guard lock(mutex_);
    std::string id = job.id;
    entries_[id] = Entry{std::move(job), nullptr, false};
}

bool JobTable::contains(const std::string& id) const {
    std::lock_guard lock(mutex_);
    return entries_.count(id) != 0;
}

std::optional<JobRecord> JobTable::find(const std::string& id) const {
    std::lock_guard lock(mutex_);
    auto it = entries_.find(id);
    if (it == entries_.end()) return std::nullopt;
    return it->second.job;
}

bool JobFilter::matches(const JobRecord& job) const {
    if (!statuses.empty() && std::find(statuses.begin(), statuses.end(), job.status) == statuses.end()) return false;
    if (!nameContains.empty()) {
        auto lower = [](unsigned char c) { return std::tolower(c); };
        auto at = std::search(job.name.begin(), job.name.end(), nameContains.begin(), nameContains.end(),
                              [&](char a, char b) { return lower(a) == lower(b); });
        if (at == job.name.end()) return false;
    }
    for (const std::string& label : labels)
        if (std::find(job.labels.begin(), job.labels.end(), label) == job.labels.end()) return false;
    return true;
}

JobTable::Page JobTable::list(const JobFilter& filter, size_t limit, size_t offset) const {
    std::vector<const JobRecord*> matching;
    Page page;
    std::lock_guard lock(mutex_);
    for (const auto& [id, entry] : entries_)
        if (filter.matches(entry.job)) matching.push_back(&entry.job);
    std::sort(matching.begin(), matching.end(), [](auto* a, auto* b) { return a->seq > b->seq; });
    page.total = matching.size();
    // A cursor starts after the job it names, wherever that now is (offsets shift when jobs
    // are submitted or deleted between pages; a submission order does not).
    size_t first = offset;
    if (filter.afterSeq)
        first = size_t(std::find_if(matching.begin(), matching.end(), [&](auto* j) { return j->seq < *filter.afterSeq; }) -
                       matching.begin());
    size_t i = first;
    for (; i < matching.size() && page.jobs.size() < limit; ++i) page.jobs.push_back(*matching[i]);
    if (i < matching.size() && !page.jobs.empty()) page.nextAfterSeq = page.jobs.back().seq;
    return page;
}

std::map<JobStatus, int> JobTable::countByStatus() const {
    std::map<JobStatus, int> counts;
    for (JobStatus s : {JobStatus::Queued, JobStatus::Running, JobStatus::Paused, JobStatus::Completed,
                        JobStatus::Failed, JobStatus::Cancelled})
        counts[s] = 0;
    std::lock_guard lock(mutex_);
    for (const auto& [id, entry] : entries_) ++counts[entry.job.status];
    return counts;
}

int64_t JobTable::activeJobsOf(const std::string& client) const {
    return sumOverActive(client, [](const JobRecord&) { return int64_t(1); });
}

int64_t JobTable::activeBytesOf(const std::string& client) const {
    return sumOverActive(client, [](const JobRecord& job) { return job.uploadBytes; });
}

std::optional<JobTable::Started> JobTable::start(const std::string& id, const std::string& now) {
    std::lock_guard lock(mutex_);
    auto it = entries_.find(id);
    if (it == entries_.end() || it->second.job.status != JobStatus::Queued) return std::nullopt;
    Entry& e = it->second;
    e.job.status = JobStatus::Running;
    e.job.startedAt = e.job.updatedAt = now;
    e.job.progress = JobProgress{};  // until its first pass reports, resumed from its checkpoint if any
    e.cancel = std::make_shared<CancelToken>();
    e.pauseRequested = false;
    return Started{e.job, e.cancel};
}

JobRecord JobTable::setProgress(const std::string& id, const JobProgress& progress) {
    std::lock_guard lock(mutex_);
    Entry& e = at(id);
    e.job.progress = progress;
    e.job.updatedAt = utcNowIso8601();
    return e.job;
}

void JobTable::addKeptPass(const std::string& id, int pass) {
    std::lock_guard lock(mutex_);
    std::vector<int>& kept = at(id).job.keptPasses;
    auto at = std::lower_bound(kept.begin(), kept.end(), pass);
    if (at == kept.end() || *at != pass) kept.insert(at, pass);
}

JobRecord JobTable::finish(const std::string& id, JobStatus status, const std::string& error, const std::string& now) {
    std::lock_guard lock(mutex_);
    Entry& e = at(id);
    e.job.status = status;
    e.job.error = error;
    e.job.finishedAt = e.job.updatedAt = now;
    e.job.progress.etaSeconds = 0;
    e.cancel.reset();
    return e.job;
}

JobTable::CancelResult JobTable::cancel(const std::string& id, const std::string& now, JobRecord& job) {
    std::lock_guard lock(mutex_);
    auto it = entries_.find(id);
    if (it == entries_.end()) return CancelResult::NotFound;
    Entry& e = it->second;
    CancelResult result = CancelResult::AlreadyFinished;
    if (e.job.status == JobStatus::Queued || e.job.status == JobStatus::Paused) {
        e.job.status = JobStatus::Cancelled;
        e.job.finishedAt = e.job.updatedAt = now;
        result = CancelResult::CancelledNow;
    } else if (e.job.status == JobStatus::Running) {
        e.cancelRequested = true;
        if (e.cancel) e.cancel->cancel();
        result = CancelResult::Requested;
    }
    job = e.job;
    return result;
}

bool JobTable::cancelRequested(const std::string& id) const {
    std::lock_guard lock(mutex_);
    auto it = entries_.find(id);
    return it != entries_.end() && it->second.cancelRequested;
}

JobTable::PauseResult JobTable::pause(const std::string& id, const std::string& now, JobRecord& job) {
    std::lock_guard lock(mutex_);
    auto it = entries_.find(id);
    if (it == entries_.end()) return PauseResult::NotFound;
    Entry& e = it->second;
    PauseResult result = PauseResult::NotPausable;
    if (e.job.status == JobStatus::Queued) {
        e.job.status = JobStatus::Paused;
        e.job.updatedAt = now;
        result = PauseResult::PausedNow;
    } else if (e.job.status == JobStatus::Running && !e.cancelRequested) {
        e.pauseRequested = true;
        if (e.cancel) e.cancel->cancel();
        result = PauseResult::Requested;
    }
    job = e.job;
    return result;
}

bool JobTable::pauseRequested(const std::string& id) const {
    std::lock_guard lock(mutex_);
    auto it = entries_.find(id);
    return it != entries_.end() && it->second.pauseRequested;
}

JobRecord JobTable::markPaused(const std::string& id, const std::string& now) {
    std::lock_guard lock(mutex_);
    Entry& e = at(id);
    e.job.status = JobStatus::Paused;
    e.job.updatedAt = now;
    e.job.progress.etaSeconds = 0;
    e.pauseRequested = false;
    e.cancel.reset();
    return e.job;
}

JobTable::ResumeResult JobTable::resume(const std::string& id, const std::string& now, JobRecord& job) {
    std::lock_guard lock(mutex_);
    auto it = entries_.find(id);
    if (it == entries_.end()) return ResumeResult::NotFound;
    Entry& e = it->second;
    job = e.job;
    if (e.job.status != JobStatus::Paused) return ResumeResult::NotPaused;
    e.job.status = JobStatus::Queued;
    e.job.updatedAt = now;
    job = e.job;
    return ResumeResult::Resumed;
}

JobTable::ContinueResult JobTable::continueWith(const std::string& id, int morePasses, const std::string& now,
                                                JobRecord& job) {
    std::lock_guard lock(mutex_);
    auto it = entries_.find(id);
    if (it == entries_.end()) return ContinueResult::NotFound;
    Entry& e = it->second;
    job = e.job;
    if (e.job.status != JobStatus::Completed) return ContinueResult::NotCompleted;
    e.job.status = JobStatus::Queued;
    // N more passes after the last one rendered, whatever ended the render (its pass count,
    // time limit or target error); the target, once reached, no longer stops it.
    e.job.settings.passes = e.job.progress.pass + morePasses;
    e.job.settings.targetError = 0;
    e.job.finishedAt.clear();
    e.job.updatedAt = now;
    e.cancelRequested = false;
    job = e.job;
    return ContinueResult::Continued;
}

JobTable::ChangeResult JobTable::setPriority(const std::string& id, int priority, const std::string& now,
                                             JobRecord& job) {
    std::lock_guard lock(mutex_);
    auto it = entries_.find(id);
    if (it == entries_.end()) return ChangeResult::NotFound;
    Entry& e = it->second;
    if (e.job.status != JobStatus::Queued) {
        job = e.job;
        return ChangeResult::NotQueued;
    }
    e.job.priority = priority;
    e.job.updatedAt = now;
    job = e.job;
    return ChangeResult::Changed;
}

JobTable::RemoveResult JobTable::remove(const std::string& id) {
    std::lock_guard lock(mutex_);
    auto it = entries_.find(id);
    if (it == entries_.end()) return RemoveResult::NotFound;
    if (!isFinished(it->second.job.status)) return RemoveResult::NotFinished;
    entries_.erase(it);
    return RemoveResult::Removed;
}

void JobTable::interruptAll() {
    std::lock_guard lock(mutex_);
    for (auto& [id, e] : entries_)
        if (e.cancel) e.cancel->cancel();
}

}  // namespace photon::server
