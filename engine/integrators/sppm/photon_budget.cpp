#include "integrators/sppm/photon_budget.h"
#include <algorithm>
#include <cmath>
#include "integrators/common/checkpoint.h"

namespace photon {

void PhotonBudget::add(const Pass& pass) {
    ++passes_;
    photons_ += pass.photons;
    photonVariance_ += pass.photonVariance;
    photonVarianceTimesPhotons_ += pass.photonVariance * static_cast<double>(pass.photons);
    cameraCost_ += pass.cameraCost;
    photonCost_ += pass.photonCost;
}

int64_t PhotonBudget::next(int64_t current, double passVariance) const {
    if (passes_ == 0 || photons_ == 0) return current;
    const double passes = static_cast<double>(passes_);
    const double a = photonVarianceTimesPhotons_ / passes;
    // What is left of the pass-to-pass variance once the photons' share is taken out; at
    // least a fiftieth of it, as the two are estimates and the camera never brings nothing.
    const double camera = std::max(passVariance - photonVariance_ / passes, passVariance / 50);
    const double cameraCost = cameraCost_ / passes;
    const double photonCost = photonCost_ / static_cast<double>(photons_);
    double best;
    if (!(camera > 0) || !(photonCost > 0))
        best = static_cast<double>(current) * kMaxStep;  // no camera noise: photons are all that helps
    else if (!(a > 0))
        best = static_cast<double>(current) / kMaxStep;  // photons bring no noise: passes are what helps
    else
        best = std::sqrt(a * cameraCost / (photonCost * camera));
    const double lo = static_cast<double>(current) / kMaxStep, hi = static_cast<double>(current) * kMaxStep;
    best = std::clamp(best, lo, hi);
    // A render already below the floor (it started there) is held where it is, not lifted to it.
    const double floor = std::min(static_cast<double>(current), static_cast<double>(kMinPhotons));
    best = std::clamp(best, floor, static_cast<double>(kMaxPhotons));
    return static_cast<int64_t>(std::llround(best));
}

PhotonBudget::Range PhotonBudget::reachable(int64_t start, int64_t passes) {
    double lo = static_cast<double>(start), hi = lo;
    for (int64_t p = 4; p <= passes; p *= 2) {  // each decision made by then
        lo = std::max(std::floor(lo / kMaxStep), std::min(lo, static_cast<double>(kMinPhotons)));
        hi = std::min(std::ceil(hi * kMaxStep), std::max(hi, static_cast<double>(kMaxPhotons)));
    }
    return {static_cast<int64_t>(lo), static_cast<int64_t>(hi)};
}

void PhotonBudget::save(std::ostream& out) const {
    writeRaw(out, &passes_, 1);
    writeRaw(out, &photons_, 1);
    const double sums[4] = {photonVariance_, photonVarianceTimesPhotons_, cameraCost_, photonCost_};
    writeRaw(out, sums, 4);
}

void PhotonBudget::restore(std::istream& in) {
    PhotonBudget b;
    readRaw(in, &b.passes_, 1);
    readRaw(in, &b.photons_, 1);
    double sums[4];
    readRaw(in, sums, 4);
    for (double s : sums)
        if (!(s >= 0 && std::isfinite(s))) throw CheckpointError("checkpoint: invalid photon budget");
    if (b.passes_ < 0 || b.photons_ < 0) throw CheckpointError("checkpoint: invalid photon budget");
    b.photonVariance_ = sums[0], b.photonVarianceTimesPhotons_ = sums[1], b.cameraCost_ = sums[2], b.photonCost_ = sums[3];
    *this = b;
}

}  // namespace photon
