// The conductor with a complex index of refraction and anisotropic GGX or Beckmann roughness:
// the exact conductor Fresnel against closed forms, the anisotropic distributions' normalisations,
// sample() against eval()/pdf() by independent quadrature, reciprocity, the white furnace,
// the named metals and their scene-file fields, and SPPM against the path tracer on a scene
// with rough gold.
#include <gtest/gtest.h>
#include <array>
#include <cmath>
#include <cstdio>
#include <ostream>
#include <string>
#include <vector>
#include "materials/beckmann.h"
#include "materials/fresnel.h"
#include "materials/material.h"
#include "materials/metal_table.h"
#include "materials/microfacet.h"
#include "materials/named_metals.h"
#include "math/rng.h"
#include "math/sampling.h"
#include "texture/image_texture.h"
#include "bsdf_checks.h"
#include "scene_loader_fixture.h"
#include "test_support.h"

namespace photon::conductor_tests {
namespace {

using namespace bsdf_checks;
constexpr float kAzimuths[] = {0.3f, 1.9f};  // anisotropic lobes differ with phi
const Color kWhite(1.0f);
// Inputs with the given tint at an arbitrary uv (conductors read no texture but the tint).
MaterialInputs tinted(Color tint) { return {{}, tint}; }

ComplexIor metal(std::string_view symbol) {
    auto ior = findMetal(symbol);
    EXPECT_TRUE(ior) << symbol;
    return ior.value_or(ComplexIor{kWhite, kWhite});
}

// A conductor of index `ior` with Beckmann alphas (ax, ay).
MaterialPtr beckmannConductor(ComplexIor ior, float ax, float ay) {
    return makeConductor(ComplexIorParam{ior.eta, ior.k},
                         MicrofacetRoughness{ax, ay, RoughnessToAlpha::Identity, MicrofacetDistribution::Beckmann});
}

// ---- Fresnel ----

// Reflectance of a conductor in the real closed form of Born & Wolf ("Principles of Optics",
// sec. 14.2, eqs. 20-21 with a^2 + b^2 and a as there), as pbrt-v3's FrConductor writes it;
// in double, independent of the complex arithmetic of fresnelConductor.
double closedFormConductorFresnel(double cosI, double eta, double k) {
    double cos2 = cosI * cosI, sin2 = 1 - cos2;
    double t0 = eta * eta - k * k - sin2;
    double a2PlusB2 = std::sqrt(t0 * t0 + 4 * eta * eta * k * k);
    double a = std::sqrt(0.5 * (a2PlusB2 + t0));
    double t1 = a2PlusB2 + cos2, t2 = 2 * cosI * a;
    double rs = (t1 - t2) / (t1 + t2);
    double t3 = cos2 * a2PlusB2 + sin2 * sin2, t4 = t2 * sin2;
    double rp = rs * (t3 - t4) / (t3 + t4);
    return 0.5 * (rs + rp);
}

TEST(ConductorFresnel, MatchesTheRealClosedForm) {
    for (float eta : {0.12f, 0.4f, 1.5f, 3.2f})
        for (float k : {0.5f, 2.5f, 7.6f})
            for (float cosI : {0.02f, 0.2f, 0.5f, 0.8f, 1.0f}) {
                double expected = closedFormConductorFresnel(cosI, eta, k);
                EXPECT_NEAR(fresnelConductor(cosI, eta, k), expected, 2e-5 + 1e-5 * expected)
                    << "eta " << eta << " k " << k << " cos " << cosI;
            }
}

TEST(ConductorFresnel, WithoutExtinctionIsTheDielectricFresnel) {
    // From outside, including eta < 1 where light is totally reflected beyond the critical angle.
    for (float eta : {0.7f, 1.33f, 1.5f, 2.4f})
        for (float cosI : {0.05f, 0.3f, 0.6f, 0.9f, 1.0f})
            EXPECT_NEAR(fresnelConductor(cosI, eta, 0.0f), fresnelDielectric(cosI, eta), 2e-6f)
                << "eta " << eta << " cos " << cosI;
}

TEST(ConductorFresnel, NormalAndGrazingIncidence) {
    for (const MetalIor& m : kMetalIors) {
        Color f0 = fresnelConductor(1.0f, m.eta, m.k);
        for (int c = 0; c < 3; ++c) {
            float n = m.eta[c], k = m.k[c];
            EXPECT_NEAR(f0[c], ((n - 1) * (n - 1) + k * k) / ((n + 1) * (n + 1) + k * k), 1e-6f) << m.name;
            EXPECT_NEAR(fresnelConductor(0.0f, n, k), 1.0f, 1e-6f) << m.name;  // grazing: a perfect mirror
            // and rising to it monotonically past the dip near the principal angle
            EXPECT_GT(fresnelConductor(1e-3f, n, k), 0.98f) << m.name;
            EXPECT_GT(fresnelConductor(1e-3f, n, k), fresnelConductor(0.05f, n, k)) << m.name;
        }
    }
}

TEST(ConductorFresnel, GoldSilverAluminiumHaveTheirKnownColours) {
    // Well-known normal-incidence reflectances (linear sRGB) within the scatter of measurements
    // and projections; scripts/metal_rgb.py checks the same when it writes the table.
    auto f0 = [](std::string_view s) { return fresnelConductor(1.0f, metal(s).eta, metal(s).k); };
    EXPECT_VEC3_NEAR(f0("Au"), Color(1.0f, 0.766f, 0.336f), 0.06f);
    EXPECT_VEC3_NEAR(f0("Ag"), Color(0.972f, 0.960f, 0.915f), 0.05f);
    EXPECT_VEC3_NEAR(f0("Al"), Color(0.913f, 0.921f, 0.925f), 0.03f);
}

// ---- the anisotropic GGX and Beckmann distributions ----

// The microfacets' projected area is the macro surface's: int D(h) h.z dh = 1 (Heitz 2014,
// eq. 4). The visible normals' distribution integrates to one for every wo (eq. 2 there),
// which ties Lambda to D: int G1(wo) max(0, wo.h) D(h) / wo.z dh = 1.
template <class Distribution>
void expectProjectedAreaAndVisibleNormalsNormalised(float ax, float ay) {
    Distribution d(ax, ay);
    float a = std::min(ax, ay);
    EXPECT_NEAR(integrateNormals(a, [&](Vec3 h) { return d.D(h) * h.z; }), 1.0, 2e-3) << ax << " " << ay;
    for (float cosO : kCosines)
        for (float phi : kAzimuths) {
            Vec3 wo = direction(cosO, phi);
            double visible = integrateNormals(a, [&](Vec3 h) { return d.G1(wo) * std::max(0.0f, dot(wo, h)) * d.D(h) / wo.z; });
            EXPECT_NEAR(visible, 1.0, 3e-3) << ax << " " << ay << " cos " << cosO << " phi " << phi;
        }
}

TEST(AnisotropicGgx, ProjectedAreaAndVisibleNormalsAreNormalised) {
    for (auto [ax, ay] : {std::pair{0.05f, 0.3f}, std::pair{0.4f, 0.1f}, std::pair{0.2f, 0.2f}})
        expectProjectedAreaAndVisibleNormalsNormalised<GGX>(ax, ay);
}

// For Beckmann this checks the exact Lambda (erf form) against its D.
TEST(AnisotropicBeckmann, ProjectedAreaAndVisibleNormalsAreNormalised) {
    for (auto [ax, ay] : {std::pair{0.05f, 0.3f}, std::pair{0.4f, 0.1f}, std::pair{0.2f, 0.2f}, std::pair{0.9f, 0.9f}})
        expectProjectedAreaAndVisibleNormalsNormalised<Beckmann>(ax, ay);
}

TEST(AnisotropicGgx, SwappingAlphasTurnsTheLobeByAQuarter) {
    GGX a(0.08f, 0.35f), b(0.35f, 0.08f);
    Rng rng(5, 0, 0, StreamPurpose::Test);
    for (int i = 0; i < 1000; ++i) {
        Vec3 w = sampleUniformSphere({rng.uniform(), rng.uniform()});
        w.z = std::abs(w.z);
        Vec3 turned(-w.y, w.x, w.z);
        EXPECT_NEAR(a.D(w), b.D(turned), 1e-4f * a.D(w));
        EXPECT_NEAR(a.lambda(w), b.lambda(turned), 1e-5f * (1 + a.lambda(w)));
    }
}

TEST(AnisotropicGgx, IsotropicCaseIsTheOneAlphaDistribution) {
    // One alpha or two equal ones: the same numbers to the bit (existing scenes render as before).
    Rng rng(9, 0, 0, StreamPurpose::Test);
    for (float alpha : {0.01f, 0.2f, 0.8f}) {
        GGX one(alpha), two(alpha, alpha);
        for (int i = 0; i < 1000; ++i) {
            Vec3 w = sampleUniformSphere({rng.uniform(), rng.uniform()});
            w.z = std::abs(w.z);
            float isotropicD = alpha * alpha / (kPi * std::pow(w.x * w.x + w.y * w.y + alpha * alpha * w.z * w.z, 2.0f));
            EXPECT_NEAR(two.D(w), isotropicD, 1e-5f * isotropicD);
            EXPECT_EQ(one.D(w), two.D(w));
            EXPECT_EQ(one.lambda(w), two.lambda(w));
        }
    }
}

// The tails that tell Beckmann from GGX: at the same alpha, a normal tilted by
// tan(theta) = 4 alpha is exp(-16) (cos(theta) = 1 / sqrt(1 + 16 alpha^2) to the fourth, cancelled by
// D's 1/cos^4) of the peak under Beckmann, and 1 / 17^2 under GGX.
TEST(AnisotropicBeckmann, TailsAreGaussianWhereGgxsArePowerLaws) {
    const float alpha = 0.05f;
    Beckmann beckmann(alpha);
    GGX ggx(alpha);
    const float t = 4 * alpha, c = 1 / std::sqrt(1 + t * t);
    Vec3 tilted(t * c, 0, c), n(0, 0, 1);
    double c4 = std::pow(double(c), 4);
    EXPECT_NEAR(beckmann.D(tilted) * c4 / beckmann.D(n), std::exp(-16.0), 1e-3 * std::exp(-16.0));
    EXPECT_NEAR(ggx.D(tilted) * c4 / ggx.D(n), 1.0 / (17.0 * 17.0), 1e-4);
    EXPECT_NEAR(beckmann.D(n), 1.0 / (kPi * alpha * alpha), 1e-3 / (kPi * alpha * alpha));
}

TEST(AnisotropicGgx, RoughnessRemaps) {
    EXPECT_FLOAT_EQ(roughnessToAlpha(0.5f), 0.25f);      // photon: alpha = roughness^2
    EXPECT_FLOAT_EQ(pbrtRoughnessToAlpha(0.25f), 0.5f);  // pbrt-v4 remaproughness: sqrt
}

// ---- the material: sampling against quadrature, pdf, reciprocity ----

struct Case {
    std::string name;
    MaterialPtr material;
    Color tint;
    float width;  // the smaller GGX alpha, which the quadrature resolves
};

void PrintTo(const Case& c, std::ostream* os) { *os << c.name; }

std::vector<Case> cases() {
    Color f0(0.9f, 0.6f, 0.3f);
    return {
        {"GoldIsotropic", makeConductor(metal("Au"), GgxAlpha{0.09f, 0.09f}), kWhite, 0.09f},
        {"GoldAnisotropic", makeConductor(metal("Au"), GgxAlpha{0.05f, 0.3f}), kWhite, 0.05f},
        {"CopperAnisotropicTurned", makeConductor(metal("Cu"), GgxAlpha{0.4f, 0.1f}), kWhite, 0.1f},
        {"TitaniumRough", makeConductor(metal("Ti"), GgxAlpha{0.6f, 0.6f}), kWhite, 0.6f},
        {"SchlickAnisotropic", makeConductor(ColorParam(f0), GgxAlpha{0.1f, 0.4f}), f0, 0.1f},
        {"BeckmannCopper", beckmannConductor(metal("Cu"), 0.1f, 0.1f), kWhite, 0.1f},
        {"BeckmannGoldAnisotropic", beckmannConductor(metal("Au"), 0.05f, 0.3f), kWhite, 0.05f},
        {"BeckmannTitaniumRough", beckmannConductor(metal("Ti"), 0.7f, 0.7f), kWhite, 0.7f},
    };
}

class ConductorAgreement : public testing::TestWithParam<Case> {};

// The mean sample weight equals the quadrature of eval |cos| (the albedo, within 1%), pdf()
// integrates to the share of draws that return a direction, and neither exceeds one.
TEST_P(ConductorAgreement, SamplingMatchesQuadratureOfEval) {
    const Case& tc = GetParam();
    for (float cosO : kCosines)
        for (float phi : kAzimuths) {
            SCOPED_TRACE("cos(theta_o) = " + std::to_string(cosO) + ", phi = " + std::to_string(phi));
            Vec3 wo = direction(cosO, phi);
            auto mc = estimateBySampling(*tc.material, wo, tinted(tc.tint), TransportMode::Radiance,
                                         uint64_t(cosO * 1000 + phi * 10));
            Channels quad = integrateHemisphere(wo, tc.width, [&](Vec3 wi) {
                return tc.material->eval(wo, wi, tinted(tc.tint), TransportMode::Radiance) * wi.z;
            });
            double pdfIntegral = integrateHemisphere(wo, tc.width, [&](Vec3 wi) {
                return Color(tc.material->pdf(wo, wi, tinted(tc.tint)));
            })[0];
            for (int c = 0; c < 3; ++c) {
                EXPECT_NEAR(mc.mean[c], quad[c], tolerance(quad[c])) << "channel " << c << ", MC se " << mc.stdError[c];
                EXPECT_LE(mc.mean[c], 1.0 + tolerance(1.0));
            }
            EXPECT_LE(pdfIntegral, 1.0 + 0.005);
            EXPECT_NEAR(pdfIntegral, mc.nonDeltaFraction, 0.005);
            std::printf("  %-24s cos %.2f phi %.1f  MC %.4f %.4f %.4f  quad %.4f %.4f %.4f  int pdf %.4f\n",
                        tc.name.c_str(), cosO, phi, mc.mean[0], mc.mean[1], mc.mean[2], quad[0], quad[1], quad[2],
                        pdfIntegral);
        }
}

// f(wo, wi) == f(wi, wo), and nothing below the surface.
TEST_P(ConductorAgreement, EvalIsReciprocal) { expectReciprocal(*GetParam().material, tinted(GetParam().tint)); }

// A sample's pdf is pdf(wo, wi) and its weight eval |cos| / pdf.
TEST_P(ConductorAgreement, SampleAgreesWithPdfAndEval) {
    expectSamplesAgreeWithPdfAndEval(*GetParam().material, tinted(GetParam().tint));
}

INSTANTIATE_TEST_SUITE_P(Conductors, ConductorAgreement, testing::ValuesIn(cases()),
                         [](const testing::TestParamInfo<Case>& info) { return info.param.name; });

// ---- white furnace ----

// With F = 1 (k -> infinity) the albedo is what single scattering on GGX keeps, in closed form
// over normals: int G2(wo, wi) max(0, wo.h) D(h) / wo.z dh with wi = reflect(wo, h) above the
// surface (Heitz 2014; the energy a single-scattering model loses, Kulla & Conty 2017). The
// material's sampling (through its own Fresnel, eval and pdf) must keep exactly that; and
// every real metal keeps less.
TEST(ConductorFurnace, PerfectConductorKeepsTheSingleScatteringAlbedo) {
    const ComplexIor perfect{Color(1.0f), Color(1e4f)};  // F = 1 - 4/k^2 to float precision
    for (GgxAlpha alpha : {GgxAlpha{0.5f, 0.5f}, GgxAlpha{1.0f, 1.0f}, GgxAlpha{0.1f, 0.7f}}) {
        auto material = makeConductor(perfect, alpha);
        auto gold = makeConductor(metal("Au"), alpha);
        GGX ggx(alpha.x, alpha.y);
        for (float cosO : kCosines)
            for (float phi : kAzimuths) {
                Vec3 wo = direction(cosO, phi);
                double expected = integrateNormals(std::min(alpha.x, alpha.y), [&](Vec3 h) {
                    float woDotH = dot(wo, h);
                    Vec3 wi = reflect(wo, h);
                    if (woDotH <= 0 || wi.z <= 0) return 0.0;
                    return double(ggx.G2(wo, wi)) * woDotH * ggx.D(h) / wo.z;
                });
                auto mc = estimateBySampling(*material, wo, tinted(kWhite), TransportMode::Radiance, 17);
                auto goldMc = estimateBySampling(*gold, wo, tinted(kWhite), TransportMode::Radiance, 19);
                EXPECT_LE(expected, 1.0);
                for (int c = 0; c < 3; ++c) {
                    EXPECT_NEAR(mc.mean[c], expected, tolerance(expected)) << "alpha " << alpha.x << " " << alpha.y;
                    EXPECT_LT(goldMc.mean[c], mc.mean[c] + 3 * goldMc.stdError[c]);
                }
                std::printf("  furnace alpha (%.1f, %.1f) cos %.2f phi %.1f  MC %.4f  single-scattering %.4f\n", alpha.x,
                            alpha.y, cosO, phi, mc.mean[0], expected);
            }
    }
}

// The same for Beckmann, whose normals are sampled by D(h) h.z rather than as seen from wo.
TEST(ConductorFurnace, PerfectBeckmannConductorKeepsTheSingleScatteringAlbedo) {
    const ComplexIor perfect{Color(1.0f), Color(1e4f)};
    for (auto [ax, ay] : {std::pair{0.3f, 0.3f}, std::pair{0.8f, 0.8f}, std::pair{0.1f, 0.6f}}) {
        auto material = beckmannConductor(perfect, ax, ay);
        Beckmann beckmann(ax, ay);
        for (float cosO : kCosines)
            for (float phi : kAzimuths) {
                Vec3 wo = direction(cosO, phi);
                double expected = integrateNormals(std::min(ax, ay), [&](Vec3 h) {
                    float woDotH = dot(wo, h);
                    Vec3 wi = reflect(wo, h);
                    if (woDotH <= 0 || wi.z <= 0) return 0.0;
                    return double(beckmann.G2(wo, wi)) * woDotH * beckmann.D(h) / wo.z;
                });
                auto mc = estimateBySampling(*material, wo, tinted(kWhite), TransportMode::Radiance, 37);
                EXPECT_LE(expected, 1.0);
                for (int c = 0; c < 3; ++c)
                    EXPECT_NEAR(mc.mean[c], expected, tolerance(expected)) << "alpha " << ax << " " << ay;
            }
    }
}

// A closed form of that loss: for alpha = 1, D = 1/pi, and at normal incidence h is the half
// vector of n and wi with Lambda(wo) = 0 and G2 = 2 cos_i / (1 + cos_i), so the albedo is
// 1/(4 pi) int G2 d(omega_i) = int_0^1 2 mu / (1 + mu) d(mu) / 2 = 1 - ln 2.
TEST(ConductorFurnace, PerfectConductorAtAlphaOneKeepsOneMinusLnTwo) {
    auto material = makeConductor(ComplexIor{Color(1.0f), Color(1e4f)}, GgxAlpha{1.0f, 1.0f});
    auto mc = estimateBySampling(*material, Vec3(0, 0, 1), tinted(kWhite), TransportMode::Radiance, 29);
    double expected = 1.0 - std::log(2.0);
    for (int c = 0; c < 3; ++c) EXPECT_NEAR(mc.mean[c], expected, 0.005 * expected) << "MC se " << mc.stdError[c];
}

// The smooth limit is a delta mirror weighted by the exact Fresnel at the incidence angle.
TEST(ConductorFurnace, SmoothLimitIsTheExactFresnelMirror) {
    ComplexIor gold = metal("Au");
    auto smooth = makeConductor(gold, GgxAlpha{0.0f, 0.0f});
    EXPECT_EQ(smooth->lobes(), unsigned(kDeltaLobe));
    EXPECT_EQ(makeConductor(gold, GgxAlpha{0.0f, 0.2f})->lobes(), unsigned(kGlossyLobe));
    for (float cosO : kCosines) {
        Vec3 wo = direction(cosO, 0.4f);
        auto s = smooth->sample(wo, 0.5f, {0.3f, 0.6f}, tinted(kWhite), TransportMode::Radiance);
        ASSERT_TRUE(s && s->delta);
        EXPECT_EQ(s->wi, Vec3(-wo.x, -wo.y, wo.z));
        EXPECT_EQ(s->weight, fresnelConductor(cosO, gold.eta, gold.k));
        EXPECT_TRUE(isBlack(smooth->eval(wo, s->wi, tinted(kWhite), TransportMode::Radiance)));
    }
}

// ---- named metals and the scene file ----

TEST(NamedMetals, SymbolsAndPbrtSpectra) {
    for (std::string_view s : {"Ag", "Al", "Au", "Cr", "Cu", "Fe", "Ni", "Pt", "Ti", "W", "CuZn", "MgO", "TiO2"})
        EXPECT_TRUE(findMetal(s)) << s;
    EXPECT_FALSE(findMetal("Unobtainium"));
    for (std::string_view s : {"Ag", "Al", "Au", "Cu", "CuZn", "MgO", "TiO2"}) {
        EXPECT_EQ(findPbrtMetalSpectrum("metal-" + std::string(s) + "-eta"), findMetal(s)->eta) << s;
        EXPECT_EQ(findPbrtMetalSpectrum("metal-" + std::string(s) + "-k"), findMetal(s)->k) << s;
    }
    EXPECT_FALSE(findPbrtMetalSpectrum("metal-Fe-eta"));  // not one of pbrt-v4's named spectra
    // The brass entry must not be mistaken for copper (a prefix of its name).
    EXPECT_NE(findPbrtMetalSpectrum("metal-CuZn-eta"), findPbrtMetalSpectrum("metal-Cu-eta"));
}

using test::expectError;
using test::load;


TEST(ConductorScene, ComplexIndexFields) {
    Color goldF0 = fresnelConductor(1.0f, metal("Au").eta, metal("Au").k);
    EXPECT_EQ(test::mirrorReflectance(test::loadedMaterial({{"type", "conductor"}, {"metal", "Au"}, {"roughness", 0}})), goldF0);
    EXPECT_EQ(test::mirrorReflectance(test::loadedMaterial(
                  {{"type", "conductor"}, {"eta", "metal-Au-eta"}, {"k", "metal-Au-k"}, {"roughness", 0}})),
              goldF0);
    Color n(0.2f, 0.9f, 1.1f), k(3.6f, 2.6f, 2.3f);
    EXPECT_EQ(test::mirrorReflectance(test::loadedMaterial({{"type", "conductor"},
                                             {"eta", {n.x, n.y, n.z}},
                                             {"k", {k.x, k.y, k.z}},
                                             {"roughness", 0}})),
              fresnelConductor(1.0f, n, k));
    // Anisotropic and remapped roughness load as glossy lobes; uroughness 0 alone is not smooth.
    EXPECT_EQ(test::loadedMaterial({{"type", "conductor"}, {"metal", "Cu"}, {"uroughness", 0}, {"vroughness", 0.3}}).lobes(),
              unsigned(kGlossyLobe));
    EXPECT_EQ(test::loadedMaterial({{"type", "conductor"}, {"metal", "Ag"}, {"roughness", 0.01}, {"remap_roughness", true}})
                  .lobes(),
              unsigned(kGlossyLobe));
    // The Schlick form is unchanged.
    EXPECT_EQ(test::mirrorReflectance(test::loadedMaterial({{"type", "conductor"}, {"reflectance", {0.9, 0.6, 0.3}}, {"roughness", 0}})),
              fresnelSchlick(Color(0.9f, 0.6f, 0.3f), 1.0f));
}

TEST(ConductorScene, TexturedIndex) {
    // eta from an image, looked up at the hit's uv (8-bit texels are sRGB-decoded, so in [0, 1]).
    const Material& m = test::loadedMaterial({{"type", "conductor"},
                                     {"eta", {{"texture", "textures/wood.png"}}},
                                     {"k", {3.0, 2.5, 2.0}},
                                     {"roughness", 0}});
    EXPECT_TRUE(m.textured());
    auto wood = ImageTexture::load(test::fixture().scene / "textures/wood.png");
    for (Vec2 uv : {Vec2{0.25f, 0.25f}, Vec2{0.75f, 0.25f}, Vec2{0.4f, 0.9f}}) {
        auto s = m.sample(Vec3(0, 0, 1), 0.5f, {0.5f, 0.5f}, m.inputsAt({uv}), TransportMode::Radiance);
        ASSERT_TRUE(s && s->delta);
        Color eta = vmax(wood->lookup({uv}), Color(1e-3f));
        EXPECT_EQ(s->weight, fresnelConductor(1.0f, eta, Color(3.0f, 2.5f, 2.0f))) << uv.x << " " << uv.y;
    }
    EXPECT_FALSE(test::loadedMaterial({{"type", "conductor"}, {"metal", "Au"}}).textured());
}

TEST(ConductorScene, TexturedRoughness) {
    // A roughness texture reads the mean of its channels at the hit's uv; the lobe there is the
    // one of that constant roughness (remapped the same way).
    const Material& m = test::loadedMaterial({{"type", "conductor"},
                                     {"metal", "Au"},
                                     {"uroughness", {{"texture", "textures/wood.png"}}},
                                     {"vroughness", 0.3},
                                     {"remap_roughness", true}});
    EXPECT_TRUE(m.textured());
    EXPECT_EQ(m.lobes(), unsigned(kGlossyLobe));
    auto wood = ImageTexture::load(test::fixture().scene / "textures/wood.png");
    Vec3 wo = direction(0.6f, 0.4f), wi = direction(0.7f, 3.0f);
    for (Vec2 uv : {Vec2{0.25f, 0.25f}, Vec2{0.75f, 0.25f}, Vec2{0.4f, 0.9f}}) {
        Color texel = wood->lookup({uv});
        float u = (texel.x + texel.y + texel.z) / 3.0f;
        ComplexIor gold = metal("Au");
        auto constant = makeConductor(ComplexIorParam{gold.eta, gold.k}, MicrofacetRoughness{u, 0.3f, RoughnessToAlpha::SquareRoot});
        MaterialInputs at{{uv}, kWhite};
        EXPECT_EQ(m.eval(wo, wi, at, TransportMode::Radiance), constant->eval(wo, wi, at, TransportMode::Radiance));
        EXPECT_EQ(m.pdf(wo, wi, at), constant->pdf(wo, wi, at));
    }
    EXPECT_FALSE(test::loadedMaterial({{"type", "conductor"}, {"metal", "Au"}, {"roughness", 0.3}}).textured());
}

TEST(ConductorScene, RemapRoughnessFollowsPbrt) {
    // pbrt's remap: alpha = sqrt(0.04) = 0.2; unremapped: alpha = 0.04; photon's: 0.2^2 = 0.04.
    auto albedoAt = [](const Material& m) {
        return estimateBySampling(m, direction(0.5f, 0.3f), tinted(kWhite), TransportMode::Radiance, 23).mean[0];
    };
    double remapped = albedoAt(test::loadedMaterial({{"type", "conductor"}, {"metal", "Ag"}, {"roughness", 0.04}, {"remap_roughness", true}}));
    double direct = albedoAt(*makeConductor(metal("Ag"), GgxAlpha{0.2f, 0.2f}));
    EXPECT_NEAR(remapped, direct, 1e-6);
    double unremapped = albedoAt(test::loadedMaterial({{"type", "conductor"}, {"metal", "Ag"}, {"roughness", 0.04}, {"remap_roughness", false}}));
    double photonMapping = albedoAt(test::loadedMaterial({{"type", "conductor"}, {"metal", "Ag"}, {"roughness", 0.2}}));
    EXPECT_NEAR(unremapped, photonMapping, 1e-6);  // 0.2^2 in float is not quite 0.04
}

TEST(ConductorScene, DistributionField) {
    Vec3 wo = direction(0.6f, 0.4f), wi = direction(0.7f, 3.0f);
    auto evalOf = [&](const Material& m) { return m.eval(wo, wi, tinted(kWhite), TransportMode::Radiance); };
    const Material& beckmann = test::loadedMaterial(
        {{"type", "conductor"}, {"metal", "Cu"}, {"roughness", 0.3}, {"remap_roughness", false}, {"distribution", "beckmann"}});
    EXPECT_EQ(evalOf(beckmann), evalOf(*beckmannConductor(metal("Cu"), 0.3f, 0.3f)));
    const Material& ggx = test::loadedMaterial(
        {{"type", "conductor"}, {"metal", "Cu"}, {"roughness", 0.3}, {"remap_roughness", false}, {"distribution", "ggx"}});
    EXPECT_EQ(evalOf(ggx), evalOf(*makeConductor(metal("Cu"), GgxAlpha{0.3f, 0.3f})));
    EXPECT_NE(evalOf(ggx), evalOf(beckmann));
}

TEST(ConductorScene, Errors) {
    const std::string path = "materials.metal.";
    expectError([](Json& d) { d["materials"]["metal"] = {{"type", "conductor"}, {"metal", "Xx"}}; }, path + "metal",
                "unknown metal \"Xx\" (expected one of " + metalSymbols() + ")");
    expectError([](Json& d) { d["materials"]["metal"] = {{"type", "conductor"}, {"eta", "metal-Fe-eta"}, {"k", {1, 1, 1}}}; },
                path + "eta", "unknown named spectrum \"metal-Fe-eta\" (expected [r, g, b] or one of " +
                                  pbrtMetalSpectrumNames() + ")");
    expectError([](Json& d) { d["materials"]["metal"] = {{"type", "conductor"}, {"eta", {1, 1, 1}}}; }, path + "k",
                "missing required field");
    expectError([](Json& d) { d["materials"]["metal"] = {{"type", "conductor"}, {"eta", {0, 1, 1}}, {"k", {1, 1, 1}}}; },
                path + "eta[0]", "must be > 0");
    expectError([](Json& d) { d["materials"]["metal"] = {{"type", "conductor"}, {"metal", "Au"}, {"k", {1, 1, 1}}}; },
                path + "k", "a named metal gives eta and k already: use either metal or eta and k");
    expectError(
        [](Json& d) { d["materials"]["metal"] = {{"type", "conductor"}, {"metal", "Au"}, {"reflectance", {1, 1, 1}}}; },
        path + "reflectance",
        "gives Schlick's F0; the complex index (metal, eta, k) is another way to give the Fresnel term: use one");
    expectError([](Json& d) { d["materials"]["metal"] = {{"type", "conductor"}, {"metal", "Au"}, {"vroughness", 2}}; },
                path + "vroughness", "must be in [0, 1]");
    expectError([](Json& d) { d["materials"]["metal"] = {{"type", "conductor"}, {"metal", "Au"}, {"remap_roughness", 1}}; },
                path + "remap_roughness", "must be true or false");
    expectError([](Json& d) { d["materials"]["metal"] = {{"type", "conductor"}, {"metal", "Au"}, {"distribution", "phong"}}; },
                path + "distribution", "unknown distribution \"phong\" (expected \"ggx\" or \"beckmann\")");
}

// ---- SPPM against the path tracer, with rough gold ----

// The Cornell box with its blocks in anisotropic rough gold: glossy transport both methods
// must agree on.
TEST(ConductorSppmVsPath, RoughGoldBlocksAgreeInMean) {
    auto gold = makeConductor(metal("Au"), GgxAlpha{0.15f, 0.35f});
    test::PathAndSppmMeans means = test::renderPathAndSppm(test::cornellBoxWith(gold, 32), 512, 256, 40000);
    std::printf("  path %.4f %.4f %.4f  sppm %.4f %.4f %.4f\n", means.path.x, means.path.y, means.path.z,
                means.sppm.x, means.sppm.y, means.sppm.z);
    for (int c = 0; c < 3; ++c) EXPECT_NEAR(means.sppm[c], means.path[c], 0.02f * means.path[c]) << "channel " << c;
}

}  // namespace
}  // namespace photon::conductor_tests
