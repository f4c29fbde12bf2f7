// Light scattered by a rough dielectric boundary, followed on the microsurface itself: the
// random walk of Heitz, Hanika, d'Eon & Dachsbacher 2016 ("Multiple-Scattering Microfacet
// BSDFs with the Smith Model", sec. 4-6) for a GGX surface of uniform heights. Unlike the
// single-scattering GGX BSDF, which loses the light its facets send into one another
// (alpha 0.25, index 1.5, light arriving from inside at cos(theta) 0.2: 21%, measured),
// the walk keeps all of it: a reference for what a real rough coat reflects and transmits.
#pragma once
#include <cmath>
#include <limits>
#include <optional>
#include "materials/fresnel.h"
#include "math/rng.h"

namespace photon::test {

class MicrosurfaceDielectricWalk {
public:
    MicrosurfaceDielectricWalk(float alpha, float eta) : alpha_(alpha), eta_(eta) {}

    // Light arriving from wi (pointing away from the surface on its side; wi.z < 0 means
    // from inside, index eta). The direction it leaves in: above the boundary (z > 0) or
    // below. Every outcome carries all the flux: a dielectric absorbs nothing.
    std::optional<Vec3> scatter(Vec3 wi, Rng& rng) const {
        if (wi.z >= 0) return walk(wi, eta_, rng);
        // From inside, the boundary is the same surface mirrored, seen from a medium of
        // relative index 1 / eta (the slopes and the uniform heights are symmetric).
        std::optional<Vec3> w = walk(Vec3(wi.x, wi.y, -wi.z), 1.0f / eta_, rng);
        if (!w) return std::nullopt;
        return Vec3(w->x, w->y, -w->z);
    }

private:
    static constexpr float kInfinity = std::numeric_limits<float>::infinity();
    static constexpr int kMaxOrder = 1000;

    // Uniform heights in [-1, 1]: C1(h) and its inverse (Heitz et al. 2016, sec. 4.1).
    static float C1(float h) { return std::clamp(0.5f * (h + 1.0f), 0.0f, 1.0f); }
    static float invC1(float u) { return std::clamp(2.0f * u - 1.0f, -1.0f, 1.0f); }

    // Smith Lambda for any direction of travel: for directions going down it is
    // -1 - Lambda(mirrored) (Heitz et al. 2016, sec. 4.2).
    float lambda(Vec3 w) const {
        if (w.z > 0.9999f) return 0.0f;
        if (w.z < -0.9999f) return -1.0f;
        float tanTheta = std::sqrt(std::max(0.0f, 1.0f - w.z * w.z)) / w.z;
        float a = 1.0f / (tanTheta * alpha_);
        return 0.5f * (-1.0f + (a > 0 ? 1.0f : -1.0f) * std::sqrt(1.0f + 1.0f / (a * a)));
    }

    // The height where a ray travelling along wr from height hr next meets the surface;
    // infinity when it escapes (sec. 4.3, the inverse of the height-dependent G1).
    float nextHeight(Vec3 wr, float hr, float u) const {
        if (wr.z > 0.9999f) return kInfinity;
        if (wr.z < -0.9999f) return invC1(u * C1(hr));
        if (std::abs(wr.z) < 1e-4f) return hr;
        float g1 = wr.z > 0 ? std::pow(C1(hr), lambda(wr)) : 0.0f;
        if (u > 1.0f - g1) return kInfinity;
        return invC1(C1(hr) / std::pow(1.0f - u, 1.0f / lambda(wr)));
    }

    // A GGX normal visible from w, for w anywhere on the sphere: the spherical caps of
    // Dupuy & Benyoub 2023 ("Sampling Visible GGX Normals with Spherical Caps", listing 3).
    Vec3 visibleNormal(Vec3 w, Vec2 u) const {
        Vec3 ws = normalize(Vec3(alpha_ * w.x, alpha_ * w.y, w.z));
        float phi = 2.0f * kPi * u.x;
        float z = (1.0f - u.y) * (1.0f + ws.z) - ws.z;
        float sinTheta = std::sqrt(std::clamp(1.0f - z * z, 0.0f, 1.0f));
        Vec3 h = Vec3(sinTheta * std::cos(phi), sinTheta * std::sin(phi), z) + ws;
        return normalize(Vec3(alpha_ * h.x, alpha_ * h.y, h.z));
    }

    // The walk from above (wi.z >= 0) through a boundary of relative index eta (sec. 6).
    std::optional<Vec3> walk(Vec3 wi, float eta, Rng& rng) const {
        Vec3 wr = -wi;  // the direction of travel
        float hr = 1.0f + invC1(0.999f);
        bool outside = true;
        for (int order = 0; order < kMaxOrder; ++order) {
            float u = rng.uniform();
            hr = outside ? nextHeight(wr, hr, u) : -nextHeight(-wr, -hr, u);
            if (std::isinf(hr)) return wr;
            // Scattering by one facet: Fresnel's choice between reflection and refraction.
            Vec3 back = -wr;
            float relative = outside ? eta : 1.0f / eta;
            Vec2 um{rng.uniform(), rng.uniform()};
            Vec3 m = outside ? visibleNormal(back, um) : -visibleNormal(-back, um);
            float F = fresnelDielectric(std::max(0.0f, dot(back, m)), relative);
            if (rng.uniform() < F) {
                wr = normalize(reflect(back, m));
            } else {
                std::optional<Refraction> r = refract(back, m, relative);
                if (!r) return std::nullopt;
                wr = normalize(r->wt);
                outside = !outside;
            }
            if (!std::isfinite(hr) || !std::isfinite(wr.z)) return std::nullopt;
        }
        return std::nullopt;
    }

    float alpha_, eta_;
};

}  // namespace photon::test
