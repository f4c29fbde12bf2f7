// A job's progress pass by pass, for plots that outlive a page reload and a restart: at most
// kMaxPoints points, thinned evenly as the render goes on (when full, every other point goes
// and from then on only every second pass is taken, then every fourth, ...), so a job of a
// million passes keeps a few kilobytes. Stored beside the job as text, one point a line.
#pragma once
#include <cstdint>
#include <filesystem>
#include <optional>
#include <vector>
#include "job.h"

namespace photon::server {

struct ProgressPoint {
    int pass = 0;
    double elapsedSeconds = 0;
    int64_t photonsTraced = 0;
    double meanRadius = 0;
    std::optional<double> relativeError;
};

class ProgressHistory {
public:
    static constexpr size_t kMaxPoints = 256;

    void add(const JobProgress& progress);
    // The method's figures as the render last reported them, kept with the history.
    MethodFigures figures;
    const std::vector<ProgressPoint>& points() const { return points_; }

    // Written through a temporary file; read back as far as it is whole (a file from an
    // older version, or none, is an empty history).
    void save(const std::filesystem::path& file) const;
    static ProgressHistory load(const std::filesystem::path& file);

private:
    std::vector<ProgressPoint> points_;
    int stride_ = 1;  // passes between points taken
};

}  // namespace photon::server
