#include "progress_history.h"
#include <fstream>
#include <sstream>
#include "job_folders.h"

namespace photon::server {

void ProgressHistory::add(const JobProgress& p) {
    if (!points_.empty() && p.pass <= points_.back().pass) {
        // A render that went back (resumed from an earlier checkpoint): the passes after it
        // are rendered again, and it is their figures that stand.
        while (!points_.empty() && points_.back().pass >= p.pass) points_.pop_back();
    }
    if (!points_.empty() && p.pass - points_.back().pass < stride_) return;
    points_.push_back({p.pass, p.elapsedSeconds, p.photonsTraced, p.meanRadius, p.relativeError});
    if (points_.size() < kMaxPoints) return;
    std::vector<ProgressPoint> kept;
    for (size_t i = 0; i < points_.size(); i += 2) kept.push_back(points_[i]);
    if (kept.back().pass != points_.back().pass) kept.push_back(points_.back());  // the latest always
    points_ = std::move(kept);
    stride_ *= 2;
}

void ProgressHistory::save(const std::filesystem::path& file) const {
    std::ostringstream text;
    text.precision(17);
    text << "stride " << stride_ << '\n';
    text << "figures " << figures.patches << ' ' << figures.solverIterations << ' ' << figures.solverResidual << ' '
         << figures.globalMapPhotons << ' ' << figures.causticMapPhotons << '\n';
    // Points of five columns, the last the relative error (-1: none); files written before
    // it have no "columns" line and four.
    text << "columns 5\n";
    for (const ProgressPoint& p : points_)
        text << p.pass << ' ' << p.elapsedSeconds << ' ' << p.photonsTraced << ' ' << p.meanRadius << ' '
             << p.relativeError.value_or(-1) << '\n';
    writeFileAtomically(file, text.str());
}

ProgressHistory ProgressHistory::load(const std::filesystem::path& file) {
    ProgressHistory h;
    std::ifstream in(file);
    std::string word;
    if (!(in >> word >> h.stride_) || word != "stride" || h.stride_ < 1) return {};
    MethodFigures& f = h.figures;
    if (!(in >> word >> f.patches >> f.solverIterations >> f.solverResidual >> f.globalMapPhotons >>
          f.causticMapPhotons) ||
        word != "figures")
        return {};
    const std::streampos pointsStart = in.tellg();
    int columns = 4;
    const bool withErrors = (in >> word >> columns) && word == "columns" && columns == 5;
    if (!withErrors) {
        in.clear();
        in.seekg(pointsStart);
    }
    ProgressPoint p;
    double error = -1;
    while (in >> p.pass >> p.elapsedSeconds >> p.photonsTraced >> p.meanRadius && (!withErrors || in >> error)) {
        if (h.points_.size() >= kMaxPoints) break;
        p.relativeError = error >= 0 ? std::optional<double>(error) : std::nullopt;
        h.points_.push_back(p);
    }
    return h;
}

}  // namespace photon::server
