// The surface of a subsurface medium (skin, wax, marble: MediumDescription::subsurface),
// where light enters it diffusely. The boundary's own material (a smooth or rough
// dielectric) reflects light on both sides and refracts the light that leaves the medium,
// as before; the light it lets in from outside goes into every inward direction with
// density cos / pi, a share 1 - F(cos theta_i) of it (F the smooth Fresnel reflectance at
// the boundary's index), as pbrt-v4's BSSRDF lets light in at its probe point by its Sw lobe,
// (1 - F) / (c pi) (pbrt-v4 sec. 11.4; the walk's own boundary losses stand in for c). One
// crossing each way, so camera paths and photons agree:
//   light coming in (a camera path that reaches the surface from inside, a photon from outside):
//       f = (1 - F(cos of the outside direction)) / pi, a smooth lobe a light sample can find;
//   light going out (a camera path from outside, a photon from inside): the boundary itself.
// Light leaving through a sharp refraction and entering by a narrow one made every light
// sample from under the skin a rare hit on a narrow lobe (fireflies under small lights); the
// walk under the surface spreads the light anyway. Energy is kept: what the boundary lets in
// plus what it reflects is 1 (for the smooth boundary, exactly).
#include "materials/fresnel.h"
#include "materials/material.h"

namespace photon {
namespace {

class SubsurfaceBoundary final : public Material {
public:
    SubsurfaceBoundary(MaterialPtr boundary, float ior)
        : Material(Color(1.0f)), boundary_(std::move(boundary)), ior_(ior), smooth_(boundary_->isDeltaOnly()) {}

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
    // outside carries light in.
    Color eval(Vec3 wo, Vec3 wi, const MaterialInputs& in, TransportMode mode, unsigned lobes) const override {
        if (!crosses(wo, wi) || !entering(wo, mode)) return boundary_->eval(wo, wi, in, mode, lobes);
        if (!(lobes & kGlossyLobe)) return Color(0.0f);
        return Color(entered(wo.z > 0 ? wo.z : wi.z) / kPi);
    }

    // The density sample() draws wi with for a camera path (Radiance).
    float pdf(Vec3 wo, Vec3 wi, const MaterialInputs& in, unsigned lobes) const override {
        if (!entering(wo, TransportMode::Radiance)) return boundary_->pdf(wo, wi, in, lobes);
        const float q = (lobes & kGlossyLobe) ? enterProbability(wo) : 0.0f;
        if (crosses(wo, wi)) return q * std::abs(wi.z) / kPi;
        return (1.0f - q) * boundary_->pdf(wo, wi, in, lobes);
    }

    // Where light comes in: with probability q a cosine-distributed direction across the
    // surface, else the boundary's own sample, kept only where it reflects (its refractions
    // are light going out the other way, not this crossing's: dropping them leaves the
    // reflection's estimate unbiased).
    std::optional<BSDFSample> sample(Vec3 wo, float uLobe, Vec2 u, const MaterialInputs& in, TransportMode mode,
                                     unsigned lobes) const override {
        if (wo.z == 0) return std::nullopt;
        if (!entering(wo, mode)) return boundary_->sample(wo, uLobe, u, in, mode, lobes);
        const float q = (lobes & kGlossyLobe) ? enterProbability(wo) : 0.0f;
        if (uLobe < q) {
            // Cosine-weighted on the far side of the surface from wo.
            const float r = std::sqrt(u.x), phi = 2.0f * kPi * u.y;
            const float z = std::sqrt(std::max(0.0f, 1.0f - u.x));
            if (!(z > 0)) return std::nullopt;
            BSDFSample s;
            s.wi = Vec3(r * std::cos(phi), r * std::sin(phi), wo.z > 0 ? -z : z);
            s.pdf = q * z / kPi;
            s.weight = Color(entered(wo.z > 0 ? wo.z : z) / q);
            s.lobeProbability = smooth_ ? q : 1.0f;
            return s;
        }
        if (smooth_) {
            // The smooth boundary's mirror reflection, drawn directly (its sample at uLobe 0
            // reflects, weight 1): F over this choice's probability.
            const float F = fresnelDielectric(wo.z, ior_);
            std::optional<BSDFSample> s = boundary_->sample(wo, 0.0f, u, in, mode, lobes);
            if (!(F > 0) || !s || crosses(wo, s->wi)) return std::nullopt;
            s->weight *= F / (1.0f - q);
            s->pdf = s->lobeProbability = 1.0f - q;
            return s;
        }
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
    // The share of light arriving at cos theta outside that goes in.
    float entered(float cosOutside) const { return 1.0f - fresnelDielectric(cosOutside, ior_); }
    // How often sample() draws the way in: 1 - F(wo) (the smooth Fresnel term, 1 under total
    // internal reflection), within [0.1, 0.9]. A photon's two ways then weigh 1 each. A
    // camera path's reflection carries F / (1 - q), its way in about (1 - F_dr) / q: a path
    // under total internal reflection goes on at weight 1 / 0.9, so the second moment of a
    // walk's weights, a product over its hits on the surface, stays bounded; drawing both
    // ways as they weigh (q = (1 - F_dr) / (1 - F_dr + F)) made it 1.94 a hit there and the
    // white furnace of tests/test_subsurface_reflectance.cpp noisy by 2.5% at 256 passes.
    float enterProbability(Vec3 wo) const { return std::clamp(1.0f - fresnelDielectric(wo.z, ior_), 0.1f, 0.9f); }

    MaterialPtr boundary_;
    float ior_;
    bool smooth_;          // the boundary is a smooth dielectric (delta lobes only)
};

}  // namespace

MaterialPtr makeSubsurfaceBoundary(MaterialPtr boundary, float ior) {
    return std::make_shared<SubsurfaceBoundary>(std::move(boundary), ior);
}

}  // namespace photon
