#include "ball_in_half_spaces.h"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace photon {

namespace {

// The area of the part of a disc of radius rho at signed distance >= q from its centre
// along a direction in its plane: rho^2 acos(q / rho) - q sqrt(rho^2 - q^2).
double discBeyond(double rho, double q) {
    if (q >= rho) return 0.0;
    if (q <= -rho) return std::numbers::pi * rho * rho;
    return rho * rho * std::acos(q / rho) - q * std::sqrt(rho * rho - q * q);
}

// The volume of the ball of radius r (about the origin) beyond both planes, in double.
double beyondBoth(Vec3 ua, double ha, Vec3 ub, double hb, double r) {
    const double c = double(ua.x) * ub.x + double(ua.y) * ub.y + double(ua.z) * ub.z;
    const double s2 = std::max(0.0, 1.0 - c * c);
    if (s2 < 1e-10) {
        // Parallel planes: on the same side the nearer cap holds the farther, on opposite
        // sides (the centre between them) the caps are apart.
        if (c < 0) return 0.0;
        const double h = std::max(ha, hb);
        const double cap = h >= r ? 0.0 : (r - h) * (r - h) * (2 * r + h) * std::numbers::pi / 3;
        return cap;
    }
    // The nearest point beyond both lies on both planes when neither plane's own nearest
    // point is beyond the other: y = x ua + z ub with ua.y = ha, ub.y = hb.
    const bool aAlone = c * ha >= hb, bAlone = c * hb >= ha;
    const double nearest2 = aAlone   ? ha * ha
                            : bAlone ? hb * hb
                                     : (ha * ha + hb * hb - 2 * c * ha * hb) / s2;
    if (nearest2 >= r * r) return 0.0;
    // Slices z = ua.y in [ha, r], each a disc of radius sqrt(r^2 - z^2) whose points beyond
    // the second plane have, along the unit w in the slice (ub = c ua + s w), x >= (hb - c z) / s.
    // With z = r cos t the integrand r sin t * area is smooth but for the kinks where the
    // second plane leaves the disc: 12 Gauss-Legendre nodes on each of four pieces.
    static constexpr double kNodes[6] = {0.1252334085114689, 0.3678314989981802, 0.5873179542866175,
                                         0.7699026741943047, 0.9041172563704749, 0.9815606342467192};
    static constexpr double kWeights[6] = {0.2491470458134028, 0.2334925365383548, 0.2031674267230659,
                                           0.1600783285433462, 0.1069393259953184, 0.0471753363865118};
    const double s = std::sqrt(s2);
    const double tMax = std::acos(std::clamp(ha / r, -1.0, 1.0));
    double volume = 0;
    constexpr int kPieces = 4;
    for (int piece = 0; piece < kPieces; ++piece) {
        const double lo = tMax * piece / kPieces, hi = tMax * (piece + 1) / kPieces;
        const double mid = 0.5 * (lo + hi), half = 0.5 * (hi - lo);
        for (int i = 0; i < 6; ++i)
            for (double sign : {-1.0, 1.0}) {
                const double t = mid + sign * half * kNodes[i];
                const double z = r * std::cos(t), rho = r * std::sin(t);
                volume += half * kWeights[i] * r * std::sin(t) * discBeyond(rho, (hb - c * z) / s);
            }
    }
    return volume;
}

}  // namespace

float capShare(float h, float r) {
    if (!(h < r)) return 0.0f;
    const float a = r - std::max(h, -r);
    return a * a * (3.0f * r - a) / (4.0f * r * r * r);
}

float ballShareInside(const CuttingPlane& a, const CuttingPlane& b, float r) {
    float share = 1.0f - capShare(a.distance, r) - capShare(b.distance, r);
    if (a.distance < r && b.distance < r) {
        const double ball = 4.0 / 3.0 * std::numbers::pi * double(r) * r * r;
        share += float(beyondBoth(a.outward, a.distance, b.outward, b.distance, r) / ball);
    }
    return share;
}

}  // namespace photon
