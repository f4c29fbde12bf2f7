// A hair fibre: Chiang, Bitterli, Tappan and Burley 2016, "A Practical and Controllable
// Hair and Fur Model for Production Path Tracing". The fibre is a rough dielectric cylinder
// with tilted cuticle scales; light leaves it after p = 0 (R), 1 (TT), 2 (TRT) internal
// paths, and the residual p >= 3 is one more lobe. Each lobe is S_p = M_p A_p N_p:
//   M_p  longitudinal: d'Eon et al. 2011's normalised lobe around the tilted specular cone,
//   A_p  attenuation: Fresnel and absorption along the path through the cylinder,
//   N_p  azimuthal: a logistic about the cylinder's exit azimuth (Chiang et al.'s choice,
//        since it has a closed-form CDF), trimmed to [-pi, pi].
// Local frame: x along the fibre, z toward the viewer, so sin(theta) = w.x and
// phi = atan2(w.z, w.y); the offset across the fibre is h = 2 uv.y - 1.
#include <array>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>
#include "materials/fresnel.h"
#include "materials/material.h"

namespace photon {
namespace {

constexpr int kHairLobes = 4;  // R, TT, TRT and the residual
constexpr float kBelowOne = 0x1.fffffep-1f;

float clampedAsin(float x) { return std::asin(std::clamp(x, -1.0f, 1.0f)); }
float squareOf(float x) { return x * x; }

// 1 / i^2, the ratios of the terms of I0's series.
constexpr auto kInverseSquares = [] {
    std::array<double, 48> r{};
    for (int i = 1; i < 48; ++i) r[i] = 1.0 / (double(i) * i);
    return r;
}();

// I0, the modified Bessel function of the first kind, by its power series (x^2/4)^i / i!^2,
// summed until the terms are below 1e-10 of the sum (x <= 12 here: at most ~35 terms).
double besselI0(double x) {
    double q = x * x / 4, term = 1, sum = 1;
    for (int i = 1; i < 48 && term > 1e-10 * sum; ++i) {
        term *= q * kInverseSquares[i];
        sum += term;
    }
    return sum;
}

// log I0(x): the series up to x = 12, then the asymptotic expansion e^x / sqrt(2 pi x)
// (1 + 1/(8x) + 9/(128x^2) + 225/(3072x^3)), whose next term is below 6e-6 at x = 12.
double logBesselI0(double x) {
    if (x <= 12) return std::log(besselI0(x));
    double r = 1 / x;
    double series = 1 + r * (1.0 / 8 + r * (9.0 / 128 + r * (225.0 / 3072)));
    return x - 0.5 * std::log(2 * double(kPi) * x) + std::log(series);
}

// M_p (d'Eon et al. 2011): the longitudinal marginal of a von Mises-Fisher lobe of variance
// v about the direction at -theta_o, normalised so that its integral against cos(theta_i)
// d(theta_i) is 1: e^(-b) I0(a) / (2 v sinh(1/v)). For small v that overflows; with
// sinh(1/v) ~ e^(1/v) / 2 its logarithm does not. In double: a and 1/v nearly cancel at
// the peak, and 1/v reaches 1e4 for betaM = 0.02.
float longitudinal(float cosI, float cosO, float sinI, float sinO, float v) {
    double a = double(cosI) * cosO / v, b = double(sinI) * sinO / v;
    if (v <= 0.1f) return float(std::exp(logBesselI0(a) - b - 1 / double(v) - std::log(double(v))));
    return float(std::exp(-b) * besselI0(a) / (std::sinh(1 / double(v)) * 2 * v));
}

// The logistic distribution of scale s and its CDF; trimmed to [-pi, pi] it is N_p's shape.
float logisticPdf(float x, float s) {
    float e = std::exp(-std::abs(x) / s);
    return e / (s * squareOf(1 + e));
}
float logisticCdf(float x, float s) { return 1 / (1 + std::exp(-x / s)); }

float trimmedLogistic(float x, float s) {
    return logisticPdf(x, s) / (logisticCdf(kPi, s) - logisticCdf(-kPi, s));
}

// Inverts the trimmed logistic's CDF: u in [0, 1) to x in [-pi, pi].
float sampleTrimmedLogistic(float u, float s) {
    float lo = logisticCdf(-kPi, s), k = logisticCdf(kPi, s) - lo;
    float c = std::clamp(u * k + lo, 1e-30f, kBelowOne);
    return std::clamp(-s * std::log(1 / c - 1), -kPi, kPi);
}

// Azimuth of the exit direction of lobe p, relative to phi_o, for a ray entering at
// gamma_o and refracted to gamma_t: 2 p gamma_t - 2 gamma_o + p pi.
float exitAzimuth(int p, float gammaO, float gammaT) { return 2 * p * gammaT - 2 * gammaO + p * kPi; }

// N_p: the trimmed logistic of the azimuth's difference from the exit azimuth, wrapped.
float azimuthal(float phi, int p, float s, float gammaO, float gammaT) {
    float dphi = std::remainder(phi - exitAzimuth(p, gammaO, gammaT), 2 * kPi);
    return trimmedLogistic(std::clamp(dphi, -kPi, kPi), s);
}

// The factors of the lobes that depend on wo only (h is tied to wo): the attenuations A_p,
// their luminance shares (the lobe choice), the azimuths gamma_o, gamma_t, and the tilted
// longitudinal angles of the lobes' cones.
struct HairLobes {
    Color attenuation[kHairLobes];
    float share[kHairLobes];
    float gammaO, gammaT;
    float sinO[kHairLobes], cosO[kHairLobes];
    float phiO;
};

class Hair final : public Material {
public:
    explicit Hair(const HairParameters& p)
        : Material(hairReflectanceFromSigmaA(p.sigmaA, p.betaN)), sigmaA_(p.sigmaA), eta_(p.eta) {
        // Roughness to lobe variance and logistic scale: Chiang et al. 2016's fits of the
        // appearance of an isotropically rough cylinder. TT is sharper and TRT wider than R
        // (Marschner et al. 2003).
        float bm = p.betaM, bn = p.betaN;
        v_[0] = squareOf(0.726f * bm + 0.812f * squareOf(bm) + 3.7f * std::pow(bm, 20.0f));
        v_[1] = 0.25f * v_[0];
        v_[2] = v_[3] = 4 * v_[0];
        s_ = std::sqrt(kPi / 8) * (0.265f * bn + 1.194f * squareOf(bn) + 5.372f * std::pow(bn, 22.0f));
        // The scales tilt lobe p's cone by -2 alpha, alpha, 4 alpha (R, TT, TRT): sin and cos
        // of 2^k alpha by the double-angle formulas.
        float alpha = p.alphaDegrees * (kPi / 180);
        sin2k_[0] = std::sin(alpha);
        cos2k_[0] = std::sqrt(std::max(0.0f, 1 - squareOf(sin2k_[0])));
        for (int i = 1; i < 3; ++i) {
            sin2k_[i] = 2 * cos2k_[i - 1] * sin2k_[i - 1];
            cos2k_[i] = squareOf(cos2k_[i - 1]) - squareOf(sin2k_[i - 1]);
        }
    }

    unsigned lobes() const override { return kGlossyLobe; }
    bool transmits() const override { return true; }
    bool textured() const override { return false; }
    bool alignsToTangent() const override { return true; }

    // S / |cos(theta_i)| with respect to z, so that the integrators' f |wi.z| is S.
    Color eval(Vec3 wo, Vec3 wi, const MaterialInputs& in, TransportMode, unsigned lobes) const override {
        if (!(lobes & kGlossyLobe)) return Color(0.0f);
        Color f = scattering(wi, lobesAt(wo, in), nullptr);
        float cosZ = std::abs(wi.z);
        return cosZ > 0 ? f / cosZ : f;
    }

    float pdf(Vec3 wo, Vec3 wi, const MaterialInputs& in, unsigned lobes) const override {
        if (!(lobes & kGlossyLobe)) return 0;
        float p = 0;
        scattering(wi, lobesAt(wo, in), &p);
        return p;
    }

    // uLobe picks the lobe and, rescaled within its share, the azimuth; u.x the longitude
    // within M_p and u.y the azimuth about M_p's cone (d'Eon et al. 2013).
    std::optional<BSDFSample> sample(Vec3 wo, float uLobe, Vec2 u, const MaterialInputs& in, TransportMode,
                                     unsigned lobes) const override {
        if (!(lobes & kGlossyLobe)) return std::nullopt;
        HairLobes l = lobesAt(wo, in);
        int last = kHairLobes - 1;
        while (last >= 0 && !(l.share[last] > 0)) --last;
        if (last < 0) return std::nullopt;  // every share 0: nothing scatters
        int p = 0;
        float below = 0;
        for (; p < last; ++p) {
            if (l.share[p] > 0 && uLobe < below + l.share[p]) break;
            below += l.share[p];
        }
        float uPhi = std::clamp((uLobe - below) / l.share[p], 0.0f, kBelowOne);

        float ux = std::max(u.x, 1e-5f);
        float cosTheta = 1 + v_[p] * std::log(ux + (1 - ux) * std::exp(-2 / v_[p]));
        float sinTheta = std::sqrt(std::max(0.0f, 1 - squareOf(cosTheta)));
        float sinI = std::clamp(-cosTheta * l.sinO[p] + sinTheta * std::cos(2 * kPi * u.y) * l.cosO[p], -1.0f, 1.0f);
        float cosI = std::sqrt(std::max(0.0f, 1 - squareOf(sinI)));

        float dphi = p < kHairLobes - 1 ? exitAzimuth(p, l.gammaO, l.gammaT) + sampleTrimmedLogistic(uPhi, s_)
                                        : 2 * kPi * uPhi;
        float phiI = l.phiO + dphi;
        Vec3 wi(sinI, cosI * std::cos(phiI), cosI * std::sin(phiI));

        float pdf = 0;
        Color f = scattering(wi, l, &pdf);
        if (!(pdf > 0) || !std::isfinite(pdf)) return std::nullopt;
        BSDFSample s;
        s.wi = wi;
        s.pdf = pdf;
        s.weight = f / pdf;  // S = f |wi.z|
        if (!isFinite(s.weight)) return std::nullopt;
        return s;
    }

private:
    // A_p at wo and offset h (Chiang et al. 2016, after Marschner et al. 2003): the path
    // through the cylinder seen in the plane normal to the fibre, with the modified index
    // eta' that makes that 2D refraction exact (Bravais).
    HairLobes lobesAt(Vec3 wo, const MaterialInputs& in) const {
        HairLobes l;
        float h = std::clamp(2 * in.at.uv.y - 1, -1.0f, 1.0f);
        float sinO = std::clamp(wo.x, -1.0f, 1.0f), cosO = std::sqrt(std::max(0.0f, 1 - squareOf(sinO)));
        l.phiO = std::atan2(wo.z, wo.y);
        l.gammaO = clampedAsin(h);

        // Inside, the longitude follows Snell's law; the azimuth the 2D law with eta'.
        float sinT = sinO / eta_, cosT = std::sqrt(std::max(0.0f, 1 - squareOf(sinT)));
        float etaPrimeCos = std::sqrt(std::max(0.0f, squareOf(eta_) - squareOf(sinO)));  // eta' cos_o
        float sinGammaT = etaPrimeCos > 0 ? std::clamp(h * cosO / etaPrimeCos, -1.0f, 1.0f) : (h < 0 ? -1.0f : 1.0f);
        float cosGammaT = std::sqrt(std::max(0.0f, 1 - squareOf(sinGammaT)));
        l.gammaT = std::asin(sinGammaT);

        // One crossing of the cylinder is 2 cos(gamma_t) diameters long in the plane, over
        // cos(theta_t) along the fibre.
        float length = 2 * cosGammaT / std::max(cosT, 1e-6f);
        Color T(std::exp(-sigmaA_.x * length), std::exp(-sigmaA_.y * length), std::exp(-sigmaA_.z * length));

        float cosGammaO = std::sqrt(std::max(0.0f, 1 - squareOf(h)));
        float f = fresnelDielectric(cosO * cosGammaO, eta_);
        l.attenuation[0] = Color(f);
        l.attenuation[1] = squareOf(1 - f) * T;
        l.attenuation[2] = l.attenuation[1] * f * T;
        // p >= 3 summed as a geometric series in f T.
        for (int c = 0; c < 3; ++c) {
            float denominator = 1 - f * T[c];
            l.attenuation[3][c] = denominator > 0 ? l.attenuation[2][c] * f * T[c] / denominator : 0.0f;
        }

        float total = 0;
        for (int p = 0; p < kHairLobes; ++p) total += l.share[p] = std::max(0.0f, luminance(l.attenuation[p]));
        for (int p = 0; p < kHairLobes; ++p) l.share[p] = total > 0 ? l.share[p] / total : 0.0f;

        // The scales tilt R's cone by -2 alpha, TT's by alpha and TRT's by 4 alpha; a cone
        // tilted past the pole is the same cone, hence |cos|.
        l.sinO[0] = sinO * cos2k_[1] - cosO * sin2k_[1];
        l.cosO[0] = std::abs(cosO * cos2k_[1] + sinO * sin2k_[1]);
        l.sinO[1] = sinO * cos2k_[0] + cosO * sin2k_[0];
        l.cosO[1] = std::abs(cosO * cos2k_[0] - sinO * sin2k_[0]);
        l.sinO[2] = sinO * cos2k_[2] + cosO * sin2k_[2];
        l.cosO[2] = std::abs(cosO * cos2k_[2] - sinO * sin2k_[2]);
        l.sinO[3] = sinO;
        l.cosO[3] = cosO;
        return l;
    }

    // S(wo, wi) = sum_p M_p A_p N_p, with N_3 uniform; and, if pdf is given, the density of
    // sample(): the same sum with A_p replaced by the lobes' shares.
    Color scattering(Vec3 wi, const HairLobes& l, float* pdf) const {
        float sinI = std::clamp(wi.x, -1.0f, 1.0f), cosI = std::sqrt(std::max(0.0f, 1 - squareOf(sinI)));
        float phi = std::atan2(wi.z, wi.y) - l.phiO;
        Color f(0.0f);
        float density = 0;
        for (int p = 0; p < kHairLobes; ++p) {
            float m = longitudinal(cosI, l.cosO[p], sinI, l.sinO[p], v_[p]);
            float n = p < kHairLobes - 1 ? azimuthal(phi, p, s_, l.gammaO, l.gammaT) : 1 / (2 * kPi);
            f += l.attenuation[p] * (m * n);
            density += l.share[p] * m * n;
        }
        if (pdf) *pdf = density;
        return f;
    }

    Color sigmaA_;
    float eta_;
    float v_[kHairLobes];
    float s_;
    float sin2k_[3], cos2k_[3];
};

// The polynomial in betaN of Chiang et al. 2016's fit between sigma_a and the colour of
// multiply scattering hair: sigma_a = (log(c) / poly)^2.
float reflectanceFit(float bn) {
    float bn2 = bn * bn;
    return 5.969f - 0.215f * bn + 2.532f * bn2 - 10.73f * bn * bn2 + 5.574f * bn2 * bn2 + 0.245f * bn * bn2 * bn2;
}

}  // namespace

MaterialPtr makeHair(const HairParameters& parameters) {
    const HairParameters& p = parameters;
    if (!(p.eta > 0) || !std::isfinite(p.eta))
        throw std::invalid_argument("hair: eta must be a positive index of refraction, got " + std::to_string(p.eta));
    if (!(p.betaM > 0 && p.betaM <= 1))
        throw std::invalid_argument("hair: beta_m (longitudinal roughness) must be in (0, 1], got " +
                                    std::to_string(p.betaM));
    if (!(p.betaN > 0 && p.betaN <= 1))
        throw std::invalid_argument("hair: beta_n (azimuthal roughness) must be in (0, 1], got " +
                                    std::to_string(p.betaN));
    if (!std::isfinite(p.alphaDegrees))
        throw std::invalid_argument("hair: alpha (scale tilt) must be finite");
    for (int c = 0; c < 3; ++c)
        if (!(p.sigmaA[c] >= 0) || !std::isfinite(p.sigmaA[c]))
            throw std::invalid_argument("hair: sigma_a must be finite and non-negative, got channel " +
                                        std::to_string(c) + " = " + std::to_string(p.sigmaA[c]));
    return std::make_shared<Hair>(p);
}

Color hairSigmaAFromMelanin(float eumelanin, float pheomelanin) {
    return eumelanin * Color(0.419f, 0.697f, 1.37f) + pheomelanin * Color(0.187f, 0.4f, 1.05f);
}

// c is kept in [FLT_MIN, 1]: black would need infinite absorption, and above 1 the fit has
// no meaning (it would absorb again).
Color hairSigmaAFromReflectance(Color c, float betaN) {
    float fit = reflectanceFit(betaN);
    Color sigmaA;
    for (int i = 0; i < 3; ++i)
        sigmaA[i] = squareOf(std::log(std::clamp(c[i], std::numeric_limits<float>::min(), 1.0f)) / fit);
    return sigmaA;
}

Color hairReflectanceFromSigmaA(Color sigmaA, float betaN) {
    float fit = reflectanceFit(betaN);
    Color c;
    for (int i = 0; i < 3; ++i) c[i] = std::exp(-std::sqrt(std::max(0.0f, sigmaA[i])) * fit);
    return c;
}

}  // namespace photon
