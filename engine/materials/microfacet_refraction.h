// The geometry of microfacet scattering through a boundary, for materials that transmit as
// well as reflect (Walter, Marschner, Li, Torrance 2007, "Microfacet Models for Refraction
// through Rough Surfaces", EGSR): the microfacet normal that turns wo into wi either way,
// and the Jacobians from microfacet normals to directions. Local shading frame, z = the
// macro normal pointing outside; eta = n_inside / n_outside as in fresnel.h.
#pragma once
#include <cmath>
#include <optional>
#include "materials/fresnel.h"
#include "materials/microfacet.h"

namespace photon {

// The microfacet that scatters light arriving along wi out along wo.
struct MicrofacetPair {
    Vec3 h;           // its normal, in the upper hemisphere
    float etap;       // n on wi's side / n on wo's side: 1 for reflection
    bool reflection;  // wo and wi on the same side
    // |wo + etap wi|^2 = (wo.h + etap wi.h)^2: the bracket of Walter's eqs. 17 and 21
    // divided by n_o^2 (it vanishes only when h is undefined).
    float length2;
};

// The generalised half vector h = -(n_i wi + n_o wo) / |...| (Walter eq. 16; eq. 13 for
// reflection), turned into the upper hemisphere. nullopt where no microfacet connects the
// pair: either direction on the horizon, h undefined, or a microfacet whose back faces
// wo or wi (the chi+ factors of Walter's G, eqs. 20-21). What remains is exactly the pairs
// that reflection or Snell refraction at h produces.
inline std::optional<MicrofacetPair> microfacetPair(Vec3 wo, Vec3 wi, float eta) {
    if (wo.z == 0 || wi.z == 0) return std::nullopt;
    MicrofacetPair p;
    p.reflection = wo.z * wi.z > 0;
    p.etap = p.reflection ? 1.0f : (wo.z > 0 ? eta : 1.0f / eta);
    Vec3 sum = wo + p.etap * wi;
    p.length2 = lengthSquared(sum);
    if (!(p.length2 > 0)) return std::nullopt;
    p.h = sum / std::sqrt(p.length2);
    if (p.h.z < 0) p.h = -p.h;
    if (dot(p.h, wo) * wo.z <= 0 || dot(p.h, wi) * wi.z <= 0) return std::nullopt;
    return p;
}

// The Fresnel reflectance of the pair's microfacet. Reflectance is the same from either side
// of a boundary (Stokes relations), so it is read from the side of lower index: from the
// denser side near the critical angle, fresnelDielectric's sqrt(1 - sin^2 / eta^2) for the
// far side's cosine loses most of its digits, and 1 - F with them, while from the other
// side that cosine is the direction's own. This also makes f(wo, wi) and f(wi, wo) use
// the same value, as reciprocity requires. A reflected pair has wo.h = wi.h, and
// wo + wi = wi + wo in floats too, so the mean of the two is exactly symmetric (F is
// steep enough near the critical angle for their rounding to show).
inline float microfacetFresnel(const MicrofacetPair& p, Vec3 wo, Vec3 wi, float eta) {
    if (p.reflection) return fresnelDielectric(0.5f * (dot(wo, p.h) + dot(wi, p.h)), eta);
    // The outside (z > 0) has the lower index when eta > 1.
    return fresnelDielectric(dot((wo.z > 0) == (eta > 1) ? wo : wi, p.h), eta);
}

// d(omega_h) / d(omega_i) at a pair: 1 / (4 |wo.h|) for reflection (Walter eq. 14), and
// n_i^2 |wi.h| / (n_i wi.h + n_o wo.h)^2 = etap^2 |wi.h| / |wo + etap wi|^2 for refraction
// (Walter eq. 17, with i and o exchanged: here wi is the sampled direction).
inline float halfVectorJacobian(const MicrofacetPair& p, Vec3 wo, Vec3 wi) {
    if (p.reflection) return 1.0f / (4.0f * std::abs(dot(wo, p.h)));
    return p.etap * p.etap * std::abs(dot(wi, p.h)) / p.length2;
}

// The density of normals visible from wo, on either side of the surface, for h in the
// upper hemisphere: G1(wo) |wo.h| D(h) / |wo.z|, the D_wo of Heitz 2018 (microfacet.h).
// Seen from below, the surface is the same one turned over.
inline float visibleNormalDensity(const GGX& ggx, Vec3 wo, Vec3 h) {
    return ggx.G1(wo) * std::abs(dot(wo, h)) * ggx.D(h) / std::abs(wo.z);
}

// Samples that density: GGX::sampleVisibleNormal from wo's side, turned over for wo below.
inline Vec3 sampleVisibleNormalEitherSide(const GGX& ggx, Vec3 wo, Vec2 u) {
    return ggx.sampleVisibleNormal(wo.z >= 0 ? wo : -wo, u);
}

}  // namespace photon
