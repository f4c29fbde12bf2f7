// Rays and the offset that keeps a spawned ray from hitting its own surface.
#pragma once
#include <limits>
#include "math/lanes.h"
#include <photon/vec.h>

namespace photon {

struct Ray {
    Vec3 o, d;
    float tMax = std::numeric_limits<float>::infinity();
};

// Moves p off its surface along the geometric normal, to the side `w` points to.
// The offset grows with |p| because float error in the hit point does (pbrt-v4 6.8.6
// bounds it properly; a relative epsilon is enough for the scene scales we accept).
template <class F>
PHOTON_LANES_INLINE F rayOffsetDistance(F px, F py, F pz) {
    return 2e-5f * (1.0f + maxValue(absValue(px), maxValue(absValue(py), absValue(pz))));
}
inline Vec3 offsetRayOrigin(Vec3 p, Vec3 ng, Vec3 w) {
    float eps = rayOffsetDistance(p.x, p.y, p.z);
    return dot(w, ng) >= 0 ? p + ng * eps : p - ng * eps;
}

inline Ray spawnRay(Vec3 p, Vec3 ng, Vec3 w) { return {offsetRayOrigin(p, ng, w), w}; }

// A shadow ray from p toward the point q, stopping just short of it.
inline Ray spawnRayTo(Vec3 p, Vec3 ng, Vec3 q) {
    Vec3 o = offsetRayOrigin(p, ng, q - p);
    Vec3 d = q - o;
    float dist = length(d);
    return {o, d / dist, dist * (1.0f - 1e-4f)};
}

}  // namespace photon
