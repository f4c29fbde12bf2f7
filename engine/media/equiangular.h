// Equiangular sampling of a distance along a ray toward a point (Kulla & Fajardo 2012,
// "Importance Sampling Techniques for Path Tracing in Participating Media", sec. 4.1): the
// distance t along o + t d, t in [0, length], drawn with density proportional to
// 1 / |o + t d - y|^2, the falloff of a point light's irradiance at y, so that the light a
// medium scatters near a point light is found where it is, not where free flights happen to
// stop. With D the ray's distance from y and foot its nearest point's t, the angle
// theta = atan((t - foot) / D) is uniform over [thetaA, thetaB]:
//     t = foot + D tan(theta),   pdf(t) = D / ((thetaB - thetaA) (D^2 + (t - foot)^2)).
#pragma once
#include <cmath>
#include <optional>
#include <photon/vec.h>

namespace photon {

struct EquiangularDistances {
    float foot = 0;      // t of the ray's point nearest y
    float distance = 0;  // D, from y to that point
    float thetaA = 0, thetaB = 0;

    // For the segment [start, end] (end infinite: the ray leaves the scene) of the ray
    // o + t d (|d| = 1); none where the ray passes through y (D = 0) or the segment is empty.
    static std::optional<EquiangularDistances> toward(Vec3 o, Vec3 d, float start, float end, Vec3 y) {
        const Vec3 toY = y - o;
        const float foot = dot(toY, d);
        const float distance = length(toY - d * foot);
        if (!(distance > 1e-6f * std::max(1.0f, std::abs(foot))) || !(end > start)) return std::nullopt;
        const float thetaA = std::atan2(start - foot, distance);
        const float thetaB = std::isinf(end) ? 1.57079632679489662f : std::atan2(end - foot, distance);
        if (!(thetaB > thetaA)) return std::nullopt;
        return EquiangularDistances{foot, distance, thetaA, thetaB};
    }
    // The distance drawn with u in [0, 1) (within the segment, up to rounding at its ends).
    float sample(float u) const {
        const float theta = thetaA + u * (thetaB - thetaA);
        return std::max(0.0f, foot + distance * std::tan(theta));
    }
    float pdf(float t) const {
        const float x = t - foot;
        return distance / ((thetaB - thetaA) * (distance * distance + x * x));
    }
};

}  // namespace photon
