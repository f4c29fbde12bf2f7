#include "integrators/common/light_along_ray.h"
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

// The densities with which each strategy draws the point at distance t of the segment
// together with light `light`, whose direction from there is wi.
struct StrategyDensities {
    float flight;  // the free flight, then the light sample's pick for the side wi is on
    float along;   // the light's pick among the point lights, then the equiangular distance
};

StrategyDensities densities(const Scene& scene, const FlightSegment& s, int32_t medium, size_t light, float t, Vec3 wi,
                            const EquiangularDistances& distances) {
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
    return {flight * pick, scene.lightsAlongRays().probability(light) * distances.pdf(t)};
}

}  // namespace

Color sampleLightAlongRay(const Scene& scene, const FlightSegment& s, int32_t medium, Color beta, float uLight,
                          float uDistance) {
    const PointLightChoice::Pick pick = scene.lightsAlongRays().pick(uLight);
    if (!pick.light) return Color(0.0f);
    const std::optional<EquiangularDistances> distances = distancesToward(s, pick.beam);
    if (!distances) return Color(0.0f);
    const float t = distances->sample(uDistance);
    const Vec3 x = s.o + s.d * t;
    const MediumDescription& m = scene.medium(medium);
    const Color sigmaS = m.scattering * m.densityAt(x);
    if (isBlack(sigmaS)) return Color(0.0f);
    const std::optional<LightSample> ls = pick.light->sampleIncident(x, Vec3(0.0f), {0.5f, 0.5f});
    if (!ls) return Color(0.0f);
    const float phase = henyeyGreenstein(dot(-s.d, ls->wi), m.g);
    const Color transmittance = scene.shadowTransmittance(Ray{x, ls->wi, ls->distance * (1.0f - 1e-4f)}, medium);
    if (isBlack(transmittance)) return Color(0.0f);
    const StrategyDensities p = densities(scene, s, medium, pick.index, t, ls->wi, *distances);
    if (!(p.along > 0)) return Color(0.0f);
    const Color toX = scene.transmittance(medium, s.o, s.d, t);
    return beta * toX * sigmaS * ls->weight * transmittance * (phase * powerHeuristic(p.along, p.flight) / p.along);
}

float weightAgainstLightAlongRay(const Scene& scene, const FlightSegment& s, int32_t medium, size_t light, Vec3 wi) {
    if (!s.lightSampled || scene.lightsAlongRays().probability(light) == 0) return 1.0f;
    const std::optional<EquiangularDistances> distances = distancesToward(s, scene.lightsAlongRays().beam(light));
    if (!distances) return 1.0f;
    const StrategyDensities p = densities(scene, s, medium, light, s.scatteredAt, wi, *distances);
    return powerHeuristic(p.flight, p.along);
}

}  // namespace photon
