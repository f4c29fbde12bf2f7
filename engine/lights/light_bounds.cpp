#include "lights/light_bounds.h"
#include <algorithm>
#include <cmath>
#include "math/lanes.h"

namespace photon {
namespace {

// One light's bounds as importance() reads them: floats, or eight lights' in lanes.
template <class F, class M>
struct BoundsOf {
    F cx, cy, cz;  // the box's centre
    F hx, hy, hz;  // and half its extent
    F ax, ay, az;  // the cone's axis
    F radius, radius2, intensity, cosThetaO, sinThetaO, cosThetaE;
    M twoSided;
};

// cos(max(0, a - b)) and sin(max(0, a - b)) from the angles' sines and cosines (both in
// [0, pi]): a < b where cosA > cosB.
template <class F>
PHOTON_LANES_INLINE F cosOfDifferenceClamped(F sinA, F cosA, F sinB, F cosB) {
    return select(cosA > cosB, broadcast<F>(1.0f), cosA * cosB + sinA * sinB);
}
template <class F>
PHOTON_LANES_INLINE F sinOfDifferenceClamped(F sinA, F cosA, F sinB, F cosB) {
    return select(cosA > cosB, broadcast<F>(0.0f), sinA * cosB - cosA * sinB);
}

// importance(), written once for one light and for eight: the same
// operations in the same order, so a light's figure does not depend on which code asks.
template <class F, class M>
PHOTON_LANES_INLINE F importanceAt(const BoundsOf<F, M>& b, Vec3 p, Vec3 n) {
    const F dx = p.x - b.cx, dy = p.y - b.cy, dz = p.z - b.cz;
    const F d2 = dx * dx + dy * dy + dz * dz;
    const M positive = d2 > 0.0f;
    const F inverseD = select(positive, 1.0f / safeSqrt(d2), broadcast<F>(0.0f));
    // The cone of directions from p that hold the box's bounding sphere; all of them when p
    // is inside it.
    const M outside = d2 > b.radius2;
    const F sinThetaBOutside = b.radius * inverseD;
    const F sinThetaB = select(outside, sinThetaBOutside, broadcast<F>(0.0f));
    const F cosThetaB = select(outside, safeSqrt(1.0f - sinThetaBOutside * sinThetaBOutside), broadcast<F>(-1.0f));
    const F fx = select(positive, dx * inverseD, broadcast<F>(0.0f));
    const F fy = select(positive, dy * inverseD, broadcast<F>(0.0f));
    const F fz = select(positive, dz * inverseD, broadcast<F>(1.0f));

    // The emitter's side: the smallest angle between an emitting direction and a direction
    // toward p.
    F cosThetaW = b.ax * fx + b.ay * fy + b.az * fz;
    cosThetaW = select(b.twoSided, absValue(cosThetaW), cosThetaW);
    const F sinThetaW = safeSqrt(1.0f - cosThetaW * cosThetaW);
    const F cosThetaX = cosOfDifferenceClamped(sinThetaW, cosThetaW, b.sinThetaO, b.cosThetaO);
    const F sinThetaX = sinOfDifferenceClamped(sinThetaW, cosThetaW, b.sinThetaO, b.cosThetaO);
    const F cosThetaP = cosOfDifferenceClamped(sinThetaX, cosThetaX, sinThetaB, cosThetaB);

    F result = b.intensity * cosThetaP / maxValue(d2, b.radius2);
    if (n.x != 0 || n.y != 0 || n.z != 0) {
        // The receiver's side: the smallest angle between n and a direction into the box.
        const F cosThetaI = -(fx * n.x + fy * n.y + fz * n.z);
        const F sinThetaI = safeSqrt(1.0f - cosThetaI * cosThetaI);
        const F cosBound = cosOfDifferenceClamped(sinThetaI, cosThetaI, sinThetaB, cosThetaB);
        // The box's highest corner above the receiver's plane: none above it, no light can
        // reach the side n faces. The bounding sphere's cone alone lets a light lying below
        // a floor but within the sphere's radius of it count (half the picks of a wall light
        // reaching down past the floor went below it, tests/test_area_light_horizon.cpp).
        const F highest = (b.cx - p.x) * n.x + (b.cy - p.y) * n.y + (b.cz - p.z) * n.z + b.hx * std::fabs(n.x) +
                          b.hy * std::fabs(n.y) + b.hz * std::fabs(n.z);
        result = select(cosBound > 0.0f, result * cosBound, broadcast<F>(0.0f));
        result = select(highest > 0.0f, result, broadcast<F>(0.0f));
    }
    // Strictly beyond: a hard-edged spot (thetaE 0, cosThetaE 1) still lights its cone.
    result = select(cosThetaP < b.cosThetaE, broadcast<F>(0.0f), result);
    return maxValue(result, broadcast<F>(0.0f));
}

// What importanceAt reads of one light's bounds, derived once.
BoundsOf<float, bool> prepared(const LightBounds& b) {
    const Vec3 centre = (b.lo + b.hi) * 0.5f;
    const float radius2 = lengthSquared(b.hi - centre);
    const Vec3 half = (b.hi - b.lo) * 0.5f;
    return {centre.x,    centre.y,   centre.z,
            half.x,      half.y,     half.z,
            b.axis.x,    b.axis.y,   b.axis.z,
            std::sqrt(radius2),      radius2,
            b.intensity, b.cosThetaO, safeSqrt(1.0f - b.cosThetaO * b.cosThetaO),
            b.cosThetaE, b.twoSided};
}

PHOTON_LANES_INLINE void importancesLanes(const LightImportances::Columns& c, size_t first, size_t count, Vec3 p, Vec3 n,
                                          float* out) {
    for (size_t k = 0; k < count; k += kLanes) {
        const size_t i = first + k;
        auto load = [&](const std::vector<float>& column) PHOTON_LANES_LAMBDA { return loadLanes<float, FloatLanes>(column.data() + i); };
        BoundsOf<FloatLanes, IntLanes> b{load(c.cx),        load(c.cy),        load(c.cz),
                                         load(c.hx),        load(c.hy),        load(c.hz),         load(c.ax),
                                         load(c.ay),        load(c.az),        load(c.radius),     load(c.radius2),
                                         load(c.intensity), load(c.cosThetaO), load(c.sinThetaO), load(c.cosThetaE),
                                         loadLanes<int32_t, IntLanes>(c.twoSided.data() + i)};
        storeLanes(out + k, importanceAt(b, p, n));
    }
}
PHOTON_LANES_KERNEL(importancesInLanes, importancesLanes,
                    (const LightImportances::Columns& c, size_t first, size_t count, Vec3 p, Vec3 n, float* out),
                    (c, first, count, p, n, out))

}  // namespace

float importance(const LightBounds& b, Vec3 p, Vec3 n) { return importanceAt(prepared(b), p, n); }

LightImportances::LightImportances(const std::vector<LightBounds>& bounds, const std::vector<uint32_t>* order)
    : size_(order ? order->size() : bounds.size()) {
    // Room for a last group of eight read whole from any first light.
    const size_t padded = size_ + kLanes;
    for (std::vector<float>* column : {&c_.cx, &c_.cy, &c_.cz, &c_.hx, &c_.hy, &c_.hz, &c_.ax, &c_.ay, &c_.az, &c_.radius, &c_.radius2,
                                       &c_.intensity, &c_.cosThetaO, &c_.sinThetaO, &c_.cosThetaE})
        column->assign(padded, 0.0f);
    c_.radius2.assign(padded, 1.0f);  // the padding's figure stays finite (0 / 1)
    c_.twoSided.assign(padded, 0);
    for (size_t i = 0; i < size_; ++i) {
        const BoundsOf<float, bool> b = prepared(bounds[order ? (*order)[i] : i]);
        c_.cx[i] = b.cx, c_.cy[i] = b.cy, c_.cz[i] = b.cz;
        c_.hx[i] = b.hx, c_.hy[i] = b.hy, c_.hz[i] = b.hz;
        c_.ax[i] = b.ax, c_.ay[i] = b.ay, c_.az[i] = b.az;
        c_.radius[i] = b.radius, c_.radius2[i] = b.radius2, c_.intensity[i] = b.intensity;
        c_.cosThetaO[i] = b.cosThetaO, c_.sinThetaO[i] = b.sinThetaO, c_.cosThetaE[i] = b.cosThetaE;
        c_.twoSided[i] = b.twoSided ? -1 : 0;
    }
}

float LightImportances::evaluate(size_t first, size_t count, Vec3 p, Vec3 n, float* out) const {
    float sum = 0;
    for (size_t k = 0; k < count; k += kGroup) {
        float group[kGroup];
        const size_t inGroup = std::min(kGroup, count - k);
        importancesInLanes(c_, first + k, inGroup, p, n, group);
        for (size_t j = 0; j < inGroup; ++j) sum += out[k + j] = group[j];
    }
    return sum;
}

}  // namespace photon
