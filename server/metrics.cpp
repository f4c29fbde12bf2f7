#include "metrics.h"
#include <sstream>

namespace photon::server {

namespace {

// Label values are route templates and status names, but escape anyway (format rules).
std::string escapeLabel(const std::string& value) {
    std::string out;
    for (char c : value) {
        if (c == '\\' || c == '"') out += '\\';
        if (c == '\n') {
            out += "\\n";
            continue;
        }
        out += c;
    }
    return out;
}

}  // namespace

void Metrics::addPass(int64_t photons, double renderSeconds) {
    std::lock_guard lock(mutex_);
    ++passes_;
    photons_ += photons;
    renderSeconds_ += renderSeconds;
}

void Metrics::countRequest(const std::string& route, int status) {
    std::lock_guard lock(mutex_);
    ++requests_[{route, status}];
}

std::string Metrics::prometheusText(const std::map<JobStatus, int>& jobsByStatus,
                                    const std::optional<FarmFigures>& farm) const {
    std::ostringstream out;
    out << "# HELP photon_jobs Jobs known to the server, by status.\n# TYPE photon_jobs gauge\n";
    for (const auto& [status, count] : jobsByStatus)
        out << "photon_jobs{status=\"" << toString(status) << "\"} " << count << "\n";
    std::lock_guard lock(mutex_);
    out << "# HELP photon_passes_total Render passes finished since start.\n# TYPE photon_passes_total counter\n"
        << "photon_passes_total " << passes_ << "\n";
    out << "# HELP photon_photons_traced_total Photons emitted since start.\n"
        << "# TYPE photon_photons_traced_total counter\nphoton_photons_traced_total " << photons_ << "\n";
    out << "# HELP photon_render_seconds_total Seconds spent rendering passes since start.\n"
        << "# TYPE photon_render_seconds_total counter\nphoton_render_seconds_total " << renderSeconds_ << "\n";
    out << "# HELP photon_http_requests_total HTTP requests by route template and status code.\n"
        << "# TYPE photon_http_requests_total counter\n";
    for (const auto& [key, count] : requests_)
        out << "photon_http_requests_total{route=\"" << escapeLabel(key.first) << "\",code=\"" << key.second
            << "\"} " << count << "\n";
    if (farm) {
        out << "# HELP photon_farm_queue_depth Render farm work items waiting or being rendered.\n"
            << "# TYPE photon_farm_queue_depth gauge\nphoton_farm_queue_depth " << farm->queueDepth << "\n";
        out << "# HELP photon_farm_batch_seconds Render farm batches merged: latency from queueing to result.\n"
            << "# TYPE photon_farm_batch_seconds summary\nphoton_farm_batch_seconds_sum " << farm->batchSeconds
            << "\nphoton_farm_batch_seconds_count " << farm->batches << "\n";
        out << "# HELP photon_farm_duplicate_results_total Batch results received again (re-delivered work).\n"
            << "# TYPE photon_farm_duplicate_results_total counter\nphoton_farm_duplicate_results_total "
            << farm->duplicates << "\n";
        out << "# HELP photon_farm_stale_results_total Results of a job's earlier round, dropped.\n"
            << "# TYPE photon_farm_stale_results_total counter\nphoton_farm_stale_results_total " << farm->stale << "\n";
        out << "# HELP photon_farm_workers Render farm workers alive.\n# TYPE photon_farm_workers gauge\n"
            << "photon_farm_workers " << farm->workers.size() << "\n";
        out << "# HELP photon_farm_worker_passes_per_second A worker's passes per second in its last batch.\n"
            << "# TYPE photon_farm_worker_passes_per_second gauge\n";
        for (const FarmFigures::Worker& w : farm->workers)
            out << "photon_farm_worker_passes_per_second{worker=\"" << escapeLabel(w.name) << "\",host=\""
                << escapeLabel(w.host) << "\"} " << w.passesPerSecond << "\n";
        out << "# HELP photon_farm_worker_batches A worker's batches rendered since it started.\n"
            << "# TYPE photon_farm_worker_batches gauge\n";
        for (const FarmFigures::Worker& w : farm->workers)
            out << "photon_farm_worker_batches{worker=\"" << escapeLabel(w.name) << "\"} " << w.batches << "\n";
        out << "# HELP photon_farm_worker_redeliveries Items a worker took over from a dead or hung one.\n"
            << "# TYPE photon_farm_worker_redeliveries gauge\n";
        for (const FarmFigures::Worker& w : farm->workers)
            out << "photon_farm_worker_redeliveries{worker=\"" << escapeLabel(w.name) << "\"} " << w.claimed << "\n";
    }
    return out.str();
}

}  // namespace photon::server
