#include "math/spherical_triangle.h"
#include <algorithm>
#include <cmath>

namespace photon {
namespace {

// In double: the formulas subtract nearly equal angles for small triangles.
struct D3 {
    double x, y, z;
};
D3 d3(Vec3 v) { return {v.x, v.y, v.z}; }
D3 operator-(D3 a, D3 b) { return {a.x - b.x, a.y - b.y, a.z - b.z}; }
D3 operator+(D3 a, D3 b) { return {a.x + b.x, a.y + b.y, a.z + b.z}; }
D3 operator*(D3 a, double s) { return {a.x * s, a.y * s, a.z * s}; }
double dot(D3 a, D3 b) { return a.x * b.x + a.y * b.y + a.z * b.z; }
D3 cross(D3 a, D3 b) { return {a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z, a.x * b.y - a.y * b.x}; }
double length(D3 a) { return std::sqrt(dot(a, a)); }
D3 normalize(D3 a) { return a * (1.0 / length(a)); }
double safeSqrt(double x) { return std::sqrt(std::max(0.0, x)); }
// The angle between unit vectors, accurate near 0 and pi too.
double angleBetween(D3 a, D3 b) {
    return dot(a, b) < 0 ? M_PI - 2 * std::asin(std::min(1.0, length(a + b) / 2))
                         : 2 * std::asin(std::min(1.0, length(b - a) / 2));
}
// v without its component along the unit vector w.
D3 gramSchmidt(D3 v, D3 w) { return v - w * dot(v, w); }

}  // namespace

float sphericalTriangleSolidAngle(Vec3 p, Vec3 v0, Vec3 v1, Vec3 v2) {
    const D3 a = d3(v0) - d3(p), b = d3(v1) - d3(p), c = d3(v2) - d3(p);
    const double la = length(a), lb = length(b), lc = length(c);
    const double numerator = dot(a, cross(b, c));
    const double denominator = la * lb * lc + dot(a, b) * lc + dot(a, c) * lb + dot(b, c) * la;
    return static_cast<float>(std::abs(2.0 * std::atan2(numerator, denominator)));
}

std::optional<Vec3> sampleSphericalTriangle(Vec3 p, Vec3 v0, Vec3 v1, Vec3 v2, Vec2 u) {
    const D3 a = normalize(d3(v0) - d3(p)), b = normalize(d3(v1) - d3(p)), c = normalize(d3(v2) - d3(p));
    D3 nab = cross(a, b), nbc = cross(b, c), nca = cross(c, a);
    if (dot(nab, nab) == 0 || dot(nbc, nbc) == 0 || dot(nca, nca) == 0) return std::nullopt;
    nab = normalize(nab), nbc = normalize(nbc), nca = normalize(nca);
    // The spherical triangle's angles at its vertices; its area is their sum minus pi.
    const double alpha = angleBetween(nab, nca * -1.0), beta = angleBetween(nbc, nab * -1.0),
                 gamma = angleBetween(nca, nbc * -1.0);
    const double areaPlusPi = alpha + beta + gamma;
    if (!(areaPlusPi > M_PI)) return std::nullopt;
    // The sub-triangle (a, b, c') of area u.x times the whole: c' on the arc from a to c.
    const double sampledPlusPi = M_PI + double(u.x) * (areaPlusPi - M_PI);
    const double cosAlpha = std::cos(alpha), sinAlpha = std::sin(alpha);
    const double sinPhi = std::sin(sampledPlusPi) * cosAlpha - std::cos(sampledPlusPi) * sinAlpha;
    const double cosPhi = std::cos(sampledPlusPi) * cosAlpha + std::sin(sampledPlusPi) * sinAlpha;
    const double k1 = cosPhi + cosAlpha, k2 = sinPhi - sinAlpha * dot(a, b);
    const double cosBp = std::clamp((k2 + (k2 * cosPhi - k1 * sinPhi) * cosAlpha) / ((k2 * sinPhi + k1 * cosPhi) * sinAlpha),
                                    -1.0, 1.0);
    const D3 towardC = gramSchmidt(c, a);
    if (dot(towardC, towardC) == 0) return std::nullopt;
    const D3 cp = a * cosBp + normalize(towardC) * safeSqrt(1 - cosBp * cosBp);
    // Then uniform along the arc from b to c', in the measure that keeps the density uniform.
    const double cosTheta = 1 - double(u.y) * (1 - dot(cp, b));
    const D3 towardCp = gramSchmidt(cp, b);
    if (dot(towardCp, towardCp) == 0) return std::nullopt;
    const D3 w = b * cosTheta + normalize(towardCp) * safeSqrt(1 - cosTheta * cosTheta);
    if (!std::isfinite(w.x + w.y + w.z)) return std::nullopt;
    const D3 wn = normalize(w);
    return Vec3(static_cast<float>(wn.x), static_cast<float>(wn.y), static_cast<float>(wn.z));
}

std::optional<Vec2> invertSphericalTriangleSample(Vec3 p, Vec3 v0, Vec3 v1, Vec3 v2, Vec3 w) {
    const D3 a = normalize(d3(v0) - d3(p)), b = normalize(d3(v1) - d3(p)), c = normalize(d3(v2) - d3(p));
    const D3 wd = normalize(d3(w));
    // The solid angle of the unit vectors' triangle (Van Oosterom & Strackee 1983).
    auto solidAngle = [](D3 x, D3 y, D3 z) {
        return std::abs(2.0 * std::atan2(dot(x, cross(y, z)), 1 + dot(x, y) + dot(x, z) + dot(y, z)));
    };
    const double whole = solidAngle(a, b, c);
    if (!(whole > 0)) return std::nullopt;
    // c': where the great circle through b and w meets the arc from a to c (sampling drew
    // the sub-triangle (a, b, c') first, then w on the arc from b to c').
    const D3 m = cross(b, wd), nac = cross(a, c);
    D3 cp = cross(nac, m);
    if (dot(m, m) < 1e-20 || dot(cp, cp) < 1e-20) return Vec2{0.0f, 0.0f};  // w is b
    cp = normalize(cp);
    if (dot(cp, a + c) < 0) cp = cp * -1.0;
    const double ux = solidAngle(a, b, cp) / whole;
    const double denominator = 1 - dot(cp, b);
    const double uy = denominator > 0 ? (1 - dot(wd, b)) / denominator : 0.0;
    return Vec2{static_cast<float>(std::clamp(ux, 0.0, 1.0)), static_cast<float>(std::clamp(uy, 0.0, 1.0))};
}

}  // namespace photon
