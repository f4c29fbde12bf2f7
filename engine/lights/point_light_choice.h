// The lights that send from one point (point, spot, profiled point and projection lights:
// EmissionGeometry::Kind::Point), picked by power: what a camera path samples along its ray
// through a medium that scatters (equiangular distances, media/equiangular.h). Near such a
// light the light a medium scatters grows as 1 / r^2, a spike that free flights, which stop
// where the medium is dense and not where the light is, find too rarely.
#pragma once
#include <vector>
#include "lights/light_sampler.h"

namespace photon {

class PointLightChoice {
public:
    PointLightChoice() = default;
    // The point lights among `all`'s, each with its share of their summed power.
    explicit PointLightChoice(const LightSampler& all);

    // Where a light sends from, and the cone outside which it sends nothing (a spot's beam,
    // a projector's frustum; cosMax -1 for a light that shines every way).
    struct Beam {
        Vec3 position;
        Vec3 axis;
        float cosMax = -1;
    };
    struct Pick {
        const Light* light = nullptr;
        size_t index = 0;  // the light's index in `all`
        float probability = 0;
        Beam beam;
    };
    bool empty() const { return index_.empty(); }
    Pick pick(float u) const {
        const LightSampler::Pick p = byPower_.pick(u);
        if (!p.light) return {};
        return {p.light, index_[p.index], p.probability, beam_[p.index]};
    }
    // The probability pick() returns light i of `all` with (0 for a light that is not one).
    float probability(size_t i) const {
        return i < slot_.size() && slot_[i] >= 0 ? byPower_.probability(size_t(slot_[i])) : 0.0f;
    }
    // Light i of `all`'s beam (one of these lights: probability(i) > 0).
    const Beam& beam(size_t i) const { return beam_[size_t(slot_[i])]; }

private:
    LightSampler byPower_;
    std::vector<size_t> index_;    // by slot: the light's index in `all`
    std::vector<Beam> beam_;       // by slot
    std::vector<int32_t> slot_;    // by light of `all`: its slot, or -1
};

}  // namespace photon
