// The Beckmann microfacet distribution (Beckmann & Spizzichino 1963; Walter et al. 2007,
// sec. 5.1): Gaussian slopes, anisotropic with alphaX along the local frame's x axis and
// alphaY along y. At the same alpha its tails fall off as exp(-tan^2 theta / alpha^2) where
// GGX's fall as a power law, so a bright light reflected in a Beckmann metal leaves the rest
// of the surface dark where GGX spreads a glow over it. Mitsuba (its default) and Tungsten
// scenes often ask for it. Same interface as GGX (microfacet.h); vectors in the local
// shading frame (z = macro normal).
#pragma once
#include <cmath>
#include "materials/microfacet.h"

namespace photon {

struct Beckmann : MicrofacetLobe<Beckmann> {
    explicit Beckmann(float alpha) : MicrofacetLobe(alpha, alpha) {}
    Beckmann(float alphaX_, float alphaY_) : MicrofacetLobe(alphaX_, alphaY_) {}

    // D(h) = exp(-(h.x^2/ax^2 + h.y^2/ay^2) / h.z^2) / (pi ax ay h.z^4): Walter et al. 2007,
    // eq. 25, with tan^2 theta (cos^2 phi/ax^2 + sin^2 phi/ay^2) written in h's components.
    float D(Vec3 h) const {
        if (h.z <= 0) return 0;
        float z2 = h.z * h.z;
        float slope2 = (h.x * h.x / (alphaX * alphaX) + h.y * h.y / (alphaY * alphaY)) / z2;
        return std::exp(-slope2) / (kPi * alphaX * alphaY * z2 * z2);
    }

    // Smith Lambda for Beckmann, exact: (erf(a) - 1) / 2 + exp(-a^2) / (2 a sqrt(pi)) with
    // a = 1 / (alpha(w) tan theta) and the anisotropic alpha(w)^2 tan^2 theta =
    // (ax^2 w.x^2 + ay^2 w.y^2) / w.z^2 (Heitz 2014, eqs. 80 and 84). In double: at large a
    // the two terms nearly cancel.
    float lambda(Vec3 w) const {
        double z2 = double(w.z) * w.z;
        if (z2 == 0) return INFINITY;
        double alpha2Tan2 = (double(alphaX) * alphaX * w.x * w.x + double(alphaY) * alphaY * w.y * w.y) / z2;
        if (alpha2Tan2 == 0) return 0;
        double a = 1.0 / std::sqrt(alpha2Tan2);
        constexpr double kSqrtPi = 1.7724538509055160;
        return float(std::max(0.0, 0.5 * (std::erf(a) - 1.0) + std::exp(-a * a) / (2.0 * a * kSqrtPi)));
    }

    // Samples a normal with density D(h) h.z (Walter et al. 2007, eqs. 28-29; the
    // anisotropic azimuth as pbrt-v3's BeckmannDistribution::Sample_wh derives it):
    // tan^2 theta = -ln(1 - u) / (cos^2 phi/ax^2 + sin^2 phi/ay^2). Not the visible
    // normals, so a normal facing away from wo can come out; the material rejects it.
    Vec3 sampleHalfVector(Vec3, Vec2 u) const {
        double logSample = std::log1p(-double(u.x));  // ln(1 - u) <= 0
        double phi, tan2Theta;
        if (alphaX == alphaY) {
            phi = 2.0 * kPi * u.y;
            tan2Theta = -double(alphaX) * alphaX * logSample;
        } else {
            phi = std::atan(double(alphaY) / alphaX * std::tan(2.0 * kPi * u.y + 0.5 * kPi));
            if (u.y > 0.5f) phi += kPi;
            double c = std::cos(phi), s = std::sin(phi);
            tan2Theta = -logSample / (c * c / (double(alphaX) * alphaX) + s * s / (double(alphaY) * alphaY));
        }
        double cosTheta = 1.0 / std::sqrt(1.0 + tan2Theta);
        double sinTheta = std::sqrt(std::max(0.0, 1.0 - cosTheta * cosTheta));
        return Vec3(float(sinTheta * std::cos(phi)), float(sinTheta * std::sin(phi)), float(cosTheta));
    }

    // Density of wi = reflect(wo, h) under that sampling: D(h) h.z times the reflection
    // Jacobian 1 / (4 wo.h) (Walter et al. 2007, eq. 14).
    float reflectionPdf(Vec3 wo, Vec3 h) const {
        float woDotH = dot(wo, h);
        if (wo.z <= 0 || woDotH <= 0) return 0;
        return D(h) * h.z / (4.0f * woDotH);
    }
};

}  // namespace photon
