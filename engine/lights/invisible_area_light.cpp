// An area light no ray meets (ShapeDescription::invisible; pbrt-v4's area light of alpha 0,
// whose DiffuseAreaLight it treats as a delta-position light for the same reason): its light
// comes only from light samples, so they are weighted as a delta light's, in full (pdf 0
// for multiple importance sampling), and its photons leave it as the visible light's would.
#include "lights/light_factories.h"

namespace photon {

namespace {

class InvisibleAreaLight final : public Light {
public:
    explicit InvisibleAreaLight(std::unique_ptr<Light> light) : light_(std::move(light)) {}
    Color power() const override { return light_->power(); }
    std::optional<LightSample> sampleIncident(Vec3 p, ReceiverSide side, Vec2 u) const override {
        std::optional<LightSample> s = light_->sampleIncident(p, side, u);
        if (s) s->pdf = 0;  // no BSDF sample can find it: nothing to weigh against
        return s;
    }
    std::optional<PhotonEmission> emitPhoton(Vec2 uPosition, Vec2 uDirection) const override {
        return light_->emitPhoton(uPosition, uDirection);
    }
    const EmissionTriangles* emissionTriangles() const override { return light_->emissionTriangles(); }
    std::optional<LightBounds> bounds() const override { return light_->bounds(); }
    // Its points say where it is (Scene::placeLightsInMedia); pointDensity stays 0, so no
    // camera ray samples it along the way (its light samples, of density 0, would weigh
    // nothing against those). pdfIncidentFrom stays 0 (no ray meets it); it has no
    // projection map (emissionGeometry).
    std::optional<LightPoint> samplePointByArea(Vec2 u) const override { return light_->samplePointByArea(u); }

private:
    std::unique_ptr<Light> light_;
};

}  // namespace

std::unique_ptr<Light> makeInvisibleAreaLight(std::unique_ptr<Light> light) {
    return std::make_unique<InvisibleAreaLight>(std::move(light));
}

}  // namespace photon
