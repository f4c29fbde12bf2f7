#include "lights/light_bounds.h"
#include <algorithm>
#include <cmath>
#include "math/lanes.h"

namespace photon {
namespace {

// cos(max(0, a - b)) from the angles' sines and cosines (both in [0, pi]).
float cosOfDifferenceClamped(float sinA, float cosA, float sinB, float cosB) {
    if (cosA > cosB) return 1.0f;  // a < b
    return cosA * cosB + sinA * sinB;
}
float sinOfDifferenceClamped(float sinA, float cosA, float sinB, float cosB) {
    if (cosA > cosB) return 0.0f;
    return sinA * cosB - cosA * sinB;
}

}  // namespace

LightImportance::LightImportance(const LightBounds& b)
    : centre_((b.lo + b.hi) * 0.5f), axis_(b.axis), intensity_(b.intensity), cosThetaO_(b.cosThetaO),
      sinThetaO_(safeSqrt(1.0f - b.cosThetaO * b.cosThetaO)), cosThetaE_(b.cosThetaE), twoSided_(b.twoSided) {
    radius2_ = lengthSquared(b.hi - centre_);
    radius_ = std::sqrt(radius2_);
}

float LightImportance::operator()(Vec3 p, Vec3 n) const {
    const float d2 = lengthSquared(p - centre_);
    const float inverseD = d2 > 0 ? 1.0f / std::sqrt(d2) : 0.0f;
    // The cone of directions from p that hold the box's bounding sphere; all of them when p
    // is inside it.
    float cosThetaB = -1, sinThetaB = 0;
    if (d2 > radius2_) {
        sinThetaB = radius_ * inverseD;
        cosThetaB = safeSqrt(1.0f - sinThetaB * sinThetaB);
    }
    const Vec3 fromLight = d2 > 0 ? (p - centre_) * inverseD : Vec3(0, 0, 1);

    // The emitter's side: the smallest angle between an emitting direction and a direction
    // toward p.
    float cosThetaW = dot(axis_, fromLight);
    if (twoSided_) cosThetaW = std::abs(cosThetaW);
    const float sinThetaW = safeSqrt(1.0f - cosThetaW * cosThetaW);
    const float cosThetaX = cosOfDifferenceClamped(sinThetaW, cosThetaW, sinThetaO_, cosThetaO_);
    const float sinThetaX = sinOfDifferenceClamped(sinThetaW, cosThetaW, sinThetaO_, cosThetaO_);
    const float cosThetaP = cosOfDifferenceClamped(sinThetaX, cosThetaX, sinThetaB, cosThetaB);
    // Strictly beyond: a hard-edged spot (thetaE 0, cosThetaE 1) still lights its cone.
    if (cosThetaP < cosThetaE_) return 0.0f;

    float result = intensity_ * cosThetaP / std::max(d2, radius2_);
    if (n.x != 0 || n.y != 0 || n.z != 0) {
        // The receiver's side: the smallest angle between n and a direction into the box.
        const float cosThetaI = -dot(fromLight, n);
        const float sinThetaI = safeSqrt(1.0f - cosThetaI * cosThetaI);
        const float cosBound = cosOfDifferenceClamped(sinThetaI, cosThetaI, sinThetaB, cosThetaB);
        if (!(cosBound > 0)) return 0.0f;
        result *= cosBound;
    }
    return std::max(result, 0.0f);
}

}  // namespace photon
