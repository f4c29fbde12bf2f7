// Uniform environment: radiance L from every direction. Photons come from a disc of the
// scene's bounding-sphere radius facing a uniformly chosen direction, so each carries
// L / (pdf_dir pdf_pos) = L 4 pi * pi R^2 (pbrt-v4 12.5.1). With an image, the light is
// an ImageEnvironmentLight instead (image_environment_light.cpp).
#include "math/frame.h"
#include "math/sampling.h"
#include "lights/light_factories.h"

namespace photon {
namespace {

class EnvironmentLight final : public Light {
public:
    EnvironmentLight(const LightDescription& d, SceneSphere bounds) : radiance_(d.radiance), bounds_(bounds) {}

    Color power() const override {
        return radiance_ * (4.0f * kPi * kPi * bounds_.radius * bounds_.radius);
    }

    // Cosine-weighted directions about the surface normal: for a diffuse surface under a
    // uniform sky the estimate is then exact (f cos / pdf = rho / pi * pi). A point in a
    // medium weighs no cosine: uniform over the side's hemisphere, as the sky is.
    std::optional<LightSample> sampleIncident(Vec3, ReceiverSide side, Vec2 u) const override {
        const Vec3 local = side.cosine ? sampleCosineHemisphere(u) : sampleUniformCone(u, 0.0f);
        if (local.z <= 0) return std::nullopt;
        const float pdf = side.cosine ? cosineHemispherePdf(local.z) : uniformConePdf(0.0f);
        return LightSample{Frame::fromNormal(side.n).toWorld(local), std::numeric_limits<float>::infinity(), radiance_ / pdf,
                           pdf};
    }

    float pdfIncident(Vec3, ReceiverSide side, Vec3 wi) const override {
        const float cosine = dot(side.n, wi);
        if (!side.cosine) return cosine > 0 ? uniformConePdf(0.0f) : 0.0f;
        return cosineHemispherePdf(std::max(0.0f, cosine));
    }

    std::optional<PhotonEmission> emitPhoton(Vec2 uPosition, Vec2 uDirection) const override {
        Frame travel = Frame::fromNormal(-sampleUniformSphere(uDirection));
        return PhotonEmission{bounds_.pointOnDiscFacing(travel, uPosition), travel.n, power(), Vec3{}};
    }

    Color radianceFromDirection(Vec3, Vec3) const override { return radiance_; }

private:
    Color radiance_;
    SceneSphere bounds_;
};

}  // namespace

std::unique_ptr<Light> makeEnvironmentLight(const LightDescription& d, SceneSphere bounds) {
    if (d.portal) return makePortalEnvironmentLight(d, bounds);
    if (d.environment.image) return makeImageEnvironmentLight(d, bounds);
    return std::make_unique<EnvironmentLight>(d, bounds);
}

}  // namespace photon
