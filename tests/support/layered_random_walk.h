// A brute-force reference for a Lambertian base, or any reflecting material (a metal),
// under a dielectric coat: light is
// followed as a random walk between the two interfaces: it enters the coat (Fresnel's
// choice at a smooth coat; a rough one's microsurface walked, microsurface_walk.h),
// bounces on the base, meets the coat again from inside (reflected or transmitted, total
// internal reflection included), and so on until it leaves or is absorbed. This is the
// position-free estimator of Guo, Hasan & Zhao 2018 ("Position-Free Monte Carlo
// Simulation for Arbitrary Layered BSDFs", sec. 4) without a medium between the layers,
// as pbrt-v4's LayeredBxDF walks it. It tracks flux (importance transport, no 1/eta^2),
// so its exit directions, weighted, are distributed as f(wi, wo) cos(theta_o).
#pragma once
#include <optional>
#include "bsdf_checks.h"
#include "materials/fresnel.h"
#include "materials/material.h"
#include "materials/microfacet.h"
#include "math/rng.h"
#include "math/sampling.h"
#include "microsurface_walk.h"

namespace photon::test {

struct LayeredExit {
    Vec3 w;        // the direction it leaves in, above the coat
    Color weight;  // flux carried out per unit arriving
};

class LayeredRandomWalk {
public:
    LayeredRandomWalk(Color baseAlbedo, float ior, float roughness)
        : albedo_(baseAlbedo), ior_(ior), alpha_(roughnessToAlpha(roughness)), microsurface_(alpha_, ior) {}
    // A material base, scattered by its own sample() as a photon would be (importance
    // transport), with `inputs` as its inputs.
    LayeredRandomWalk(MaterialPtr base, MaterialInputs inputs, float ior, float roughness)
        : albedo_(1.0f), base_(std::move(base)), inputs_(inputs), ior_(ior), alpha_(roughnessToAlpha(roughness)),
          microsurface_(alpha_, ior) {}

    // Light arriving from direction wi (above the coat, pointing toward the light).
    // Nothing when the base absorbs it.
    std::optional<LayeredExit> trace(Vec3 wi, Rng& rng) const {
        Vec3 wo = wi;  // toward where the light came from, on its side of the coat
        Color beta(1.0f);
        for (int bounce = 0; bounce < kMaxBounces; ++bounce) {
            std::optional<Vec3> next = scatterAtCoat(wo, rng);
            if (!next) return std::nullopt;
            if (next->z > 0) return LayeredExit{*next, beta};  // reflected above, or out through the coat
            if (base_) {
                // Down to a material base: its sample from where the light came.
                const float uLobe = rng.uniform();
                const Vec2 u{rng.uniform(), rng.uniform()};
                std::optional<BSDFSample> s = base_->sample(-*next, uLobe, u, inputs_, TransportMode::Importance);
                if (!s || s->wi.z <= 0) return std::nullopt;
                beta *= s->weight;
                wo = -s->wi;
                continue;
            }
            // Down to the base: Lambertian, so the weight is its albedo and the direction
            // cosine-distributed upward, back to the coat from inside.
            beta *= albedo_;
            if (bounce >= 3) {  // Russian roulette on the largest channel
                float q = std::min(1.0f, maxComponent(beta));
                if (!(rng.uniform() < q)) return std::nullopt;
                beta /= q;
            }
            Vec3 up = sampleCosineHemisphere({rng.uniform(), rng.uniform()});
            if (up.z <= 0) return std::nullopt;
            wo = -up;
        }
        return std::nullopt;
    }

private:
    static constexpr int kMaxBounces = 1000;

    // The coat met with wo on either side (wo.z > 0 outside, < 0 inside): the direction
    // light continues in, with all its flux (the coat absorbs nothing).
    std::optional<Vec3> scatterAtCoat(Vec3 wo, Rng& rng) const {
        if (alpha_ < kSmoothAlpha) {
            float F = fresnelDielectric(wo.z, ior_);  // 1 under total internal reflection
            if (rng.uniform() < F) return Vec3(-wo.x, -wo.y, wo.z);
            std::optional<Refraction> r = refract(wo, Vec3(0, 0, 1), ior_);
            if (!r) return std::nullopt;
            return r->wt;  // flux weight (1 - F) / (1 - F)
        }
        // Rough: the walk on the microsurface, which keeps all the flux.
        return microsurface_.scatter(wo, rng);
    }

    Color albedo_;
    MaterialPtr base_;
    MaterialInputs inputs_{};
    float ior_, alpha_;
    MicrosurfaceDielectricWalk microsurface_;
};

// The walk's exit directions for `paths` lights arriving from wi, binned as
// bsdf_checks::binBySampling bins a material's samples.
inline bsdf_checks::BinnedAlbedo binWalk(const LayeredRandomWalk& walk, Vec3 wi, int paths, Rng& rng) {
    bsdf_checks::BinnedAlbedo bins{};
    for (int i = 0; i < paths; ++i)
        if (auto exit = walk.trace(wi, rng))
            for (int c = 0; c < 3; ++c) bins[bsdf_checks::hemisphereBin(exit->w)][c] += exit->weight[c] / paths;
    return bins;
}

}  // namespace photon::test
