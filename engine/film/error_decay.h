// The rate at which a render's estimated error falls, measured from its own estimates.
//
// A model rate (PixelErrors::decay: passes^-1/2, SPPM's passes^-alpha/2) describes the
// asymptote, not the passes a user waits through. Measured on coffee at 200 x 250 (SPPM,
// passes 50-190) the error fell as passes^-0.69 with stratified camera paths and
// passes^-0.65 with independent ones, where the model says -1/3: camera-side noise
// (antialiasing, direct light, textures) falls faster than the gather's, and stratified
// draws faster still. Asked for 4.5%, that render reached it after 187 passes; at half way
// the model's rate predicted 387 in all, the measured one 180 (docs/error-estimate.md).
// So the time left is extrapolated from the slope of log(error) on log(passes) over the
// render's latest half.
#pragma once
#include <cstdint>
#include <optional>
#include <vector>

namespace photon {

class ErrorDecay {
public:
    // Records the estimate after `passes` passes. Points closer than 1% in passes to the
    // last one kept are skipped, and those before half the passes dropped, so a render of
    // any length keeps at most ~70.
    void add(int64_t passes, double relativeError);
    // The least-squares slope d of -log(error) on log(passes) over the points from half the
    // latest pass count on; none until they span a factor of 1.4 in passes with at least 4
    // points. Clamped to [0.1, 1.5]: flatter or steeper than that is noise in the estimate.
    std::optional<double> measured() const;
    void clear() { points_.clear(); }

private:
    struct Point {
        int64_t passes;
        double error;
    };
    std::vector<Point> points_;
};

// Passes still to render from `error` after `passes` until `target`, if the error falls
// as passes^-decay: N (e / e_t)^(1 / decay) - N.
double passesToTarget(double passes, double error, double target, double decay);

}  // namespace photon
