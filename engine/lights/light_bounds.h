// Where a finite light is and which way it shines, bounded: enough to say from a point how
// much light could at most arrive from it, up to a constant, without sampling it. After
// pbrt-v4's LightBounds (Pharr, Jakob & Humphreys, 4th ed., sec. 12.6.3), from Conty Estevez
// & Kulla 2018 ("Importance sampling of many lights with adaptive tree splitting").
#pragma once
#include <cstdint>
#include <vector>
#include <photon/vec.h>

namespace photon {

struct LightBounds {
    Vec3 lo, hi;            // a box around every point that emits
    float intensity = 0;    // radiant intensity along the emission axis, mean over channels (W/sr)
    Vec3 axis{0, 0, 1};     // unit; every emitting normal (or spot direction) is within thetaO of it
    float cosThetaO = -1;   // -1: any direction
    float cosThetaE = 0;    // light leaves each normal at most thetaE away (pi/2 for diffuse: 0)
    bool twoSided = false;  // emits about -axis as well

};

// How much light could reach p from a light with bounds b, in proportion to the irradiance
// there: intensity over the squared distance to the box's centre, times a bound on the
// emitter's cosine (thetaW, the angle of p from the axis, less thetaO and the angle the box
// subtends) and, when n is not zero, on the receiver's cosine about n (one-sided: 0 when the
// whole box is at or below the horizon of n). Conservative: 0 only where no light can arrive
// from above n. The squared distance is kept above the box's half diagonal squared, so a
// point in or near the box does not make its light's importance unbounded.
float importance(const LightBounds& b, Vec3 p, Vec3 n);

// Many lights' bounds, asked eight at a time in SIMD lanes (math/lanes.h) with the
// arithmetic of importance(), so that each light's figure is the same to the bit whichever
// asks. What the exhaustive light sampler and the light tree's leaves evaluate at every
// shadow ray.
class LightImportances {
public:
    LightImportances() = default;
    // Light i's bounds are bounds[order[i]] (bounds[i] without an order).
    explicit LightImportances(const std::vector<LightBounds>& bounds, const std::vector<uint32_t>* order = nullptr);
    size_t size() const { return size_; }

    // The importances at p (as importance()) of lights [first, first + count), into
    // out[0, count); their sum, added in order.
    float evaluate(size_t first, size_t count, Vec3 p, Vec3 n, float* out) const;

    // The bounds by field, each padded by a group of lanes.
    struct Columns {
        std::vector<float> cx, cy, cz, hx, hy, hz, ax, ay, az, radius, radius2, intensity, cosThetaO, sinThetaO, cosThetaE;
        std::vector<int32_t> twoSided;  // -1 true, 0 false
    };

private:
    static constexpr size_t kGroup = 16;  // lights evaluated per call of the lanes' kernel
    Columns c_;
    size_t size_ = 0;
};

}  // namespace photon
