// Orthonormal frames: shading happens in a local frame whose z axis is the normal.
#pragma once
#include "vec.h"

namespace photon {

struct Frame {
    Vec3 s, t, n;

    // Branchless basis from a unit normal: Duff et al. 2017, "Building an Orthonormal
    // Basis, Revisited", JCGT 6(1). Deterministic, so a frame rebuilt from a stored
    // normal matches the one the camera pass used.
    static Frame fromNormal(Vec3 n) {
        float sign = std::copysign(1.0f, n.z);
        float a = -1.0f / (sign + n.z);
        float b = n.x * n.y * a;
        return {{1.0f + sign * n.x * n.x * a, sign * b, -sign * n.x}, {b, sign + n.y * n.y * a, -n.y}, n};
    }
    Vec3 toLocal(Vec3 v) const { return {dot(v, s), dot(v, t), dot(v, n)}; }
    Vec3 toWorld(Vec3 v) const { return s * v.x + t * v.y + n * v.z; }
};

// Local-frame helpers (z is the normal).
inline float cosTheta(Vec3 w) { return w.z; }
inline float absCosTheta(Vec3 w) { return std::abs(w.z); }
inline bool sameHemisphere(Vec3 a, Vec3 b) { return a.z * b.z > 0; }

}  // namespace photon
