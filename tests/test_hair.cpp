// hair (Chiang et al. 2016): a white furnace (no absorption: S integrates to 1 over the
// sphere), the albedo with absorption against its closed form sum_p A_p, sample() against
// quadrature of eval() and pdf() and against a histogram of pdf(), the cuticle tilt of the
// R and TT lobes, the colour conversions and parameter checks, and finite values for any
// input.
#include <gtest/gtest.h>
#include <cmath>
#include <cstdio>
#include <stdexcept>
#include <string>
#include <tuple>
#include <utility>
#include <vector>
#include "bsdf_checks.h"
#include "materials/material.h"

namespace photon {
namespace {

using namespace bsdf_checks;

// The inputs at offset h across the fibre (h = 2 uv.y - 1).
MaterialInputs atOffset(const Material& m, double h) { return {{Vec2{0.5f, float((h + 1) / 2)}}, m.tint().value}; }

// Direction with sin(theta) = sinTheta along the fibre (x) and azimuth phi about it
// (phi = atan2(w.z, w.y)).
Vec3 fibreDirection(double sinTheta, double phi) {
    double c = std::sqrt(std::max(0.0, 1 - sinTheta * sinTheta));
    return {float(sinTheta), float(c * std::cos(phi)), float(c * std::sin(phi))};
}

// Deterministic quadrature of g(wi) over the sphere in the fibre's coordinates: s = sin(theta)
// = wi.x and phi about the fibre, d(omega) = ds d(phi), midpoint rule in both. S is smooth in
// s (M_p depends on cos(theta_i) only through its square) and periodic in phi, so once a step
// is below the lobes' widths what remains is the O(ds^2) error at s = +-1 (2e-4 at worst
// here, for a broad lobe near the pole; 2e-5 with 1024 steps).
template <class G>
Channels integrateAroundFibre(G g, int ns = 256, int nphi = 256) {
    Channels total{};
    double ds = 2.0 / ns, dphi = 2 * kPi / nphi;
    for (int i = 0; i < ns; ++i)
        for (int j = 0; j < nphi; ++j) {
            Color v = g(fibreDirection(-1 + (i + 0.5) * ds, (j + 0.5) * dphi));
            for (int c = 0; c < 3; ++c) total[c] += v[c] * ds * dphi;
        }
    return total;
}

// S = f |wi.z|, as the integrators weight eval().
Color scattering(const Material& m, Vec3 wo, Vec3 wi, const MaterialInputs& in) {
    return m.eval(wo, wi, in, TransportMode::Radiance) * std::abs(wi.z);
}

// Unpolarised Fresnel reflectance of a dielectric of index eta seen from outside.
double fresnel(double cosI, double eta) {
    double sin2T = (1 - cosI * cosI) / (eta * eta);
    if (sin2T >= 1) return 1;
    double cosT = std::sqrt(1 - sin2T);
    double rs = (cosI - eta * cosT) / (cosI + eta * cosT), rp = (eta * cosI - cosT) / (eta * cosI + cosT);
    return 0.5 * (rs * rs + rp * rp);
}

// The fibre's albedo in closed form: the lobes' M_p and N_p are normalised, so S integrates
// to sum_p A_p, with A_0 = f, A_1 = (1 - f)^2 T, A_2 = A_1 f T and A_3 the rest of the
// geometric series, f the Fresnel term at cos(theta_o) cos(gamma_o) and T the transmittance
// of one crossing, 2 cos(gamma_t) / cos(theta_t) long.
Channels albedoInClosedForm(double sinO, double h, double eta, Color sigmaA) {
    double cosO = std::sqrt(1 - sinO * sinO);
    double sinT = sinO / eta, cosT = std::sqrt(1 - sinT * sinT);
    double etaPrime = std::sqrt(eta * eta - sinO * sinO) / cosO;
    double sinGammaT = h / etaPrime, cosGammaT = std::sqrt(1 - sinGammaT * sinGammaT);
    double f = fresnel(cosO * std::sqrt(1 - h * h), eta);
    Channels a{};
    for (int c = 0; c < 3; ++c) {
        double T = std::exp(-sigmaA[c] * 2 * cosGammaT / cosT);
        double a1 = (1 - f) * (1 - f) * T, a2 = a1 * f * T;
        a[c] = f + a1 + a2 + a2 * f * T / (1 - f * T);
    }
    return a;
}

HairParameters parameters(float betaM, float betaN, Color sigmaA = Color(0.0f), float alphaDegrees = 2) {
    HairParameters p;
    p.betaM = betaM;
    p.betaN = betaN;
    p.sigmaA = sigmaA;
    p.alphaDegrees = alphaDegrees;
    return p;
}

TEST(Hair, DescribesItselfAsAGlossyTransmittingFibre) {
    MaterialPtr m = makeHair(HairParameters{});
    EXPECT_EQ(m->lobes(), unsigned(kGlossyLobe));
    EXPECT_TRUE(m->alignsToTangent());
    EXPECT_TRUE(m->transmits());
    EXPECT_TRUE(m->twoSided());
    EXPECT_FALSE(m->textured());
    EXPECT_FALSE(m->lambertian());
    EXPECT_FALSE(m->isDeltaOnly());
    // Restricted to the other lobes it is black.
    Vec3 wo = fibreDirection(0.3, 1.0), wi = fibreDirection(-0.3, 1.4);
    MaterialInputs in = atOffset(*m, 0.2);
    EXPECT_TRUE(isBlack(m->eval(wo, wi, in, TransportMode::Radiance, kDiffuseLobe | kDeltaLobe)));
    EXPECT_EQ(m->pdf(wo, wi, in, kDiffuseLobe), 0.0f);
    EXPECT_FALSE(m->sample(wo, 0.5f, {0.5f, 0.5f}, in, TransportMode::Radiance, kDiffuseLobe));
    EXPECT_GT(luminance(m->eval(wo, wi, in, TransportMode::Radiance)), 0.0f);
}

// Without absorption the fibre loses nothing: for every wo and h, S integrates to 1 over the
// sphere (A_p sums to 1 and each M_p N_p is normalised), shown here averaged over h (eight
// midpoints of [-1, 1]) and for each h, to 1e-3. Every sample's weight is then exactly 1
// too, since pdf() is S itself (the lobes are chosen by A_p, which is grey).
TEST(Hair, WhiteFurnace) {
    struct Roughness {
        float betaM, betaN;
    };
    constexpr int kOffsets = 8;
    for (Roughness r : {Roughness{0.3f, 0.3f}, Roughness{0.1f, 0.8f}, Roughness{0.8f, 0.2f}}) {
        MaterialPtr m = makeHair(parameters(r.betaM, r.betaN));
        for (double sinO : {-0.7, 0.0, 0.35, 0.9}) {
            Vec3 wo = fibreDirection(sinO, 0.8);
            double mean = 0, lowest = 2, highest = 0;
            for (int k = 0; k < kOffsets; ++k) {
                double h = -1 + (k + 0.5) * 2.0 / kOffsets;
                MaterialInputs in = atOffset(*m, h);
                double e = integrateAroundFibre([&](Vec3 wi) { return scattering(*m, wo, wi, in); })[0];
                EXPECT_NEAR(e, 1.0, 1e-3) << "betaM " << r.betaM << " betaN " << r.betaN << " sin(theta_o) " << sinO
                                          << " h " << h;
                mean += e / kOffsets;
                lowest = std::min(lowest, e);
                highest = std::max(highest, e);
            }
            auto mc = estimateBySampling(*m, wo, atOffset(*m, 0.3), TransportMode::Radiance, 5);
            std::printf("  betaM %.1f betaN %.1f sin(theta_o) %+.2f: furnace mean over h %.5f (h from %.5f to %.5f), "
                        "sampled %.5f\n",
                        r.betaM, r.betaN, sinO, mean, lowest, highest, mc.mean[0]);
            EXPECT_NEAR(mean, 1.0, 1e-3);
            EXPECT_NEAR(mc.mean[0], 1.0, 1e-4);
        }
    }
}

// With absorption (melanin 1.3, brown hair) at random wo and h: quadrature of S over the
// sphere equals sum_p A_p in closed form (1e-3), pdf() integrates to 1 (1e-3), and sample()'s
// mean weight equals the quadrature (bsdf_checks' tolerance: 1%, or 0.005 absolute); each
// sample's pdf is pdf() and its weight eval |wi.z| / pdf (1e-4 relative).
TEST(Hair, SamplingAgreesWithEvalAndPdf) {
    const Color sigmaA = hairSigmaAFromMelanin(1.3f, 0.0f);
    Rng rng(21, 0, 0, StreamPurpose::Test);
    for (auto [betaM, betaN] : {std::pair{0.3f, 0.3f}, std::pair{0.15f, 0.6f}}) {
        MaterialPtr m = makeHair(parameters(betaM, betaN, sigmaA));
        for (int trial = 0; trial < 3; ++trial) {
            Vec3 wo = sampleUniformSphere({rng.uniform(), rng.uniform()});
            double h = 2 * rng.uniform() - 1;
            MaterialInputs in = atOffset(*m, h);
            SCOPED_TRACE("betaM " + std::to_string(betaM) + " wo.x " + std::to_string(wo.x) + " h " +
                         std::to_string(h));
            Channels albedo = integrateAroundFibre([&](Vec3 wi) { return scattering(*m, wo, wi, in); });
            double pdfIntegral = integrateAroundFibre([&](Vec3 wi) { return Color(m->pdf(wo, wi, in)); })[0];
            Channels expected = albedoInClosedForm(wo.x, h, 1.55, sigmaA);
            auto mc = estimateBySampling(*m, wo, in, TransportMode::Radiance, 100 + trial);
            std::printf("  betaM %.2f betaN %.2f wo.x %+.3f h %+.3f: albedo %.4f %.4f %.4f (closed form %.4f %.4f "
                        "%.4f), sampled %.4f %.4f %.4f, int pdf %.5f\n",
                        betaM, betaN, wo.x, h, albedo[0], albedo[1], albedo[2], expected[0], expected[1],
                        expected[2], mc.mean[0], mc.mean[1], mc.mean[2], pdfIntegral);
            EXPECT_NEAR(pdfIntegral, 1.0, 1e-3);
            for (int c = 0; c < 3; ++c) {
                EXPECT_NEAR(albedo[c], expected[c], 1e-3) << "channel " << c;
                EXPECT_NEAR(mc.mean[c], albedo[c], tolerance(albedo[c])) << "channel " << c;
            }
            for (int i = 0; i < 20000; ++i) {
                auto s = m->sample(wo, rng.uniform(), {rng.uniform(), rng.uniform()}, in, TransportMode::Radiance);
                ASSERT_TRUE(s);
                ASSERT_FALSE(s->delta);
                ASSERT_EQ(s->lobeProbability, 1.0f);
                ASSERT_NEAR(length(s->wi), 1.0f, 1e-4f);
                float p = m->pdf(wo, s->wi, in);
                ASSERT_GT(p, 0.0f);
                ASSERT_NEAR(s->pdf, p, 1e-4f * p);
                Color f = scattering(*m, wo, s->wi, in) / p;
                for (int c = 0; c < 3; ++c) ASSERT_NEAR(s->weight[c], f[c], 1e-4f * f[c] + 1e-7f) << "sample " << i;
            }
        }
    }
}

// The directions sample() draws are distributed as pdf() says: a histogram over sin(theta_i)
// (24 bins) and phi_i - phi_o (32 bins) against pdf() integrated over each bin, by Pearson's
// chi-square (bins expecting under 5 draws pooled). With the fixed seed the statistic is a
// number; the bound is its mean (the degrees of freedom) plus 5 standard deviations.
TEST(Hair, SampledDirectionsFollowPdf) {
    constexpr int kS = 24, kPhi = 32, kSub = 16, kDraws = 400000;
    const Color sigmaA = hairSigmaAFromMelanin(0.5f, 0.3f);
    for (auto [betaM, betaN, sinO, h] : {std::tuple{0.3f, 0.3f, 0.4, 0.3}, std::tuple{0.15f, 0.9f, -0.8, -0.7}}) {
        MaterialPtr m = makeHair(parameters(betaM, betaN, sigmaA, 3));
        const double phiO = 0.4;
        Vec3 wo = fibreDirection(sinO, phiO);
        MaterialInputs in = atOffset(*m, h);
        std::vector<double> expected(kS * kPhi), observed(kS * kPhi);
        double ds = 2.0 / kS, dphi = 2 * kPi / kPhi, mass = 0;
        for (int i = 0; i < kS; ++i)
            for (int j = 0; j < kPhi; ++j) {
                double sum = 0;
                for (int a = 0; a < kSub; ++a)
                    for (int b = 0; b < kSub; ++b) {
                        double s = -1 + (i + (a + 0.5) / kSub) * ds, phi = -kPi + (j + (b + 0.5) / kSub) * dphi;
                        sum += m->pdf(wo, fibreDirection(s, phiO + phi), in);
                    }
                expected[i * kPhi + j] = sum * (ds / kSub) * (dphi / kSub);
                mass += expected[i * kPhi + j];
            }
        EXPECT_NEAR(mass, 1.0, 1e-3);
        Rng rng(8, 0, 0, StreamPurpose::Test);
        int returned = 0;
        for (int n = 0; n < kDraws; ++n) {
            auto smp = m->sample(wo, rng.uniform(), {rng.uniform(), rng.uniform()}, in, TransportMode::Radiance);
            if (!smp) continue;
            ++returned;
            double phi = std::remainder(std::atan2(smp->wi.z, smp->wi.y) - phiO, 2 * kPi);
            int i = std::clamp(int((smp->wi.x + 1) / ds), 0, kS - 1);
            int j = std::clamp(int((phi + kPi) / dphi), 0, kPhi - 1);
            observed[i * kPhi + j] += 1;
        }
        EXPECT_EQ(returned, kDraws);
        double chi2 = 0, pooledExpected = 0, pooledObserved = 0;
        int bins = 0;
        for (int k = 0; k < kS * kPhi; ++k) {
            double e = expected[k] * kDraws;
            if (e < 5) {
                pooledExpected += e;
                pooledObserved += observed[k];
                continue;
            }
            chi2 += (observed[k] - e) * (observed[k] - e) / e;
            ++bins;
        }
        if (pooledExpected > 0) {
            chi2 += (pooledObserved - pooledExpected) * (pooledObserved - pooledExpected) / pooledExpected;
            ++bins;
        }
        double dof = bins - 1;
        std::printf("  betaM %.2f betaN %.2f: pdf mass %.5f, chi-square %.1f over %d bins (bound %.1f)\n", betaM, betaN,
                    mass, chi2, bins, dof + 5 * std::sqrt(2 * dof));
        EXPECT_LT(chi2, dof + 5 * std::sqrt(2 * dof));
    }
}

// The cuticle's scales tilt R's cone by 2 alpha toward the root and TT's by alpha the other
// way (Marschner et al. 2003): at the lobe's azimuth S peaks at theta_i = -theta_o + 2 alpha
// (R, isolated by an opaque fibre) and at -theta_o - alpha (TT, straight through at h = 0).
TEST(Hair, ScalesTiltTheLobes) {
    const double alpha = 4 * kPi / 180, thetaO = 0.5;
    struct Case {
        const char* lobe;
        Color sigmaA;
        double phi, expectedTheta;
    };
    for (Case c : {Case{"R", Color(50.0f), 0.0, -thetaO + 2 * alpha}, Case{"TT", Color(0.0f), kPi, -thetaO - alpha}}) {
        MaterialPtr m = makeHair(parameters(0.1f, 0.2f, c.sigmaA, 4));
        MaterialInputs in = atOffset(*m, 0.0);
        Vec3 wo = fibreDirection(std::sin(thetaO), 0.3);
        double best = 0, bestTheta = 0;
        for (int i = 0; i <= 20000; ++i) {
            double theta = -kPi / 2 + kPi * i / 20000;
            double s = luminance(scattering(*m, wo, fibreDirection(std::sin(theta), 0.3 + c.phi), in));
            if (s > best) best = s, bestTheta = theta;
        }
        std::printf("  %s peaks at theta_i %.4f, expected %.4f\n", c.lobe, bestTheta, c.expectedTheta);
        EXPECT_NEAR(bestTheta, c.expectedTheta, 0.005) << c.lobe;
    }
}

TEST(Hair, ColourConversions) {
    // Melanin: eumelanin and pheomelanin's absorption spectra, added.
    Color brown = hairSigmaAFromMelanin(1.3f, 0.0f), red = hairSigmaAFromMelanin(0.0f, 1.0f);
    Color mixed = hairSigmaAFromMelanin(0.5f, 2.0f);
    const Color eu(0.419f, 0.697f, 1.37f), pheo(0.187f, 0.4f, 1.05f);
    for (int c = 0; c < 3; ++c) {
        EXPECT_NEAR(brown[c], 1.3f * eu[c], 1e-6f);
        EXPECT_NEAR(red[c], pheo[c], 1e-6f);
        EXPECT_NEAR(mixed[c], 0.5f * eu[c] + 2.0f * pheo[c], 1e-6f);
    }
    EXPECT_EQ(hairSigmaAFromMelanin(0, 0), Color(0.0f));
    // The reflectance fit at betaN = 0.3: sigma_a = (log c / 5.88841)^2.
    Color c(0.5f, 0.2f, 0.05f);
    Color sigmaA = hairSigmaAFromReflectance(c, 0.3f);
    for (int i = 0; i < 3; ++i) EXPECT_NEAR(sigmaA[i], std::pow(std::log(c[i]) / 5.888414, 2), 1e-5);
    EXPECT_EQ(hairSigmaAFromReflectance(Color(1.0f), 0.3f), Color(0.0f));
    EXPECT_TRUE(isFinite(hairSigmaAFromReflectance(Color(0.0f), 0.3f)));
    // Round trips, both ways.
    for (float betaN : {0.1f, 0.3f, 0.8f, 1.0f})
        for (Color x : {Color(0.0f, 0.05f, 0.3f), Color(0.5f, 1.3f, 2.0f), Color(4.0f, 8.0f, 0.01f)}) {
            Color back = hairSigmaAFromReflectance(hairReflectanceFromSigmaA(x, betaN), betaN);
            Color reflectance(0.9f, 0.3f, 0.02f);
            Color again = hairReflectanceFromSigmaA(hairSigmaAFromReflectance(reflectance, betaN), betaN);
            for (int i = 0; i < 3; ++i) {
                EXPECT_NEAR(back[i], x[i], 1e-4f * std::max(1.0f, x[i])) << "betaN " << betaN;
                EXPECT_NEAR(again[i], reflectance[i], 1e-5f * reflectance[i]) << "betaN " << betaN;
            }
        }
    // The tint (what an albedo buffer shows) is the colour sigma_a stands for.
    MaterialPtr m = makeHair(parameters(0.3f, 0.3f, brown));
    Color tint = m->tint().value, expected = hairReflectanceFromSigmaA(brown, 0.3f);
    for (int i = 0; i < 3; ++i) EXPECT_FLOAT_EQ(tint[i], expected[i]);
}

TEST(Hair, RejectsParametersOutsideTheModel) {
    auto message = [](HairParameters p) {
        try {
            makeHair(p);
        } catch (const std::invalid_argument& e) {
            return std::string(e.what());
        }
        return std::string("(accepted)");
    };
    EXPECT_NE(message(parameters(0.0f, 0.3f)).find("beta_m"), std::string::npos);
    EXPECT_NE(message(parameters(1.5f, 0.3f)).find("beta_m"), std::string::npos);
    EXPECT_NE(message(parameters(0.3f, 0.0f)).find("beta_n"), std::string::npos);
    EXPECT_NE(message(parameters(0.3f, -0.1f)).find("beta_n"), std::string::npos);
    EXPECT_NE(message(parameters(0.3f, 0.3f, Color(0.1f, -0.2f, 0.1f))).find("sigma_a"), std::string::npos);
    EXPECT_NE(message(parameters(0.3f, 0.3f, Color(0.1f, INFINITY, 0.1f))).find("sigma_a"), std::string::npos);
    EXPECT_NE(message(parameters(0.3f, NAN)).find("beta_n"), std::string::npos);
    HairParameters p;
    p.eta = 0;
    EXPECT_NE(message(p).find("eta"), std::string::npos);
    p.eta = NAN;
    EXPECT_NE(message(p).find("eta"), std::string::npos);
    EXPECT_EQ(message(parameters(1.0f, 1.0f)), "(accepted)");
    EXPECT_EQ(message(parameters(0.01f, 0.01f)), "(accepted)");
}

// Any wo and wi (grazing, along the fibre, w.x = +-1), any h in [-1, 1] (the edges too) and
// any random numbers (0 and the largest below 1 too) give finite, non-negative values, and
// samples with unit directions and weights that agree with eval() and pdf().
TEST(Hair, FiniteForAllInputs) {
    std::vector<MaterialPtr> materials = {
        makeHair(HairParameters{}),
        makeHair(parameters(0.1f, 0.8f, hairSigmaAFromMelanin(8, 0))),
        makeHair(parameters(1.0f, 1.0f, Color(0.0f), 0)),
        makeHair(parameters(0.02f, 0.05f, Color(0.0f), 10)),
    };
    HairParameters unit;
    unit.eta = 1;  // no Fresnel reflection at all
    materials.push_back(makeHair(unit));
    HairParameters low;
    low.eta = 0.8f;  // denser outside than inside: total internal reflection at grazing angles
    materials.push_back(makeHair(low));
    Rng rng(13, 0, 0, StreamPurpose::Test);
    auto draw = [&] {
        float u = rng.uniform();
        return u < 0.05f ? 0.0f : u > 0.95f ? 0x1.fffffep-1f : rng.uniform();
    };
    auto anyDirection = [&] {
        float u = rng.uniform();
        if (u < 0.05f) return Vec3(u < 0.025f ? 1.0f : -1.0f, 0, 0);  // along the fibre
        if (u < 0.1f) return fibreDirection(0, 2 * kPi * rng.uniform());  // across it
        if (u < 0.15f) return Vec3(0, 0, u < 0.125f ? 1.0f : -1.0f);
        return sampleUniformSphere({rng.uniform(), rng.uniform()});
    };
    int samples = 0;
    for (int i = 0; i < 100000; ++i) {
        const Material& m = *materials[i % materials.size()];
        Vec3 wo = anyDirection(), wi = anyDirection();
        float u = rng.uniform();
        double h = u < 0.1f ? (u < 0.05f ? -1.0 : 1.0) : 2 * rng.uniform() - 1;
        MaterialInputs in = atOffset(m, h);
        Color f = m.eval(wo, wi, in, TransportMode::Radiance);
        float p = m.pdf(wo, wi, in);
        ASSERT_TRUE(isFinite(f) && minComponent(f) >= 0 && std::isfinite(p) && p >= 0)
            << "material " << i % materials.size() << " wo " << wo.x << " " << wo.y << " " << wo.z << " wi " << wi.x
            << " " << wi.y << " " << wi.z << " h " << h;
        auto s = m.sample(wo, draw(), {draw(), draw()}, in, TransportMode::Importance);
        if (!s) continue;
        ++samples;
        ASSERT_TRUE(isFinite(s->weight) && minComponent(s->weight) >= 0 && std::isfinite(s->pdf) && s->pdf > 0)
            << "material " << i % materials.size() << " wo " << wo.x << " " << wo.y << " " << wo.z << " h " << h;
        ASSERT_NEAR(length(s->wi), 1.0f, 1e-4f);
    }
    // Only draws whose lobes all vanish may return nothing.
    EXPECT_GT(samples, 99000);
}

}  // namespace
}  // namespace photon
