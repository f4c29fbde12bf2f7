// Checks shared by the material tests: directions at a given angle, albedo estimates from
// sample(), and quadratures of the upper hemisphere and of the whole sphere independent of
// sample().
#pragma once
#include <gtest/gtest.h>
#include <algorithm>
#include <array>
#include <cmath>
#include <type_traits>
#include "materials/material.h"
#include "math/frame.h"
#include "math/rng.h"
#include "math/sampling.h"

namespace photon::bsdf_checks {

constexpr int kSamples = 200000;
constexpr float kCosines[] = {0.1f, 0.5f, 0.95f};  // near-grazing, oblique, near-normal

using Channels = std::array<double, 3>;

// Unit direction with the given cos(theta); a non-zero azimuth avoids axis-aligned luck.
inline Vec3 direction(float cosTheta, float phi = 0.7f) {
    float s = std::sqrt(std::max(0.0f, 1.0f - cosTheta * cosTheta));
    return {s * std::cos(phi), s * std::sin(phi), cosTheta};
}

// Allowed difference between two albedo estimates: 1% relative or 0.005 absolute.
inline double tolerance(double reference) { return std::max(0.005, 0.01 * std::abs(reference)); }

// Monte Carlo estimate of the directional albedo from sample(): the mean weight.
struct SampleEstimate {
    Channels mean{}, stdError{};
    double nonDeltaFraction = 0;  // share of all draws that returned a non-delta wi
};

inline SampleEstimate estimateBySampling(const Material& m, Vec3 wo, const MaterialInputs& in, TransportMode mode,
                                         uint64_t seed) {
    Rng rng(seed, 0, 0, StreamPurpose::Test);
    Channels sum{}, sumSq{};
    int nonDelta = 0;
    for (int i = 0; i < kSamples; ++i) {
        float uLobe = rng.uniform();
        Vec2 u{rng.uniform(), rng.uniform()};
        auto s = m.sample(wo, uLobe, u, in, mode);
        if (!s) continue;
        if (!s->delta) ++nonDelta;
        for (int c = 0; c < 3; ++c) {
            sum[c] += s->weight[c];
            sumSq[c] += double(s->weight[c]) * s->weight[c];
        }
    }
    SampleEstimate e;
    for (int c = 0; c < 3; ++c) {
        e.mean[c] = sum[c] / kSamples;
        double var = std::max(0.0, sumSq[c] / kSamples - e.mean[c] * e.mean[c]);
        e.stdError[c] = std::sqrt(var / kSamples);
    }
    e.nonDeltaFraction = double(nonDelta) / kSamples;
    return e;
}

// Deterministic quadrature of g(h) over the hemisphere of normals h (h.z > 0): theta_h uses
// the warp tan(theta_h) = a tan(u pi/2) up to tan(theta_h) = 30 a, so a lobe of GGX width a
// is resolved, then a uniform grid up to pi/2 for the broad remainder (a diffuse lobe, an
// anisotropic lobe's wide direction). Midpoint rule in both, periodic in phi. g returns a
// number (summed in double) or an array of numbers.
template <class G>
auto integrateNormals(float a, G g) {
    constexpr int kTheta = 400, kPhi = 512;
    constexpr float kHalfPi = 0.5f * kPi;
    double uMax = std::atan(30.0) / kHalfPi;  // tan(uMax pi/2) = 30
    double thetaSplit = std::atan(30.0 * a);
    using Value = decltype(g(Vec3()));
    std::conditional_t<std::is_arithmetic_v<Value>, double, Value> total{};
    auto ring = [&](double theta, double dTheta) {
        double dPhi = 2.0 * kPi / kPhi, sinTheta = std::sin(theta);
        for (int j = 0; j < kPhi; ++j) {
            double phi = (j + 0.5) * dPhi;
            Vec3 h(float(sinTheta * std::cos(phi)), float(sinTheta * std::sin(phi)), float(std::cos(theta)));
            auto v = g(h);
            double measure = sinTheta * dTheta * dPhi;
            if constexpr (std::is_arithmetic_v<Value>) {
                total += v * measure;
            } else {
                for (size_t c = 0; c < v.size(); ++c) total[c] += v[c] * measure;
            }
        }
    };
    double du = uMax / kTheta;
    for (int i = 0; i < kTheta; ++i) {
        double t = std::tan((i + 0.5) * du * kHalfPi);
        double dThetaDu = a * kHalfPi * (1 + t * t) / (1 + a * a * t * t);
        ring(std::atan(a * t), dThetaDu * du);
    }
    double dTheta = (kHalfPi - thetaSplit) / kTheta;
    for (int i = 0; i < kTheta; ++i) ring(thetaSplit + (i + 0.5) * dTheta, dTheta);
    return total;
}

// Deterministic quadrature of g(wi) over the upper hemisphere, independent of sample():
// wi = reflect(wo, h) over the half vectors h of integrateNormals, with d(omega_i) =
// 4 (wo.h) d(omega_h) (Walter et al. 2007, eq. 14). g returns a Color.
template <class G>
Channels integrateHemisphere(Vec3 wo, float a, G g) {
    return integrateNormals(a, [&](Vec3 h) {
        Channels v{};
        float woDotH = dot(wo, h);
        if (woDotH <= 0) return v;
        Vec3 wi = normalize(reflect(wo, h));
        if (wi.z <= 0) return v;
        Color f = g(wi);
        for (int c = 0; c < 3; ++c) v[c] = double(f[c]) * 4.0 * woDotH;
        return v;
    });
}

// Reciprocity f(wo, wi) == f(wi, wo) over random pairs, and no reflection into the lower
// hemisphere.
inline void expectReciprocal(const Material& m, const MaterialInputs& in) {
    Rng rng(7, 0, 0, StreamPurpose::Test);
    for (int i = 0; i < 20000; ++i) {
        Vec3 a = sampleUniformSphere({rng.uniform(), rng.uniform()});
        Vec3 b = sampleUniformSphere({rng.uniform(), rng.uniform()});
        Color fab = m.eval(a, b, in, TransportMode::Radiance);
        Color fba = m.eval(b, a, in, TransportMode::Radiance);
        if (a.z <= 0 || b.z <= 0) {
            ASSERT_TRUE(isBlack(fab) && isBlack(fba)) << "a.z " << a.z << " b.z " << b.z;
            continue;
        }
        for (int c = 0; c < 3; ++c)
            ASSERT_NEAR(fab[c], fba[c], 1e-4f * std::max(fab[c], fba[c]) + 1e-12f) << "pair " << i << " channel " << c;
    }
}

// A non-delta sample's pdf is pdf(wo, wi) and its weight is eval |cos| / pdf; a delta one's
// pdf is its lobe probability.
inline void expectSamplesAgreeWithPdfAndEval(const Material& m, const MaterialInputs& in) {
    Rng rng(11, 0, 0, StreamPurpose::Test);
    for (float cosO : kCosines) {
        Vec3 wo = direction(cosO, 2.1f);
        for (int i = 0; i < 20000; ++i) {
            float uLobe = rng.uniform();
            auto s = m.sample(wo, uLobe, {rng.uniform(), rng.uniform()}, in, TransportMode::Radiance);
            if (!s) continue;
            ASSERT_NEAR(length(s->wi), 1.0f, 1e-4f);
            ASSERT_GT(s->lobeProbability, 0.0f);
            ASSERT_LE(s->lobeProbability, 1.0f);
            if (s->delta) {
                ASSERT_FLOAT_EQ(s->pdf, s->lobeProbability);
                continue;
            }
            float p = m.pdf(wo, s->wi, in);
            ASSERT_GT(s->pdf, 0.0f);
            ASSERT_NEAR(s->pdf, p, 1e-4f * p);
            Color expected = m.eval(wo, s->wi, in, TransportMode::Radiance) * (s->wi.z / p);
            for (int c = 0; c < 3; ++c) ASSERT_NEAR(s->weight[c], expected[c], 1e-4f * expected[c] + 1e-7f);
        }
    }
}

// The same over the whole sphere, for materials that transmit: the lower hemisphere is the
// upper one mirrored (wi.z -> -wi.z), resolved with the same GGX width.
template <class G>
Channels integrateSphere(Vec3 wo, float a, G g) {
    Channels upper = integrateHemisphere(wo, a, g);
    Channels lower = integrateHemisphere(wo, a, [&](Vec3 wi) { return g(Vec3(wi.x, wi.y, -wi.z)); });
    for (int c = 0; c < 3; ++c) upper[c] += lower[c];
    return upper;
}

// Coarse bins over the upper hemisphere, for comparing the shapes of lobes: kRings rings
// of equal projected solid angle (equal steps in cos^2 theta) by kSectors equal sectors
// of azimuth.
constexpr int kRings = 4, kSectors = 8, kBins = kRings * kSectors;
using BinnedAlbedo = std::array<Channels, kBins>;

inline int hemisphereBin(Vec3 w) {
    int ring = std::min(kRings - 1, int(std::max(0.0f, w.z * w.z) * kRings));
    float phi = std::atan2(w.y, w.x);
    if (phi < 0) phi += 2 * kPi;
    int sector = std::min(kSectors - 1, int(phi / (2 * kPi) * kSectors));
    return ring * kSectors + sector;
}

// The directional albedo per bin of wi, from `samples` draws of sample(): each bin holds
// the integral of f cos over it (delta lobes included, in the bin of their direction).
inline BinnedAlbedo binBySampling(const Material& m, Vec3 wo, const MaterialInputs& in, int samples, uint64_t seed) {
    Rng rng(seed, 0, 0, StreamPurpose::Test);
    BinnedAlbedo bins{};
    for (int i = 0; i < samples; ++i) {
        float uLobe = rng.uniform();
        Vec2 u{rng.uniform(), rng.uniform()};
        auto s = m.sample(wo, uLobe, u, in, TransportMode::Radiance);
        if (!s || s->wi.z <= 0) continue;
        for (int c = 0; c < 3; ++c) bins[hemisphereBin(s->wi)][c] += s->weight[c] / samples;
    }
    return bins;
}

// Two binned lobes compared per channel: their albedos (the sums over the bins) and L1, the
// sum over the bins of |model - reference| over the reference's albedo.
struct BinComparison {
    Channels model{}, reference{}, l1{};
};
inline BinComparison compareBins(const BinnedAlbedo& model, const BinnedAlbedo& reference) {
    BinComparison r;
    for (int c = 0; c < 3; ++c) {
        for (int k = 0; k < kBins; ++k) r.model[c] += model[k][c], r.reference[c] += reference[k][c];
        for (int k = 0; k < kBins; ++k) r.l1[c] += std::abs(model[k][c] - reference[k][c]) / r.reference[c];
    }
    return r;
}

// Deterministic quadrature of g(wi) over the whole sphere, independent of sample() and of
// any half-vector mapping: polar coordinates about `axis`, midpoint rule. The polar angle
// is spaced geometrically from kTheta0 to kThetaNear (theta = kTheta0 (kThetaNear /
// kTheta0)^u), so a peak near the axis is resolved whatever its width down to ~1e-5, with
// the same number of rings per octave of angle, then evenly to pi for the broad remainder
// and for where g jumps (the horizon, when g is one side's part). The cap inside kTheta0
// counts as g(axis) times its area. For a BSDF with two narrow lobes, integrate each
// hemisphere's part about its own peak (g masked by the side of the surface).
template <class G>
Channels integrateSphere(Vec3 axis, G g) {
    constexpr int kNearRings = 1000, kFarRings = 500, kPhi = 384;
    constexpr double kTheta0 = 1e-6, kThetaNear = 0.5;
    const double logRatio = std::log(kThetaNear / kTheta0), dPhi = 2.0 * kPi / kPhi;
    Frame frame = Frame::fromNormal(axis);
    Channels total{};
    auto add = [&](Vec3 wi, double measure) {
        Color v = g(wi);
        for (int c = 0; c < 3; ++c) total[c] += v[c] * measure;
    };
    auto ring = [&](double theta, double dTheta) {
        double sinTheta = std::sin(theta), cosTheta = std::cos(theta);
        for (int j = 0; j < kPhi; ++j) {
            double phi = (j + 0.5) * dPhi;
            Vec3 local(float(sinTheta * std::cos(phi)), float(sinTheta * std::sin(phi)), float(cosTheta));
            add(normalize(frame.toWorld(local)), sinTheta * dTheta * dPhi);
        }
    };
    add(axis, kPi * kTheta0 * kTheta0);
    for (int i = 0; i < kNearRings; ++i) {
        double u = (i + 0.5) / kNearRings, theta = kTheta0 * std::exp(u * logRatio);
        ring(theta, theta * logRatio / kNearRings);
    }
    double dTheta = (kPi - kThetaNear) / kFarRings;
    for (int i = 0; i < kFarRings; ++i) ring(kThetaNear + (i + 0.5) * dTheta, dTheta);
    return total;
}

}  // namespace photon::bsdf_checks
