// Coated conductor: a metal (conductor.cpp's, smooth or rough) under a clear dielectric coat
// of index eta, smooth or GGX-rough, with nothing between them: car paint's clear coat over
// flakes of metal, lacquered brass, pbrt-v4's coatedconductor.
//
//   f = F(wo.h) D G2 / (4 cos_o cos_i)                                  (coat)
//     + (1 - E(cos_o)) (1 - E(cos_i)) f_m(wo', wi') / eta^2              (metal, at once)
//     + M(cos_o) M(cos_i) / (pi Mbar)                                    (metal, held in)
//
// E is the coat's directional albedo (coat_albedo.h), 1 - E what it lets through; wo' and wi'
// are wo and wi refracted through the coat's plane (sin' = sin / eta), where the metal's own
// BRDF f_m is evaluated with its index relative to the coat's. For a smooth coat the second
// term is exact for light that meets the metal once: entering along wi it carries eta^2 (1 -
// F_i) of its radiance into the coat, meets the metal over dw' = cos_i / (eta^2 cos_i') dw,
// and leaves with (1 - F_o) / eta^2 of what the metal sends back, so (1 - F_o)(1 - F_i) f_m /
// eta^2, symmetric in wo and wi; for a Lambertian f_m, coated_diffuse.cpp's base term. This
// is the layered model of Weidlich & Wilkie 2007 ("Arbitrarily Layered Micro-Facet
// Surfaces", sec. 4), the coat's transmission taken from its albedo.
//
// A rough metal sends much of its light where the coat holds it in (beyond the critical
// angle, or reflected back inside): gold of roughness 0.5 under ior 1.5 gets 17-26% of its
// albedo this way (measured at cos 0.9 and 0.45). That
// light meets the metal again and again and leaves in the end, less what the metal absorbs.
// M(mu), what of the light arriving at mu leaves that way, is found when the material is made,
// by a random walk between coat and metal (tabulateTrapped), and given out by the third term:
// energy M(mu_i) for light arriving at mu_i, and reciprocal (Kulla & Conty's form for the
// light a single-scattering model misses, "Revisiting Physically Based Shading at
// Imageworks", 2017). A mirror-smooth metal keeps its light on the mirror direction, where
// it bounces between metal and coat as a geometric series: F + (1 - F)^2 R / (1 - F R) under a
// smooth coat, exact, and 1 for a perfect reflector (R = 1).
//
// Measured against a random walk between coat and metal (tests/test_coated_conductor.cpp, a
// rough coat walked on its microsurface): a smooth coat's albedo within 0.02 over any metal
// roughness; a rough coat over a rough metal within 0.03. A rough coat refracts here through
// its mean plane, so over a mirror-smooth metal the reflection stays sharp where a real coat
// blurs it, and gold comes out too bright at grazing angles (+0.21 at cos 0.2). Not
// modelled: a medium between coat and metal (pbrt-v4's thickness, albedo and g), anisotropic
// coats.
#include <algorithm>
#include <array>
#include <cmath>
#include <tbb/parallel_for.h>
#include "materials/coat_albedo.h"
#include "materials/fresnel.h"
#include "materials/material.h"
#include "materials/microfacet.h"
#include "math/rng.h"
#include "math/sampling.h"

namespace photon {
namespace {

class CoatedConductor final : public Material {
public:
    CoatedConductor(MaterialPtr metal, float ior, float roughness)
        : Material(metal->tint()),
          metal_(std::move(metal)),
          ior_(ior),
          ggx_(roughnessToAlpha(roughness)),
          coat_(ior, ggx_),
          coatLobe_(ggx_.smooth() ? kDeltaLobe : kGlossyLobe),
          metalLobe_(metal_->lobes()) {
        if (metalLobe_ == kGlossyLobe) tabulateTrapped();
    }

    unsigned lobes() const override { return coatLobe_ | metalLobe_; }
    bool textured() const override { return metal_->textured(); }

    Color eval(Vec3 wo, Vec3 wi, const MaterialInputs& in, TransportMode mode, unsigned lobes) const override {
        if (wo.z <= 0 || wi.z <= 0 || !(lobes & kGlossyLobe)) return Color(0.0f);
        Color f(0.0f);
        if (coatLobe_ == kGlossyLobe) f += Color(coatSpecular(wo, wi));
        if (metalLobe_ == kGlossyLobe) f += metalThroughCoat(wo, wi, in, mode) + trapped(wo.z, wi.z, in);
        return f;
    }

    float pdf(Vec3 wo, Vec3 wi, const MaterialInputs& in, unsigned lobes) const override {
        lobes &= this->lobes();
        if (wo.z <= 0 || wi.z <= 0 || !(lobes & kGlossyLobe)) return 0;
        const Choice c = choose(wo, in, lobes);
        float p = 0;
        if (coatLobe_ == kGlossyLobe) {
            auto h = reflectionHalfVector(wo, wi);
            if (h) p += c.coat * ggx_.reflectionPdf(wo, *h);
        }
        if (metalLobe_ == kGlossyLobe) {
            const std::optional<Vec3> a = intoCoat(wo), b = intoCoat(wi);
            // The metal's density over wi' times dw'/dw = cos_i / (eta^2 cos_i').
            if (a && b) p += c.metal * metal_->pdf(*a, *b, in, kGlossyLobe) * wi.z / (ior_ * ior_ * b->z);
            p += c.trapped * cosineHemispherePdf(wi.z);
        }
        return p;
    }

    std::optional<BSDFSample> sample(Vec3 wo, float uLobe, Vec2 u, const MaterialInputs& in, TransportMode mode,
                                     unsigned lobes) const override {
        lobes &= this->lobes();
        if (wo.z <= 0 || !lobes) return std::nullopt;
        if (this->lobes() == kDeltaLobe) return sampleMirrors(wo, in);
        const Choice c = choose(wo, in, lobes);
        if (uLobe < c.coat) {
            if (coatLobe_ == kDeltaLobe) return mirror(wo, Color(coat_(wo.z)), c.coat);
            std::optional<BSDFSample> s = weightedSample(wo, reflect(wo, ggx_.sampleVisibleNormal(wo, u)), in, mode, lobes);
            if (s) s->lobeProbability = metalLobe_ == kDeltaLobe ? c.coat : 1.0f;
            return s;
        }
        if (uLobe >= c.coat + c.metal) {  // the trapped light's broad lobe
            std::optional<BSDFSample> s = weightedSample(wo, sampleCosineHemisphere(u), in, mode, lobes);
            if (s) s->lobeProbability = coatLobe_ == kDeltaLobe ? 1.0f - c.coat : 1.0f;
            return s;
        }
        const std::optional<Vec3> inside = intoCoat(wo);
        if (!inside) return std::nullopt;
        const float uMetal = std::min((uLobe - c.coat) / c.metal, 0.99999994f);
        std::optional<BSDFSample> m = metal_->sample(*inside, uMetal, u, in, mode, metalLobe_);
        if (!m) return std::nullopt;
        if (m->delta) {
            // The metal's mirror maps to the mirror outside; its reflectance m->weight.
            const float E = coat_(wo.z);
            return mirror(wo, m->weight * (1.0f - E) * (1.0f - E) * interreflection(E, m->weight), c.metal);
        }
        const std::optional<Vec3> wi = outOfCoat(m->wi);
        if (!wi) return std::nullopt;  // reflected beyond the critical angle: the trapped lobe's
        std::optional<BSDFSample> s = weightedSample(wo, *wi, in, mode, lobes);
        if (s) s->lobeProbability = coatLobe_ == kDeltaLobe ? 1.0f - c.coat : 1.0f;
        return s;
    }

private:
    // The coat's GGX reflection (Walter et al. 2007, eq. 20), rough coats only.
    float coatSpecular(Vec3 wo, Vec3 wi) const {
        auto h = reflectionHalfVector(wo, wi);
        return h ? fresnelDielectric(dot(wo, *h), ior_) * ggx_.reflectionNoFresnel(wo, wi, *h) : 0.0f;
    }

    // The rough metal's light that leaves the coat at once (the second term above).
    Color metalThroughCoat(Vec3 wo, Vec3 wi, const MaterialInputs& in, TransportMode mode) const {
        const float To = 1.0f - coat_(wo.z), Ti = 1.0f - coat_(wi.z);
        const std::optional<Vec3> a = intoCoat(wo), b = intoCoat(wi);
        if (!a || !b || !(To > 0) || !(Ti > 0)) return Color(0.0f);
        return metal_->eval(*a, *b, in, mode, kGlossyLobe) * (To * Ti / (ior_ * ior_));
    }

    // The rough metal's light the coat holds in at first (the third term above): M(mu_o)
    // M(mu_i) / (pi Mbar), per channel, so that light arriving at mu_i brings M(mu_i) out
    // this way, and reciprocal. A textured metal scales it by its reflectance against the
    // one the table was made with, squared (the light met the metal at least twice).
    Color trapped(float cosO, float cosI, const MaterialInputs& in) const {
        const Color m = trappedAlbedo(cosO, in) * trappedAlbedo(cosI, in);
        Color f(0.0f);
        for (int c = 0; c < 3; ++c)
            if (trappedMean_[c] > 0) f[c] = m[c] / (kPi * trappedMean_[c]);
        return f;
    }

    // M(mu) at a hit: the table's, for a textured metal scaled as above (by its square root,
    // since trapped() multiplies two of them).
    Color trappedAlbedo(float cosTheta, const MaterialInputs& in) const {
        Color m = trappedTableAt(cosTheta);
        if (!metal_->textured()) return m;
        const Color R = metal_->normalReflectance(in);
        for (int c = 0; c < 3; ++c) m[c] *= referenceReflectance_[c] > 0 ? R[c] / referenceReflectance_[c] : 0.0f;
        return m;
    }

    // The table of M, interpolated linearly.
    Color trappedTableAt(float cosTheta) const {
        const float t = std::clamp(cosTheta, 0.0f, 1.0f) * (kTable - 1);
        const int k = std::min(int(t), kTable - 2);
        const float f = t - float(k);
        return trappedTable_[k] * (1.0f - f) + trappedTable_[k + 1] * f;
    }

    // M(mu): the light arriving at mu that the metal reflects, the coat holds in (beyond the
    // critical angle, or reflected back inside), and that leaves after more bounces, by a
    // random walk between coat and metal at construction: the metal's own sampling (at the
    // middle of its uv square), the coat's transmission 1 - E at each meeting taken as an
    // expectation (no choice), 16 x 16 stratified first bounces and a fixed seed for the
    // rest, until less than 1/1000 is left. Then Mbar = 2 int M(mu) mu dmu.
    void tabulateTrapped() {
        constexpr int kGrid = 16, kMaxBounces = 64;
        // A textured colour at its mean, so that a dark texel at the middle does not stand
        // for the whole texture.
        const MaterialInputs in{{{0.5f, 0.5f}, Vec3(0.0f)}, metal_->tint().average()};
        referenceReflectance_ = metal_->normalReflectance(in);
        // Each node from its own random stream, so the table is the same on any thread count.
        tbb::parallel_for(0, kTable, [&](int k) {
            const float mu = std::max(float(k) / (kTable - 1), 1e-3f);
            const std::optional<Vec3> inside = intoCoat({std::sqrt(1.0f - mu * mu), 0.0f, mu});
            Rng rng(0x636f6174, uint64_t(k), 0, StreamPurpose::Setup);
            Color sum(0.0f);
            for (int i = 0; inside && i < kGrid; ++i)
                for (int j = 0; j < kGrid; ++j) {
                    Vec2 u{(float(i) + 0.5f) / kGrid, (float(j) + 0.5f) / kGrid};
                    Vec3 wo = *inside;  // toward where the light came from, above the metal
                    Color beta(1.0f - coat_(mu));
                    for (int bounce = 0; bounce < kMaxBounces && maxComponent(beta) > 1e-3f; ++bounce) {
                        const std::optional<BSDFSample> s = metal_->sample(wo, 0.5f, u, in, TransportMode::Importance, kGlossyLobe);
                        if (!s || s->wi.z <= 0) break;
                        beta *= s->weight;
                        const std::optional<Vec3> up = outOfCoat(s->wi);
                        const float leaves = up ? 1.0f - coat_(up->z) : 0.0f;
                        if (bounce > 0) sum += beta * leaves;  // the first way out is metalThroughCoat's
                        beta *= 1.0f - leaves;
                        wo = Vec3(-s->wi.x, -s->wi.y, s->wi.z);  // reflected back down by the coat
                        u = {rng.uniform(), rng.uniform()};
                    }
                }
            trappedTable_[k] = sum / float(kGrid * kGrid);
        });
        constexpr int kSteps = 1024;
        for (int i = 0; i < kSteps; ++i) {
            const float mu = (float(i) + 0.5f) / kSteps;
            trappedMean_ += trappedTableAt(mu) * (2.0f * mu / kSteps);
        }
    }

    // 1 / (1 - R E): a mirror-smooth metal's light the coat sends back down to it, summed
    // (it stays on the mirror direction).
    static Color interreflection(float E, Color R) {
        return Color(1.0f) / vmax(Color(1.0f) - R * E, Color(1e-6f));
    }

    // Smooth coat over a mirror-smooth metal: one mirror, F + (1 - F)^2 R / (1 - F R).
    std::optional<BSDFSample> sampleMirrors(Vec3 wo, const MaterialInputs& in) const {
        const float F = coat_(wo.z);
        Color R(0.0f);
        if (const std::optional<Vec3> inside = intoCoat(wo))
            if (std::optional<BSDFSample> m = metal_->sample(*inside, 0.5f, {0.5f, 0.5f}, in, TransportMode::Radiance, kDeltaLobe))
                R = m->weight;
        return mirror(wo, Color(F) + R * ((1.0f - F) * (1.0f - F)) * interreflection(F, R), 1.0f);
    }

    // The mirror direction with reflectance `reflectance`, chosen with probability `pick`.
    static BSDFSample mirror(Vec3 wo, Color reflectance, float pick) {
        BSDFSample s;
        s.wi = Vec3(-wo.x, -wo.y, wo.z);
        s.weight = reflectance / pick;
        s.pdf = pick;
        s.delta = true;
        s.lobeProbability = pick;
        return s;
    }

    // Which lobe sample() draws from: the coat, the metal seen through it, or the trapped
    // light, in proportion to what each reflects toward wo, none of them (of those the mask
    // lets through) under 0.05, so that no weight exceeds 20 times its share.
    struct Choice {
        float coat = 0, metal = 0, trapped = 0;
    };
    Choice choose(Vec3 wo, const MaterialInputs& in, unsigned lobes) const {
        const float E = coat_(wo.z), R = maxComponent(metal_->normalReflectance(in));
        Choice c;
        if (lobes & coatLobe_) c.coat = E;
        if (lobes & metalLobe_) {
            c.metal = (1.0f - E) * (1.0f - E) * R;
            if (metalLobe_ == kGlossyLobe) c.trapped = maxComponent(trappedAlbedo(wo.z, in));
        }
        const float sum = c.coat + c.metal + c.trapped;
        if (!(sum > 0)) return (lobes & coatLobe_) ? Choice{1, 0, 0} : Choice{0, 1, 0};
        // The floor, for every lobe present and allowed, then the shares renormalised.
        const bool trappedPresent = (lobes & metalLobe_) && metalLobe_ == kGlossyLobe && maxComponent(trappedMean_) > 0;
        const float floor = kMinLobeProbability * sum;
        if (lobes & coatLobe_) c.coat = std::max(c.coat, floor);
        if (lobes & metalLobe_) c.metal = std::max(c.metal, floor);
        c.trapped = trappedPresent ? std::max(c.trapped, floor) : 0.0f;
        const float total = c.coat + c.metal + c.trapped;
        return {c.coat / total, c.metal / total, c.trapped / total};
    }

    // A direction above the coat refracted into it (Snell, through the coat's plane), and
    // back; none where light cannot cross (an index below 1, or beyond the critical angle).
    std::optional<Vec3> intoCoat(Vec3 w) const { return throughPlane(w, 1.0f / ior_); }
    std::optional<Vec3> outOfCoat(Vec3 w) const { return throughPlane(w, ior_); }
    static std::optional<Vec3> throughPlane(Vec3 w, float sinScale) {
        const float x = w.x * sinScale, y = w.y * sinScale, z2 = 1.0f - x * x - y * y;
        if (!(z2 > 0)) return std::nullopt;
        return Vec3(x, y, std::sqrt(z2));
    }

    static constexpr float kMinLobeProbability = 0.05f;
    static constexpr int kTable = 32;
    MaterialPtr metal_;
    float ior_;
    GGX ggx_;
    CoatAlbedo coat_;
    unsigned coatLobe_, metalLobe_;
    std::array<Color, kTable> trappedTable_{};  // M(mu) at mu = k / (kTable - 1)
    Color trappedMean_{0.0f};                  // Mbar
    Color referenceReflectance_{0.0f};         // the metal's at the uv the table was made at
};

}  // namespace

MaterialPtr makeCoatedConductor(MaterialPtr conductor, float ior, float roughness) {
    return std::make_shared<CoatedConductor>(std::move(conductor), ior, roughness);
}

}  // namespace photon
