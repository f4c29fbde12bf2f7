#include "integrators/common/light_along_ray.h"
#include <array>
#include "math/ray_cone.h"
#include "media/equiangular.h"
#include "media/henyey_greenstein.h"
#include "math/sampling.h"

namespace photon {

namespace {

// The equiangular distances toward a light's point over the part of the segment inside its
// beam: a spot's light reaches no other part, and samples drawn there would be wasted.
std::optional<EquiangularDistances> distancesToward(const FlightSegment& s, const PointLightChoice::Beam& beam) {
    RayInterval lit{0.0f, s.end};
    if (beam.cosMax > 0) {
        const std::optional<RayInterval> inside = rayInsideCone(s.o, s.d, 0.0f, s.end, beam.position, beam.axis, beam.cosMax);
        if (!inside) return std::nullopt;
        lit = *inside;
    }
    return EquiangularDistances::toward(s.o, s.d, lit.start, lit.end, beam.position);
}

// How a segment picks its light among Scene::lightsAlongRays. Up to kWeighed lights, each
// in proportion to what it could bring along the segment without the medium: its mean
// intensity times the integral of 1 / r^2 over the lit part of the segment, which is the
// angle that part subtends from the light over its distance D from the ray,
// (thetaB - thetaA) / D (Kulla & Fajardo 2012, sec. 4.1), so that of a street of lamps in fog
// a ray samples the ones it passes, and a spot whose beam it misses never. Beyond, by power.
class SegmentLightChoice {
public:
    static constexpr size_t kWeighed = 64;

    SegmentLightChoice(const PointLightChoice& lights, const FlightSegment& s) : lights_(lights) {
        if (lights.size() > kWeighed) return;
        for (size_t slot = 0; slot < lights.size(); ++slot) {
            const PointLightChoice::Beam& beam = lights.beam(slot);
            const std::optional<EquiangularDistances> e = distancesToward(s, beam);
            weights_[slot] = e ? beam.meanIntensity * (e->thetaB - e->thetaA) / e->distance : 0.0f;
            total_ += weights_[slot];
        }
    }
    // The slot picked with u (-1: none, where no light's beam meets the segment).
    int32_t pick(float u) const {
        if (lights_.size() > kWeighed) {
            const LightSampler::Pick p = lights_.pickByPower(u);
            return p.light ? int32_t(p.index) : -1;
        }
        if (!(total_ > 0)) return -1;
        float sum = 0;
        const float target = u * total_;
        int32_t last = -1;
        for (size_t slot = 0; slot < lights_.size(); ++slot) {
            if (weights_[slot] <= 0) continue;
            last = int32_t(slot);
            sum += weights_[slot];
            if (target < sum) break;
        }
        return last;
    }
    float probability(size_t slot) const {
        if (lights_.size() > kWeighed) return lights_.powerProbability(slot);
        return total_ > 0 ? weights_[slot] / total_ : 0.0f;
    }

private:
    const PointLightChoice& lights_;
    std::array<float, kWeighed> weights_{};
    float total_ = 0;
};

// The densities with which each strategy draws the point at distance t of the segment
// together with light `light`, whose direction from there is wi.
struct StrategyDensities {
    float flight;  // the free flight, then the light sample's pick for the side wi is on
    float along;   // the light's pick among the point lights, then the equiangular distance
};

StrategyDensities densities(const Scene& scene, const FlightSegment& s, int32_t medium, size_t light, float t, Vec3 wi,
                            const EquiangularDistances& distances, float pickAlong) {
    const MediumDescription& m = scene.medium(medium);
    const Vec3 x = s.o + s.d * t;
    // The flight's density over the channels (free_flight.h: weighFlight's mean): on a
    // density grid sigma_t rho(x) T(t).
    const Color sigmaT = m.extinction() * m.densityAt(x), tr = scene.transmittance(medium, s.o, s.d, t);
    const float flight = (s.ratios.x * sigmaT.x * tr.x + s.ratios.y * sigmaT.y * tr.y + s.ratios.z * sigmaT.z * tr.z) / 3;
    // sampleDirectLightInMedium picks the light for the half of the sphere on wo's side or
    // the other, each with probability 1/2, and keeps the sample only on that side.
    const Vec3 wo = -s.d;
    const float side = dot(wi, wo);
    const float pick = side == 0 ? 0.0f : 0.5f * scene.directLights().probability(light, x, side > 0 ? wo : -wo);
    return {flight * pick, pickAlong * distances.pdf(t)};
}

}  // namespace

Color sampleLightAlongRay(const Scene& scene, const FlightSegment& s, int32_t medium, Color beta, float uLight,
                          float uDistance) {
    const PointLightChoice& lights = scene.lightsAlongRays();
    const SegmentLightChoice choice(lights, s);
    const int32_t slot = choice.pick(uLight);
    if (slot < 0) return Color(0.0f);
    const std::optional<EquiangularDistances> distances = distancesToward(s, lights.beam(size_t(slot)));
    if (!distances) return Color(0.0f);
    const float t = distances->sample(uDistance);
    const Vec3 x = s.o + s.d * t;
    const MediumDescription& m = scene.medium(medium);
    const Color sigmaS = m.scattering * m.densityAt(x);
    if (isBlack(sigmaS)) return Color(0.0f);
    const std::optional<LightSample> ls = lights.light(size_t(slot)).sampleIncident(x, Vec3(0.0f), {0.5f, 0.5f});
    if (!ls) return Color(0.0f);
    const float phase = henyeyGreenstein(dot(-s.d, ls->wi), m.g);
    const Color transmittance = scene.shadowTransmittance(Ray{x, ls->wi, ls->distance * (1.0f - 1e-4f)}, medium);
    if (isBlack(transmittance)) return Color(0.0f);
    const StrategyDensities p = densities(scene, s, medium, lights.index(size_t(slot)), t, ls->wi, *distances,
                                          choice.probability(size_t(slot)));
    if (!(p.along > 0)) return Color(0.0f);
    const Color toX = scene.transmittance(medium, s.o, s.d, t);
    return beta * toX * sigmaS * ls->weight * transmittance * (phase * powerHeuristic(p.along, p.flight) / p.along);
}

float weightAgainstLightAlongRay(const Scene& scene, const FlightSegment& s, int32_t medium, size_t light, Vec3 wi) {
    const PointLightChoice& lights = scene.lightsAlongRays();
    const int32_t slot = lights.slotOf(light);
    if (!s.lightSampled || slot < 0) return 1.0f;
    const std::optional<EquiangularDistances> distances = distancesToward(s, lights.beam(size_t(slot)));
    if (!distances) return 1.0f;
    const float pickAlong = SegmentLightChoice(lights, s).probability(size_t(slot));
    const StrategyDensities p = densities(scene, s, medium, light, s.scatteredAt, wi, *distances, pickAlong);
    return powerHeuristic(p.flight, p.along);
}

}  // namespace photon
