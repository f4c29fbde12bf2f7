// The surface of a subsurface medium (skin, wax, marble: MediumDescription::subsurface),
// where light comes in as from a diffuse sky. The boundary's own material (a smooth or rough
// dielectric) reflects light on both sides and refracts the light that leaves the medium,
// as before. The light it lets in from outside direction w_out goes to inside direction
// w_in by the separable Fresnel lobe of the dipole BSSRDF (Jensen et al. 2001, eq. 4: the
// Fresnel transmittances of the two directions):
//
//     f(w_in, w_out) = (1 - F(w_out)) (1 - F(w_in)) / (pi (1 - F_dr)),
//
// F the smooth Fresnel reflectance at the boundary's index (F(w_in) seen from inside: 1
// beyond the critical angle), F_dr its mean over cosine-weighted inside directions. Of light
// arriving along w_out a share 1 - F(w_out) comes in, as through the smooth boundary, so it
// keeps energy with the reflection; under light that arrives alike from every direction the
// radiance inside is n^2 (1 - F(w_in)) times it, as refraction makes it (since 1 - F_dr
// outside = n^2 (1 - F_dr inside)): light comes in within the refraction cone, to the depth
// refraction takes it to, and a lossless ball in a white sky stays white. It only forgets
// where the light came from, as pbrt-v4's BSSRDF does (its Sw lobe).
//
// One crossing each way, so camera paths and photons agree: light coming in (a camera path
// that reaches the surface from inside, a photon from outside) takes this lobe, light going
// out (a camera path from outside, a photon from inside) the boundary. A camera path from
// inside then sees a smooth lobe over the outside that a light sample can find, where the
// refraction out of a rough surface is a narrow lobe a light sample rarely meets (fireflies
// under small lights); with the refraction's own odds (1 - F(w_in), else the reflection) its
// weights are those of the refraction, n^2 (1 - F) on average.
#include "materials/fresnel.h"
#include "materials/material.h"

namespace photon {
namespace {

class SubsurfaceBoundary final : public Material {
public:
    SubsurfaceBoundary(MaterialPtr boundary, float ior)
        : Material(Color(1.0f)), boundary_(std::move(boundary)), ior_(ior), smooth_(boundary_->isDeltaOnly()),
          cone_(ior > 1 ? 1.0f / ior : 1.0f) {
        // F_dr inside: 2 int_0^1 F(-mu) mu dmu, by the midpoint rule.
        constexpr int kSteps = 4096;
        double sum = 0;
        for (int i = 0; i < kSteps; ++i) {
            const double mu = (i + 0.5) / kSteps;
            sum += fresnelDielectric(-float(mu), ior_) * mu;
        }
        transmittedInside_ = float(1.0 - 2.0 * sum / kSteps);
    }

    unsigned lobes() const override { return boundary_->lobes() | kGlossyLobe; }
    bool twoSided() const override { return false; }
    bool textured() const override { return boundary_->textured(); }
    bool bendsNormal() const override { return boundary_->bendsNormal(); }
    Vec3 bentNormal(const TexturePoint& at, Vec3 n, Vec3 ng, const SurfaceTangents& t) const override {
        return boundary_->bentNormal(at, n, ng, t);
    }
    std::optional<float> refractiveIndex() const override { return ior_; }

    // In the local frame z points outside. `mode` says which way light flows: a camera path
    // (Radiance) at wo inside gathers the light that comes in; a photon (Importance) at wo
    // outside carries light in. The lobe is symmetric, so both read it alike.
    Color eval(Vec3 wo, Vec3 wi, const MaterialInputs& in, TransportMode mode, unsigned lobes) const override {
        if (!crosses(wo, wi) || !entering(wo, mode)) return boundary_->eval(wo, wi, in, mode, lobes);
        if (!(lobes & kGlossyLobe)) return Color(0.0f);
        return Color(comingIn(wo, wi));
    }

    // The density sample() draws wi with for a camera path (Radiance).
    float pdf(Vec3 wo, Vec3 wi, const MaterialInputs& in, unsigned lobes) const override {
        if (!entering(wo, TransportMode::Radiance)) return boundary_->pdf(wo, wi, in, lobes);
        const float q = (lobes & kGlossyLobe) ? transmitted(wo.z) : 0.0f;
        if (crosses(wo, wi)) return q * std::abs(wi.z) / kPi;
        return (1.0f - q) * boundary_->pdf(wo, wi, in, lobes);
    }

    // Where light comes in: with the refraction's probability 1 - F(wo) a direction across
    // the surface (for a camera path cosine-weighted over the outside; for a photon
    // cosine-weighted within the refraction cone inside), else the boundary's reflection (the
    // smooth one drawn directly; a rough one's sample kept only where it reflects: its
    // refractions are light going out the other way, and dropping them leaves the
    // reflection's estimate unbiased).
    std::optional<BSDFSample> sample(Vec3 wo, float uLobe, Vec2 u, const MaterialInputs& in, TransportMode mode,
                                     unsigned lobes) const override {
        if (wo.z == 0) return std::nullopt;
        if (!entering(wo, mode)) return boundary_->sample(wo, uLobe, u, in, mode, lobes);
        const float q = (lobes & kGlossyLobe) ? transmitted(wo.z) : 0.0f;
        if (uLobe < q) {
            // Malley's method on a disc of radius s: cosine-weighted within the cone of
            // half-angle asin(s), density cos / (pi s^2).
            const bool camera = mode == TransportMode::Radiance;
            const float s = camera ? 1.0f : cone_;
            const float r = s * std::sqrt(u.x), phi = 2.0f * kPi * u.y;
            const float z = std::sqrt(std::max(0.0f, 1.0f - r * r));
            if (!(z > 0)) return std::nullopt;
            BSDFSample b;
            b.wi = Vec3(r * std::cos(phi), r * std::sin(phi), wo.z > 0 ? -z : z);
            b.pdf = q * z / (kPi * s * s);
            const float f = comingIn(wo, b.wi);
            if (!(f > 0)) return std::nullopt;
            b.weight = Color(f * z / b.pdf);
            b.lobeProbability = smooth_ ? q : 1.0f;
            return b;
        }
        if (smooth_) {
            // The smooth boundary's mirror reflection, drawn directly (its sample at uLobe 0
            // reflects, weight 1): F(wo) over this choice's probability 1 - q, which is F(wo).
            const float F = fresnelDielectric(wo.z, ior_);
            std::optional<BSDFSample> s = boundary_->sample(wo, 0.0f, u, in, mode, lobes);
            if (!(F > 0) || !s || crosses(wo, s->wi)) return std::nullopt;
            s->weight *= F / (1.0f - q);
            s->pdf = s->lobeProbability = 1.0f - q;
            return s;
        }
        if (!(q < 1)) return std::nullopt;
        std::optional<BSDFSample> s = boundary_->sample(wo, (uLobe - q) / (1.0f - q), u, in, mode, lobes);
        if (!s || crosses(wo, s->wi)) return std::nullopt;
        s->weight /= 1.0f - q;
        s->pdf *= 1.0f - q;
        return s;
    }

private:
    // Whether the pair lies on the two sides of the surface.
    static bool crosses(Vec3 wo, Vec3 wi) { return (wo.z > 0) != (wi.z > 0); }
    // Whether light comes in through the crossing at wo: a camera path looking out from
    // inside, a photon arriving from outside.
    static bool entering(Vec3 wo, TransportMode mode) { return mode == TransportMode::Radiance ? wo.z < 0 : wo.z > 0; }
    // The smooth boundary's transmittance along a direction (z < 0: seen from inside).
    float transmitted(float cosTheta) const { return 1.0f - fresnelDielectric(cosTheta, ior_); }
    // f of the way in for a pair across the surface.
    float comingIn(Vec3 wo, Vec3 wi) const {
        return transmitted(wo.z) * transmitted(wi.z) / (kPi * transmittedInside_);
    }

    MaterialPtr boundary_;
    float ior_;
    bool smooth_;                   // the boundary is a smooth dielectric (delta lobes only)
    float cone_;                    // the sine of the refraction cone's half-angle inside
    float transmittedInside_ = 1;   // 1 - F_dr seen from inside
};

}  // namespace

MaterialPtr makeSubsurfaceBoundary(MaterialPtr boundary, float ior) {
    return std::make_shared<SubsurfaceBoundary>(std::move(boundary), ior);
}

}  // namespace photon
