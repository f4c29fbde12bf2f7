// Stochastic progressive photon mapping (Hachisuka & Jensen 2009), with the radius
// schedule of Knaus & Zwicker 2011's probabilistic formulation. Each pass: a camera pass
// finds one visible point per pixel, a hash grid is built over them, photons are traced
// and splatted into the visible points around their hits, and per-pixel statistics are
// updated. Photons are never stored, so memory does not grow with their number.
#pragma once
#include <mutex>
#include <vector>
#include "../accel/hash_grid.h"
#include "../math/octahedral.h"
#include "../math/rng.h"
#include "../scene/scene.h"
#include "integrator.h"

namespace photon {

class SppmIntegrator final : public Integrator {
public:
    explicit SppmIntegrator(std::shared_ptr<const Scene> scene);

    bool renderPass(const CancelToken& cancel) override;
    Image snapshot() const override;
    const PassStats& lastPassStats() const override { return stats_; }
    int passesDone() const override { return passes_; }
    size_t bytesPerPixel() const override;

    // Persistent per-pixel statistics (the paper's N, R, tau) plus summed direct light.
    struct PixelState {
        Color directSum;  // sum over passes of direct radiance at the camera path
        Color tau;        // flux accumulated within the current radius
        float n = 0;      // photon count N after the alpha reduction
        float r2 = 0;     // squared gather radius; 0 until the pixel first sees a surface
    };
    const PixelState& pixel(int x, int y) const { return pixels_[static_cast<size_t>(y) * width_ + x]; }
    // Photons gathered by each pixel in the last pass (M in the paper), for tests.
    uint32_t lastPhotonCount(int x, int y) const { return photonCount_[static_cast<size_t>(y) * width_ + x]; }

private:
    // The first non-specular vertex of a pixel's camera path in this pass.
    struct VisiblePoint {
        Vec3 p;
        OctahedralVector n;        // shading normal
        OctahedralVector woLocal;  // outgoing direction in the frame of n
        Color beta;        // camera path throughput up to here
        Color tint;        // material colour at the hit
        float r2 = 0;      // gather radius for this pass (0: no visible point)
        uint32_t material = 0;
    };

    // Fixed-point scale for the photon flux sums: 2^32 units per unit of normalised flux
    // (photons start with a mean flux of 1), so sums are exact integers whatever the order
    // threads add them in, and the image is bit-identical for any thread count.
    static constexpr double kFluxScale = 4294967296.0;

    void cameraPass(const CancelToken& cancel);
    void tracePixel(size_t index, Rng& rng);
    float autoRadius(float pathLength) const;
    void buildGrid();
    void photonPass(const CancelToken& cancel);
    void tracePhoton(int64_t index, int64_t& segments);
    void deposit(Vec3 p, Vec3 n, Vec3 wi, Color flux);
    void updateStatistics();

    std::shared_ptr<const Scene> scene_;
    const RenderSettings& settings_;
    int width_, height_;
    int passes_ = 0;
    PassStats stats_;

    std::vector<PixelState> pixels_;
    std::vector<VisiblePoint> visible_;
    std::vector<Color> passDirect_;      // direct light found by this pass's camera paths
    std::vector<uint64_t> passFlux_;     // fixed-point flux sums, 3 per pixel, atomically added
    std::vector<uint32_t> photonCount_;  // M per pixel, atomically added
    HashGrid grid_;
    mutable std::mutex stateMutex_;      // guards pixels_ and passes_ between update and snapshot
};

}  // namespace photon
