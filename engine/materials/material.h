// The one interface every material implements. All directions are in the local
// shading frame (z = shading normal) and point away from the surface.
#pragma once
#include <functional>
#include <memory>
#include <optional>
#include <vector>
#include "materials/normal_map.h"
#include "math/frame.h"
#include <photon/vec.h>
#include "texture/color_param.h"
#include "texture/float_param.h"

namespace photon {

// Which way light flows along the path being traced. Refraction scales radiance by
// 1/eta^2 but not importance (Veach 1997, sec. 5.2), so the two differ for dielectrics.
enum class TransportMode { Radiance, Importance };

// Lobes a material has; integrators decide from these where a camera path stops.
enum LobeFlags : unsigned { kDiffuseLobe = 1u, kGlossyLobe = 2u, kDeltaLobe = 4u, kAllLobes = 7u };

// What a material reads at a surface point: where its textures are read (uv and point),
// and its tint (the colour parameter, see Material::tint) looked up there once, since
// nearly every call needs it. Materials with other textured parameters look them up at `at`.
struct MaterialInputs {
    TexturePoint at;
    Color tint;
    MaterialInputs() = default;
    // A constructor, not an aggregate: {uv, tint} would otherwise fill `at` with uv and tint.
    MaterialInputs(const TexturePoint& at_, Color tint_) : at(at_), tint(tint_) {}
};

struct BSDFSample {
    Vec3 wi;            // sampled incident direction (local frame)
    Color weight;       // f * |cos(theta_i)| / pdf, already divided by lobeProbability
    float pdf = 0;      // solid-angle density for non-delta lobes; the choice probability for delta ones
    bool delta = false; // true if wi came from a Dirac lobe (mirror, refraction)
    // Probability that sampling picked this kind of lobe (delta vs non-delta). A camera
    // path that stops on the non-delta part of a mixed material divides by it.
    float lobeProbability = 1;
};

class Material {
public:
    virtual ~Material() = default;
    virtual unsigned lobes() const = 0;
    // Every call can be restricted to some of the lobes (`lobes`, a LobeFlags mask): the
    // material then behaves as if it had only those.
    // f(wo, wi) of the non-delta lobes; zero for pure delta materials.
    virtual Color eval(Vec3 wo, Vec3 wi, const MaterialInputs& in, TransportMode mode, unsigned lobes = kAllLobes) const = 0;
    // Solid-angle density with which sample() returns wi for the non-delta lobes.
    virtual float pdf(Vec3 wo, Vec3 wi, const MaterialInputs& in, unsigned lobes = kAllLobes) const = 0;
    // uLobe picks a lobe, u the direction within it.
    virtual std::optional<BSDFSample> sample(Vec3 wo, float uLobe, Vec2 u, const MaterialInputs& in, TransportMode mode,
                                             unsigned lobes = kAllLobes) const = 0;
    // For a material with a diffuse lobe beside others: the probability with which a
    // camera path should stop on the diffuse lobe alone rather than follow the others
    // (roughly the diffuse lobe's share of the albedo at wo).
    virtual float diffuseShare(Vec3 wo, const MaterialInputs& in) const { return 1.0f; }

    // The material's colour parameter (albedo or reflectance), constant or textured.
    // Evaluated once per hit and passed back in MaterialInputs::tint.
    const ColorParam& tint() const { return tint_; }
    MaterialInputs inputsAt(const TexturePoint& at) const { return {at, tint_.eval(at)}; }
    // True if any parameter is a texture: hits on the material then need uv.
    virtual bool textured() const { return tint_.textured(); }
    // Opaque materials shade both sides alike (the normal is turned toward the viewer);
    // a dielectric's orientation tells inside from outside, so it is not two-sided.
    virtual bool twoSided() const { return true; }
    // True if f = tint / pi for every pair of directions above the surface (and 0
    // otherwise): integrators may then premultiply it instead of calling eval().
    virtual bool lambertian() const { return false; }
    // A perfect mirror (ior 0) or a smooth dielectric boundary of index ior: one whose
    // sample() is a formula the photon walk can also run for eight photons at once
    // (integrators/photon_paths.cpp), with the same result. Other materials: none.
    struct SmoothSpecular {
        float ior;
    };
    virtual std::optional<SmoothSpecular> smoothSpecular() const { return std::nullopt; }
    // A dielectric boundary's index of refraction, smooth or rough (the inside's over the
    // outside's); none for other materials.
    virtual std::optional<float> refractiveIndex() const {
        const std::optional<SmoothSpecular> s = smoothSpecular();
        return s && s->ior > 0 ? std::optional<float>(s->ior) : std::nullopt;
    }
    // True if the non-delta lobes also scatter light to the far side of the surface
    // (diffuse transmission): light arriving from behind then counts where it is gathered.
    virtual bool transmits() const { return false; }
    // True if the local frame's x axis must be the surface's dp/du: a fibre's scattering
    // (hair) depends on where the fibre points, not only on its normal, and an anisotropic
    // measured BRDF was measured against the surface's dp/du. The integrators then build the
    // frame from the normal and dp/du (Scene::tangentsAt) instead of the normal alone, and
    // store no visible point on it (a visible point keeps only a normal).
    virtual bool alignsToTangent() const { return false; }
    // True if the material bends its shading normal by a normal or bump map
    // (materials/normal_map.h); bentNormal then gives it at `at` for the unbent n.
    virtual bool bendsNormal() const { return false; }
    virtual Vec3 bentNormal(const TexturePoint& at, Vec3 n, Vec3 ng, const SurfaceTangents& tangents) const {
        return n;
    }
    // A reflector's reflectance at normal incidence (its Fresnel term there), for a coat
    // laid over it (coated_conductor.cpp); black for materials that are not reflectors.
    virtual Color normalReflectance(const MaterialInputs& in) const { return Color(0.0f); }
    bool isDeltaOnly() const { return lobes() == kDeltaLobe; }
    bool hasDiffuse() const { return (lobes() & kDiffuseLobe) != 0; }

protected:
    explicit Material(ColorParam tint) : tint_(std::move(tint)) {}
    // A reflected non-delta sample weighted through this material's own eval() and pdf(),
    // so that weight == eval |cos| / pdf holds exactly whatever lobe proposed wi.
    std::optional<BSDFSample> weightedSample(Vec3 wo, Vec3 wi, const MaterialInputs& in, TransportMode mode,
                                             unsigned lobes) const {
        if (wi.z <= 0) return std::nullopt;
        float p = pdf(wo, wi, in, lobes);
        if (!(p > 0)) return std::nullopt;
        BSDFSample s;
        s.wi = wi;
        s.pdf = p;
        s.weight = eval(wo, wi, in, mode, lobes) * (wi.z / p);
        return s;
    }
    ColorParam tint_;
};

using MaterialPtr = std::shared_ptr<const Material>;

// Factories, one file each under materials/.
MaterialPtr makeDiffuse(ColorParam albedo);
MaterialPtr makeMirror(ColorParam reflectance);
MaterialPtr makeDielectric(float ior);
// The same boundary made of GGX microfacets (Walter et al. 2007); alpha = roughness^2.
// Roughness 0 (or so small that alpha < kSmoothAlpha) is the smooth dielectric. ior is the
// relative index n_inside / n_outside and may be below 1 (ice in water: 1.31 / 1.33).
MaterialPtr makeRoughDielectric(float ior, float roughness);
// A thin slab of index ior (window glass): mirror reflection and straight-through
// transmission with the slab's inter-reflections summed; two-sided.
MaterialPtr makeThinDielectric(float ior);
// GGX microfacet conductor with Schlick's Fresnel from `reflectance` (F0);
// alpha = roughness^2 (Burley 2012). roughness 0 is a perfect mirror.
MaterialPtr makeConductor(ColorParam reflectance, float roughness);
// GGX alphas of an anisotropic lobe: x along the shading frame's s axis, y along its t axis
// (math/frame.h). Both below kSmoothAlpha (materials/microfacet.h) make a perfect mirror.
struct GgxAlpha {
    float x, y;
};
// The same conductor with anisotropic roughness.
MaterialPtr makeConductor(ColorParam reflectance, GgxAlpha alpha);
// How a roughness parameter becomes a GGX alpha: photon's perceptual roughness, alpha = r^2
// (Burley 2012); pbrt-v4's remapped roughness, alpha = sqrt(r); or r as alpha itself (pbrt-v4
// without remapping).
enum class RoughnessToAlpha { Square, SquareRoot, Identity };
// The microfacet distribution of a rough conductor: GGX (materials/microfacet.h), long
// tails; or Beckmann (materials/beckmann.h), Gaussian slopes.
enum class MicrofacetDistribution { GGX, Beckmann };
// A lobe's roughness along the shading frame's s (u) and t (v) axes, constant or textured,
// and its distribution. A textured roughness always makes a glossy lobe (each alpha at least
// kSmoothAlpha).
struct MicrofacetRoughness {
    FloatParam u, v;
    RoughnessToAlpha toAlpha = RoughnessToAlpha::Square;
    MicrofacetDistribution distribution = MicrofacetDistribution::GGX;
};
MaterialPtr makeConductor(ColorParam reflectance, MicrofacetRoughness roughness);
// Complex index of refraction eta + i k per colour channel; k is the extinction coefficient.
struct ComplexIor {
    Color eta, k;
};
// The same as colour parameters: constant, or textured and looked up at the hit's uv.
struct ComplexIorParam {
    ColorParam eta, k;
};
// GGX microfacet conductor with the exact Fresnel of the complex index `ior` (the outside
// has index 1); its tint is white and unused.
MaterialPtr makeConductor(ComplexIor ior, GgxAlpha alpha);
MaterialPtr makeConductor(ComplexIorParam ior, MicrofacetRoughness roughness);
// Diffuse base under a dielectric coating of index `ior` with GGX roughness (0 = smooth).
// The cheaper of the two coated models: no internal reflections and no 1/ior^2
// (materials/plastic.cpp); kept so that scenes made with it render as before.
MaterialPtr makePlastic(ColorParam albedo, float ior, float roughness);
// (1 - amount) a + amount b. Throws std::invalid_argument if one part is one-sided (a
// dielectric) and the other two-sided.
MaterialPtr makeMix(MaterialPtr a, MaterialPtr b, FloatParam amount);
// `base` with its shading normal bent by a tangent-space normal map (RGB = (n + 1) / 2 in the
// frame x = dp/du, y = n x (dp/du), z = n; read without the sRGB curve).
MaterialPtr makeNormalMapped(MaterialPtr base, std::shared_ptr<const Texture> normalMap);
// `base` with its shading normal bent by the height field `height` (scene units) along the
// normal: a bump map.
MaterialPtr makeBumpMapped(MaterialPtr base, FloatParam height);
// An opaque material whose back (the side away from its surface's normal) is black
// (materials/one_sided.cpp); base must be two-sided.
MaterialPtr makeOneSided(MaterialPtr base);
// A conductor (makeConductor's) under a clear dielectric coat of index `ior`, GGX-rough or
// smooth (roughness 0): car paint's clear coat over metal, pbrt-v4's coatedconductor
// (materials/coated_conductor.cpp). `conductor` is the base as it is inside the coat: a
// complex index relative to the coat's (eta / ior, k / ior).
MaterialPtr makeCoatedConductor(MaterialPtr conductor, float ior, float roughness);
// Diffuse base under a dielectric coat with internal reflections summed and the rough
// coat's transmission taken from its albedo: energy-conserving (materials/coated_diffuse.cpp).
MaterialPtr makeCoatedDiffuse(ColorParam albedo, float ior, float roughness);
// A family's material (coated_diffuse, plastic) made at a ladder of roughnesses, for
// textured roughness (textured_roughness.cpp). Its colour is read from MaterialInputs, so
// materials of one family and index differing only in colour share one ladder.
using RoughnessLevels = std::vector<MaterialPtr>;
std::shared_ptr<const RoughnessLevels> makeRoughnessLevels(const std::function<MaterialPtr(float)>& make);
// The family's material whose roughness is a texture: roughness^exponent at each point (1,
// or pbrt's meanings: 1/4 with remaproughness, 1/2 without), blended between the levels.
// `tint` is the colour parameter.
MaterialPtr makeTexturedRoughness(ColorParam tint, FloatParam roughness, float exponent,
                                  std::shared_ptr<const RoughnessLevels> levels);
// A hair fibre: Chiang, Bitterli, Tappan and Burley 2016, "A Practical and Controllable
// Hair and Fur Model for Production Path Tracing" (pbrt-v4's HairBxDF): specular
// reflection R, transmission TT, TRT and the residual of higher orders, each a longitudinal
// lobe (Mp) times its attenuation (Ap) times an azimuthal logistic lobe (Np). The local
// frame's x axis runs along the fibre (alignsToTangent), z faces the viewer; the offset h in
// [-1, 1] across the fibre's width is read from the texture coordinates, h = 2 uv.y - 1
// (pbrt-v4's curves set v across their width).
struct HairParameters {
    Color sigmaA{0.0f};      // absorption inside the fibre, per unit of its diameter
    float eta = 1.55f;       // the fibre's index of refraction
    float betaM = 0.3f;      // longitudinal roughness in [0, 1]
    float betaN = 0.3f;      // azimuthal roughness in [0, 1]
    float alphaDegrees = 2;  // tilt of the cuticle scales
};
MaterialPtr makeHair(const HairParameters& parameters);
// sigma_a of a fibre with the given concentrations of eumelanin and pheomelanin (Chiang
// et al. 2016, eq. 8; pbrt-v4's defaults).
Color hairSigmaAFromMelanin(float eumelanin, float pheomelanin);
// sigma_a for which multiple scattering in a mass of such fibres has roughly the colour c
// (Chiang et al. 2016, eq. 9), at azimuthal roughness betaN; and its inverse.
Color hairSigmaAFromReflectance(Color c, float betaN);
Color hairReflectanceFromSigmaA(Color sigmaA, float betaN);
// Translucent sheet: Lambertian reflection (reflectance, the tint) on the side light
// arrives from and Lambertian transmission to the other (reflectance + transmittance <= 1).
MaterialPtr makeDiffuseTransmission(ColorParam reflectance, ColorParam transmittance);
// The surface of a subsurface medium (MediumDescription::subsurface) whose boundary is
// `boundary`, a dielectric of index `ior`: light going out refracts as the boundary makes it,
// light coming in goes by the dipole BSSRDF's separable Fresnel lobe (materials/subsurface_boundary.cpp).
MaterialPtr makeSubsurfaceBoundary(MaterialPtr boundary, float ior);

}  // namespace photon
