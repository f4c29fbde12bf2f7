// render.adaptive_photons: the photons a pass traces, chosen from how the render's error
// splits between its camera paths and its photons and from what each costs
// (docs/sppm.md, "Photons per pass").
//
// After P passes of N photons the per-pixel schedule's variance is about
//     E^2 = V_c / P + a / (P N):
// V_c what a pass's camera path brings (where in the pixel, which lobe, the direct light),
// a / N what its photons bring given that path. A pass costs C_c + N c_p (camera rays and
// the grid; photon rays and the gather), so time T holds T / (C_c + N c_p) passes and
//     E^2 T = (C_c + N c_p) (V_c + a / N),
// least at N* = sqrt(a C_c / (c_p V_c)): the split of work that maximises Monte Carlo
// efficiency, 1 / (variance x cost) (Hammersley & Handscomb 1964). The two variances
// are told apart without a second render: a pass's estimate p at a point that gathered M
// photons varies by about p^2 / M given its camera path (the photons' count is Poisson),
// and the rest of the pass-to-pass variance (the error estimate's halves) is the camera's.
// Every figure is a count or the image itself, never a clock, so the choice is the same
// for a seed on any machine and thread count.
#pragma once
#include <cstdint>
#include <istream>
#include <ostream>

namespace photon {

class PhotonBudget {
public:
    // What one pass measured.
    struct Pass {
        int64_t photons = 0;         // N, the photons it traced
        double photonVariance = 0;   // mean over pixels of p^2 / M: its photons' variance
        double cameraCost = 0;       // its camera pass and grid, in ray equivalents
        double photonCost = 0;       // its photon pass, in ray equivalents
    };
    // In camera rays (a ray cast and its vertex shaded, light sample included): a grid entry
    // built, and a visible point a photon tests on top of its own ray. photon-bench's
    // camera_ns_per_ray, grid_ns_per_entry and photon_ns_per_ray on the Cornell box, the
    // glass one and the textured mesh: 92-110 ns a camera ray, 24-26 ns an entry, 107-139 ns
    // a photon ray with 1.7-7.5 candidates (docs/sppm.md, "Photons per pass").
    static constexpr double kGridEntryCost = 0.25, kCandidateCost = 0.03;
    // The photons per pass move by at most this factor at a decision, and stay in
    // [kMinPhotons, kMaxPhotons] (a render started below kMinPhotons may stay there).
    static constexpr double kMaxStep = 4;
    static constexpr int64_t kMinPhotons = 1000, kMaxPhotons = 100'000'000;

    // The photons per pass a render started at `start` can trace after `passes` passes:
    // within kMaxStep of the last count at each decision made by then, and within the limits
    // (the start itself may lie outside them). What a checkpoint is checked against.
    struct Range {
        int64_t lo, hi;
    };
    static Range reachable(int64_t start, int64_t passes);

    void add(const Pass& pass);
    // Decisions fall after passes 4, 8, 16, ...: each on twice the passes of the last.
    static bool decidesAfter(int64_t passes) { return passes >= 4 && (passes & (passes - 1)) == 0; }
    // The photons per pass from here on, for a render now at `current` whose pass
    // estimates vary by `passVariance` (mean over pixels, luminance squared); `current`
    // unchanged until a pass has been added.
    int64_t next(int64_t current, double passVariance) const;

    void save(std::ostream& out) const;
    // Throws CheckpointError on values no render could have written.
    void restore(std::istream& in);

private:
    int64_t passes_ = 0, photons_ = 0;
    double photonVariance_ = 0;           // sum over passes of Pass::photonVariance
    double photonVarianceTimesPhotons_ = 0;  // ... times the pass's N: a, summed
    double cameraCost_ = 0, photonCost_ = 0;
};

}  // namespace photon
