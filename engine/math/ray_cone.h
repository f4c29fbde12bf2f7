// The part of a ray inside a cone: where a spot light's beam, or any light that sends only
// into a cone, can light a point along the ray.
#pragma once
#include <algorithm>
#include <cmath>
#include <optional>
#include <photon/vec.h>

namespace photon {

struct RayInterval {
    float start, end;
};

// The t in [start, end] (end may be infinite) at which o + t d lies in the cone of apex a,
// unit axis n and half-angle acos(cosMax) (cosMax > 0: a convex cone, so one interval);
// none if the ray misses it there. On the cone, (p.n)^2 = cosMax^2 |p|^2 with p.n >= 0,
// p = o - a + t d: a quadratic in t, solved in double.
inline std::optional<RayInterval> rayInsideCone(Vec3 o, Vec3 d, float start, float end, Vec3 a, Vec3 n, float cosMax) {
    const double px = double(o.x) - a.x, py = double(o.y) - a.y, pz = double(o.z) - a.z;
    const double dn = double(d.x) * n.x + double(d.y) * n.y + double(d.z) * n.z;
    const double pn = px * n.x + py * n.y + pz * n.z;
    const double dp = d.x * px + d.y * py + d.z * pz, pp = px * px + py * py + pz * pz;
    const double dd = double(d.x) * d.x + double(d.y) * d.y + double(d.z) * d.z;
    const double c2 = double(cosMax) * cosMax;
    // f(t) = (pn + t dn)^2 - c2 |p + t d|^2 >= 0 inside the double cone.
    const double qa = dn * dn - c2 * dd, qb = 2 * (pn * dn - c2 * dp), qc = pn * pn - c2 * pp;
    double lo = start, hi = end;
    // The forward nappe: pn + t dn >= 0.
    if (dn > 0) lo = std::max(lo, -pn / dn);
    else if (dn < 0) hi = std::min(hi, -pn / dn);
    else if (pn < 0) return std::nullopt;
    if (std::abs(qa) < 1e-12) {
        // f is linear (the ray parallel to the cone's side): f >= 0 on a half-line.
        if (qb > 0) lo = std::max(lo, -qc / qb);
        else if (qb < 0) hi = std::min(hi, -qc / qb);
        else if (qc < 0) return std::nullopt;
    } else {
        const double disc = qb * qb - 4 * qa * qc;
        if (disc < 0) {
            if (qa < 0) return std::nullopt;  // f < 0 everywhere
        } else {
            const double r = std::sqrt(disc);
            // Roots without cancellation (Numerical Recipes 5.6).
            const double q = -0.5 * (qb + (qb >= 0 ? r : -r));
            double t1 = q / qa, t2 = q != 0 ? qc / q : t1;
            if (t1 > t2) std::swap(t1, t2);
            if (qa < 0) {
                lo = std::max(lo, t1), hi = std::min(hi, t2);  // f >= 0 between the roots
            } else if (lo < t1 && hi > t2) {
                // f >= 0 outside the roots, and the forward nappe takes one side: the half of
                // [lo, hi] where f is positive at its middle.
                const double below = 0.5 * (lo + t1), above = std::isinf(hi) ? t2 + 1 : 0.5 * (t2 + hi);
                auto f = [&](double t) { return (qa * t + qb) * t + qc; };
                if (f(below) >= 0 && (pn + below * dn) >= 0) hi = t1;
                else if (f(above) >= 0 && (pn + above * dn) >= 0) lo = t2;
                else return std::nullopt;
            } else if (lo >= t1 && hi <= t2) {
                return std::nullopt;  // all of it between the roots, where f < 0
            } else if (lo < t1) {
                hi = std::min(hi, t1);
            } else {
                lo = std::max(lo, t2);
            }
        }
    }
    if (!(hi > lo)) return std::nullopt;
    return RayInterval{static_cast<float>(lo), static_cast<float>(hi)};
}

}  // namespace photon
