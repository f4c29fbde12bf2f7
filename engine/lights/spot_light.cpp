// Spot light: intensity I inside falloff_angle, smoothly fading to zero at cone_angle
// (pbrt-v4 12.2.1, smoothstep falloff).
#include "math/frame.h"
#include "math/sampling.h"
#include "lights/light_factories.h"

namespace photon {
namespace {

float smoothStep(float x, float a, float b) {
    if (a == b) return x < a ? 0.0f : 1.0f;
    float t = std::clamp((x - a) / (b - a), 0.0f, 1.0f);
    return t * t * (3.0f - 2.0f * t);
}

class SpotLight final : public Light {
public:
    explicit SpotLight(const LightDescription& d)
        : position_(d.position), frame_(Frame::fromNormal(normalize(d.direction))), intensity_(d.intensity),
          cosTotal_(std::cos(d.coneAngleDegrees * kPi / 180.0f)),
          cosFalloffStart_(std::cos(d.falloffAngleDegrees * kPi / 180.0f)) {}

    // Integral of the falloff over the sphere: 2 pi ((1 - cosStart) + (cosStart - cosTotal) / 2),
    // the smoothstep's average over its cos range being 1/2.
    Color power() const override {
        return intensity_ * (2.0f * kPi * ((1.0f - cosFalloffStart_) + (cosFalloffStart_ - cosTotal_) / 2.0f));
    }

    std::optional<LightSample> sampleIncident(Vec3 p, ReceiverSide, Vec2) const override {
        Vec3 toLight = position_ - p;
        float dist2 = lengthSquared(toLight);
        if (dist2 <= 0) return std::nullopt;
        float dist = std::sqrt(dist2);
        Vec3 wi = toLight / dist;
        Color I = intensity_ * falloff(dot(-wi, frame_.n));
        if (isBlack(I)) return std::nullopt;
        return LightSample{wi, dist, I / dist2};
    }

    std::optional<PhotonEmission> emitPhoton(Vec2, Vec2 uDirection) const override {
        Vec3 local = sampleUniformCone(uDirection, cosTotal_);
        Color flux = intensity_ * (falloff(local.z) / uniformConePdf(cosTotal_));
        if (isBlack(flux)) return std::nullopt;
        return PhotonEmission{position_, frame_.toWorld(local), flux, Vec3{}};
    }

    EmissionGeometry emissionGeometry() const override {
        return {EmissionGeometry::Kind::Point, position_, frame_, cosTotal_, {}};
    }
    Color emittedDensity(Vec3 w) const override { return intensity_ * falloff(dot(w, frame_.n)); }
    // Full intensity within the falloff's start, none beyond the cone (pbrt-v4 12.6.1). (Scenes
    // cannot give a falloff wider than the cone; the bound would hold it to the cone.)
    std::optional<LightBounds> bounds() const override {
        LightBounds b;
        b.lo = b.hi = position_;
        b.intensity = average(intensity_);
        b.axis = frame_.n;
        const float thetaTotal = std::acos(std::clamp(cosTotal_, -1.0f, 1.0f));
        const float thetaStart = std::min(std::acos(std::clamp(cosFalloffStart_, -1.0f, 1.0f)), thetaTotal);
        b.cosThetaO = std::cos(thetaStart);
        b.cosThetaE = std::cos(thetaTotal - thetaStart);
        return b;
    }

private:
    float falloff(float cosTheta) const { return smoothStep(cosTheta, cosTotal_, cosFalloffStart_); }
    Vec3 position_;
    Frame frame_;
    Color intensity_;
    float cosTotal_, cosFalloffStart_;
};

}  // namespace

std::unique_ptr<Light> makeSpotLight(const LightDescription& d) { return std::make_unique<SpotLight>(d); }

}  // namespace photon
