// A measured BRDF (materials/measured_brdf.h): evaluated, sampled and given its density in
// the tables' own parameterisation, as Dupuy & Jakob 2018 (sec. 5-6) and pbrt-v4's
// MeasuredBxDF use them. The tables are conditioned on wo, the direction the path arrives
// from, in both transport modes: a measured BRDF is reciprocal up to its tabulation.
#include <algorithm>
#include <cmath>
#include "materials/measured_brdf.h"
#include "math/sampling.h"

namespace photon {
namespace {

constexpr float kHalfPi = 0.5f * kPi;

float thetaToU(float theta) { return std::sqrt(std::max(0.0f, theta) / kHalfPi); }
float phiToV(float phi) { return (phi + kPi) / (2.0f * kPi); }
float uToTheta(float u) { return u * u * kHalfPi; }
float vToPhi(float v) { return (2.0f * v - 1.0f) * kPi; }

float thetaOf(Vec3 w) { return std::acos(std::clamp(w.z, -1.0f, 1.0f)); }
float phiOf(Vec3 w) { return std::atan2(w.y, w.x); }

class Measured final : public Material {
public:
    explicit Measured(std::shared_ptr<const MeasuredBrdf> brdf) : Material(ColorParam(Color(1.0f))), brdf_(std::move(brdf)) {}

    unsigned lobes() const override { return kGlossyLobe; }
    // An anisotropic table is measured against the surface's tangent (pbrt-v4's shading dp/du).
    bool alignsToTangent() const override { return !brdf_->isotropic; }

    Color eval(Vec3 wo, Vec3 wi, const MaterialInputs&, TransportMode, unsigned lobes) const override {
        const auto at = halfVectorAt(wo, wi, lobes);
        if (!at) return Color(0.0f);
        return finiteOrZero(value(wo, wi, at->input, at->halfVector, at->blend));
    }

    float pdf(Vec3 wo, Vec3 wi, const MaterialInputs&, unsigned lobes) const override {
        const auto at = halfVectorAt(wo, wi, lobes);
        if (!at) return 0;
        const float p = brdf_->luminance.density(at->input, at->blend) * at->vndfDensity / jacobian(wo, at->wm, at->halfVector.x);
        return std::isfinite(p) ? p : 0.0f;
    }

    std::optional<BSDFSample> sample(Vec3 wo, float, Vec2 u, const MaterialInputs& in, TransportMode mode,
                                     unsigned lobes) const override {
        if (!(lobes & kGlossyLobe) || wo.z <= 0) return std::nullopt;
        const float phiO = phiOf(wo);
        const SliceBlend blend = blendAt(wo);
        // The luminance picks the warp's input, the warp a half vector (Dupuy & Jakob 2018, sec. 6).
        const Vec2 input = brdf_->luminance.sample(u, blend).p;
        const Vec2 half = brdf_->vndf.sample(input, blend).p;
        const float thetaM = uToTheta(half.x), phiM = vToPhi(half.y) + (brdf_->isotropic ? phiO : 0.0f);
        const float sinM = std::sin(thetaM);
        const Vec3 wm(sinM * std::cos(phiM), sinM * std::sin(phiM), std::cos(thetaM));
        // The weight through eval() and pdf(), which invert the warp at this wi: the same
        // input and half vector up to rounding, and weight == f cos / pdf exactly.
        auto s = weightedSample(wo, reflect(wo, wm), in, mode, lobes);
        if (s && !isFinite(s->weight)) return std::nullopt;
        return s;
    }

private:
    // A file's tables are finite (scene/measured_brdf_file.cpp) but may be large enough for
    // their products to overflow: such a value reflects nothing rather than infinite light.
    static Color finiteOrZero(Color c) { return isFinite(c) ? c : Color(0.0f); }

    struct HalfVector {
        Vec3 wm;
        Vec2 halfVector;  // (u(theta_m), v(phi_m)) as the tables hold it
        Vec2 input;       // the vndf's input that reaches it
        float vndfDensity;
        SliceBlend blend;
    };

    SliceBlend blendAt(Vec3 wo) const {
        const float params[2] = {phiOf(wo), thetaOf(wo)};
        return brdf_->outgoing.blend(params);
    }

    std::optional<HalfVector> halfVectorAt(Vec3 wo, Vec3 wi, unsigned lobes) const {
        if (!(lobes & kGlossyLobe) || wo.z <= 0 || wi.z <= 0) return std::nullopt;
        const Vec3 sum = wo + wi;
        const float length2 = dot(sum, sum);
        if (!(length2 > 0)) return std::nullopt;
        HalfVector h;
        h.wm = sum * (1.0f / std::sqrt(length2));
        const float phiM = phiOf(h.wm) - (brdf_->isotropic ? phiOf(wo) : 0.0f);
        const float v = phiToV(phiM);
        h.halfVector = Vec2{thetaToU(thetaOf(h.wm)), v - std::floor(v)};
        h.blend = blendAt(wo);
        const auto inverted = brdf_->vndf.invert(h.halfVector, h.blend);
        h.input = inverted.p;
        h.vndfDensity = inverted.pdf;
        return h;
    }

    Color value(Vec3 wo, Vec3 wi, Vec2 input, Vec2 halfVector, const SliceBlend& blend) const {
        const float sigma = brdf_->sigma.eval(Vec2{thetaToU(thetaOf(wo)), phiToV(phiOf(wo))}, singleSlice());
        if (!(sigma > 0)) return Color(0.0f);
        const Color r = brdf_->reflectance.eval(input, blend);
        const float d = std::max(0.0f, brdf_->ndf.eval(halfVector, singleSlice()));
        return Color(std::max(0.0f, r.x), std::max(0.0f, r.y), std::max(0.0f, r.z)) * (d / (4.0f * sigma * wi.z));
    }

    // d omega_i / d(u, v) of the half vector's table coordinates: the reflection's 4 (wo . wm)
    // (Walter et al. 2007, eq. 14) times the sphere's sin(theta) d theta d phi in (u, v),
    // 2 pi^2 u sin(theta_m).
    static float jacobian(Vec3 wo, Vec3 wm, float u) {
        const float sinM = std::sqrt(std::max(0.0f, wm.x * wm.x + wm.y * wm.y));
        return 4.0f * std::max(dot(wo, wm), 1e-6f) * std::max(2.0f * kPi * kPi * u * sinM, 1e-6f);
    }

    std::shared_ptr<const MeasuredBrdf> brdf_;
};

}  // namespace

MaterialPtr makeMeasured(std::shared_ptr<const MeasuredBrdf> brdf) { return std::make_shared<Measured>(std::move(brdf)); }

}  // namespace photon
