// The lights a camera path samples along its ray through a medium that scatters
// (equiangular distances, media/equiangular.h): those that send from one point (point, spot,
// profiled point and projection lights: EmissionGeometry::Kind::Point) and area lights,
// toward a point drawn on them by area first (Kulla & Fajardo 2012, sec. 4.2). Near such a
// light the light a medium scatters grows as 1 / r^2, a spike that free flights, which stop
// where the medium is dense and not where the light is, find too rarely.
#pragma once
#include <vector>
#include "lights/light_sampler.h"

namespace photon {

class LightsAlongRays {
public:
    LightsAlongRays() = default;
    // Those among `all`'s lights. Area lights that no ray meets (InvisibleAreaLight, whose
    // light samples carry no density to weigh against) draw no points and are left out.
    explicit LightsAlongRays(const LightSampler& all);

    // Where a light sends from (an area light: the centre of its bounds), the cone outside
    // which it sends nothing (a spot's beam, a projector's frustum; cosMax -1 for a light
    // that shines every way), its mean intensity over that cone (the mean over channels of
    // its power over the cone's solid angle, W/sr), and whether it is an area light, whose
    // samples go toward a point drawn on it (Light::samplePointByArea).
    struct Beam {
        Vec3 position;
        Vec3 axis;
        float cosMax = -1;
        float meanIntensity = 0;
        bool area = false;
    };
    bool empty() const { return index_.empty(); }
    bool hasAreaLights() const { return hasAreaLights_; }
    // The lights, by slot.
    size_t size() const { return index_.size(); }
    const Light& light(size_t slot) const { return byPower_.light(slot); }
    size_t index(size_t slot) const { return index_[slot]; }  // the light's index in `all`
    const Beam& beam(size_t slot) const { return beam_[slot]; }
    // A slot picked by power, and the probability of each.
    LightSampler::Pick pickByPower(float u) const { return byPower_.pick(u); }
    float powerProbability(size_t slot) const { return byPower_.probability(slot); }
    // The slot of light i of `all`, -1 if it is not one of these.
    int32_t slotOf(size_t i) const { return i < slot_.size() ? slot_[i] : -1; }

private:
    LightSampler byPower_;
    std::vector<size_t> index_;    // by slot: the light's index in `all`
    std::vector<Beam> beam_;       // by slot
    std::vector<int32_t> slot_;    // by light of `all`: its slot, or -1
    bool hasAreaLights_ = false;
};

}  // namespace photon
