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

std::string Metrics::prometheusText(const std::map<JobStatus, int>& jobsByStatus) const {
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
    return out.str();
}

}  // namespace photon::server
