// Orthonormal frames: shading happens in a local frame whose z axis is the normal.
#pragma once
#include "math/lanes.h"
#include <photon/vec.h>

namespace photon {

// s and t completing the unit normal n to a right-handed basis: Duff et al. 2017, "Building
// an Orthonormal Basis, Revisited", JCGT 6(1). F: float or FloatLanes.
template <class F>
PHOTON_LANES_INLINE void orthonormalBasis(F nx, F ny, F nz, F& sx, F& sy, F& sz, F& tx, F& ty, F& tz) {
    F sign = signOf(nz);
    F a = -1.0f / (sign + nz);
    F b = nx * ny * a;
    sx = 1.0f + sign * nx * nx * a;
    sy = sign * b;
    sz = -sign * nx;
    tx = b;
    ty = sign + ny * ny * a;
    tz = -ny;
}

struct Frame {
    Vec3 s, t, n;

    // Branchless, so deterministic: a frame rebuilt from a stored normal matches the one
    // the camera pass used.
    static Frame fromNormal(Vec3 n) {
        Frame f{{}, {}, n};
        orthonormalBasis(n.x, n.y, n.z, f.s.x, f.s.y, f.s.z, f.t.x, f.t.y, f.t.z);
        return f;
    }
    // s along the tangent's part across n (Gram-Schmidt); the normal's own frame where the
    // tangent is zero or parallel to n.
    static Frame fromNormalAndTangent(Vec3 n, Vec3 tangent) {
        const Vec3 across = tangent - n * dot(tangent, n);
        const float len2 = dot(across, across);
        if (!(len2 > 1e-12f * dot(tangent, tangent)) || !(len2 > 0)) return fromNormal(n);
        const Vec3 s = across * (1.0f / std::sqrt(len2));
        return {s, cross(n, s), n};
    }
    Vec3 toLocal(Vec3 v) const { return {dot(v, s), dot(v, t), dot(v, n)}; }
    Vec3 toWorld(Vec3 v) const { return s * v.x + t * v.y + n * v.z; }
};

// Local-frame helpers (z is the normal).
inline float cosTheta(Vec3 w) { return w.z; }
inline float absCosTheta(Vec3 w) { return std::abs(w.z); }
inline bool sameHemisphere(Vec3 a, Vec3 b) { return a.z * b.z > 0; }

}  // namespace photon
