// render.adaptive_radius: each pixel's gather radius shrinks as far as the bias its own
// photons show asks for, not by one schedule for all (after Kaplanyan & Dachsbacher 2013,
// "Adaptive Progressive Photon Mapping", who choose the radius that balances the estimate's
// bias, from the Laplacian of the radiance, against its variance).
//
// The bias and the Laplacian come from where in the disc the photons fall. A disc of radius
// r over a radiance L(x) = L0 + g.x + x^T H x / 2 (x in the surface's plane) gathers in
// proportion to its integral pi r^2 (L0 + dL r^2 / 8), dL = trace H the Laplacian, so the
// uniform kernel's estimate is too high by dL r^2 / 8. Its photons' mean of s = |x|^2 / r^2
// is (L0 / 2 + dL r^2 / 12) / (L0 + dL r^2 / 8): 1/2 where the light is flat, and
// s - 1/2 = dL r^2 / (48 L) to first order, so beta = dL / L = 48 (s - 1/2) / r^2 with no
// flux or count in it. A disc that a surface's edge cuts has photons on one side only and
// reads as curved too, which is the bias the disc has there (it divides by the whole of it);
// but an edge through the disc's centre leaves the mean at 1/2. So a photon on a surface
// that faces elsewhere within the disc's sphere (the other wall of a corner, the side of a
// box), which the disc turns away, adds 1 to the sum, as one at the rim would, and is not
// counted: with the corner through the centre the mean reads 3/2 (clamped to 1) and the
// radius shrinks as fast as it may. Without it the Cornell box's regions along its corners
// came out 2.1% dark at 64 x 64 where alpha's schedule keeps them within 2%. With
// render.disc_coverage (disc_coverage.h) such a photon instead marks the disc, whose
// measured share corrects the estimate and the mean s it is read against.
//
// With n photons in the disc the estimate's relative variance is about 1 / n, so c / r^2
// with c = r^2 / n; its relative bias is beta r^2 / 8. The squared error
// (beta rho / 8)^2 + c / rho of a squared radius rho is least at rho^3 = 32 c / beta^2.
// Each pass the pixel's radius goes there, but never grows (the flux within a radius is all
// a pixel keeps) and shrinks at most as fast as the schedule with alpha / 2 would; the
// photon count and flux follow it as in Hachisuka & Jensen's update (N' = (N + M) R'^2 / R^2,
// which alpha's rule is a case of). As photons accumulate c falls as 1 / N and the radius
// with it, r ~ passes^(-1/6) where beta is not 0: bias and variance both go to 0.
// Everything is per pixel and in a fixed order: the same for a seed on any thread count.
#pragma once
#include <cstdint>
#include <istream>
#include <ostream>
#include <vector>

namespace photon {

// The photons' mean s = d^2 / r^2 in a disc, as a pass's results keep it in one byte.
struct PhotonSpread {
    // A visible point sums its photons' s in units of 2^-11 in 32 bits: exact up to 2^21
    // photons in one disc in one pass, after which the mean is not known.
    static constexpr float kUnitsPerPhoton = 2048.0f;
    static constexpr uint8_t kUnknown = 255;
    // The mean over `photons` photons of units summed as above (those turned away
    // included), within [0, 1], in 1/254 (kUnknown: none, or too many to have summed).
    static uint8_t of(uint32_t units, uint32_t photons);
    static float mean(uint8_t code) { return static_cast<float>(code) / 254.0f; }
    // A mean as that byte, clamped to [0, 1].
    static uint8_t code(double mean);
};

// beta = dL / L from photons' mean spread s in a disc of squared radius r2 (above).
inline float relativeLaplacian(float meanSpread, float r2) { return 48.0f * (meanSpread - 0.5f) / r2; }

// The squared radius that balances bias against variance for n photons in a disc of r2
// where the radiance's relative Laplacian is beta: (32 r2 / (n beta^2))^(1/3) (above).
float balancedRadiusSquared(float r2, float n, float beta);

class AdaptiveRadius {
public:
    AdaptiveRadius() = default;
    AdaptiveRadius(int width, int height)
        : width_(width), height_(height), moments_(static_cast<size_t>(width) * height) {}

    // A pass's m photons at `pixel`, in a disc of squared radius r2, with their spread.
    void add(size_t pixel, uint32_t m, uint8_t spread, float r2);
    // The factor R'^2 / R^2 for `pixel` after a pass that put m photons in its disc of r2,
    // where n were counted before: the balanced radius, within [the factor of alpha / 2's
    // schedule, 1]; alpha's own schedule until the pixel and its neighbours have seen
    // kWarmUpPhotons photons. Call after add() of the pass, reading every pixel's moments.
    float shrink(size_t pixel, float n, float m, float r2, float alpha) const;

    void save(std::ostream& out) const;
    // Reads the block save() wrote if the stream is at one, else starts anew; throws
    // CheckpointError on a damaged block.
    void restore(std::istream& in);

    static constexpr float kWarmUpPhotons = 64;
    static constexpr size_t kBytesPerPixel = 8;

private:
    // Summed over every pass with photons of a known spread, none discounted: a running mean
    // weighted by N instead (4 bytes a pixel, older passes weighing less as N shrinks) read
    // the Laplacian through fewer photons, its noise shrank the radii, and the noise at 30 s
    // rose from 0.0163 to 0.0186 on the Bitterli Cornell box at 256², 0.0075 to 0.0099 at 64².
    struct Moments {
        float laplacian = 0;  // sum over passes of m beta_pass, beta_pass from that pass's spread
        float photons = 0;    // sum of those passes' m
    };
    int width_ = 0, height_ = 0;
    std::vector<Moments> moments_;
    static_assert(sizeof(Moments) == kBytesPerPixel);
};

}  // namespace photon
