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
std::optional<EquiangularDistances> distancesToward(const FlightSegment& s, const LightsAlongRays::Beam& beam) {
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

    SegmentLightChoice(const LightsAlongRays& lights, const FlightSegment& s) : lights_(lights) {
        if (lights.size() > kWeighed) return;
        for (size_t slot = 0; slot < lights.size(); ++slot) {
            weights_[slot] = weightOf(lights.beam(slot), s);
            total_ += weights_[slot];
        }
    }
    // The sum of the weights, which the segment keeps (FlightSegment::choiceTotal) so that
    // the light sample's weight later asks for one light's probability without the others'.
    float total() const { return total_; }
    // probability(slot) of the choice whose total is `total`, to the bit.
    static float probability(const LightsAlongRays& lights, const FlightSegment& s, size_t slot, float total) {
        if (lights.size() > kWeighed) return lights.powerProbability(slot);
        return total > 0 ? weightOf(lights.beam(slot), s) / total : 0.0f;
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
    static float weightOf(const LightsAlongRays::Beam& beam, const FlightSegment& s) {
        const std::optional<EquiangularDistances> e = distancesToward(s, beam);
        return e ? beam.meanIntensity * (e->thetaB - e->thetaA) / e->distance : 0.0f;
    }

    const LightsAlongRays& lights_;
    std::array<float, kWeighed> weights_{};
    float total_ = 0;
};

// The equiangular distances a segment draws for the light in `beam`: toward the point y
// drawn on an area light, or toward a point light within its beam.
std::optional<EquiangularDistances> distancesFor(const FlightSegment& s, const LightsAlongRays::Beam& beam, Vec3 y) {
    return beam.area ? EquiangularDistances::toward(s.o, s.d, 0.0f, s.end, y) : distancesToward(s, beam);
}

// The densities with which each strategy draws the point at distance t of the segment
// together with the light sample ls there (its direction, distance and, on an area light,
// its point's normal): for an area light over t and the solid angle at the point, for a
// point light over t alone. pLight: an area light's sample's solid-angle density for that
// direction (`area`; unused for a point light). And the weight of the light sample against the phase
// function's direction where the path goes on from the point it scatters at (a ray that may
// meet an area light), which both strategies' samples share.
struct StrategyDensities {
    float flight;  // the free flight, then the light sample's pick for the side wi is on and its point
    float along;   // the light's pick among Scene::lightsAlongRays, the equiangular distance and its point
    float againstPhase = 1;
};

StrategyDensities densities(const Scene& scene, const FlightSegment& s, int32_t medium, size_t light, float t,
                            const LightSample& ls, bool area, float pLight, const EquiangularDistances& distances,
                            float pickAlong) {
    const MediumDescription& m = scene.medium(medium);
    const Vec3 x = s.o + s.d * t;
    // The flight's density over the channels (free_flight.h: weighFlight's mean): on a
    // density grid sigma_t rho(x) T(t).
    const Color sigmaT = m.extinction() * m.densityAt(x), tr = scene.transmittance(medium, s.o, s.d, t);
    const float flight = (s.ratios.x * sigmaT.x * tr.x + s.ratios.y * sigmaT.y * tr.y + s.ratios.z * sigmaT.z * tr.z) / 3;
    // sampleDirectLightInMedium picks the light for the half of the sphere on wo's side or
    // the other, each with probability 1/2, and keeps the sample only on that side.
    const Vec3 wo = -s.d;
    const float side = dot(ls.wi, wo);
    if (side == 0) return {0.0f, 0.0f};
    const float pick = 0.5f * scene.directLights().probability(light, x, side > 0 ? wo : -wo);
    const float along = pickAlong * distances.pdf(t);
    if (!area) return {flight * pick, along};
    // An area light: its point y drawn by area is, over the solid angle at x,
    // pointDensity d^2 / |cos|.
    const float cosLight = std::abs(dot(ls.normal, ls.wi));
    const float pPoint = cosLight > 0 ? scene.lights().light(light).pointDensity() * ls.distance * ls.distance / cosLight : 0.0f;
    // Where the path goes on, the light sample's share against the phase function's
    // direction (0 where the light sample cannot draw y: the phase function's alone).
    const float againstPhase = s.continues ? powerHeuristic(pick * pLight, henyeyGreenstein(dot(wo, ls.wi), m.g)) : 1.0f;
    return {flight * pick * pLight, along * pPoint, againstPhase};
}

}  // namespace

Color sampleLightAlongRay(const Scene& scene, FlightSegment& s, int32_t medium, Color beta, float uLight,
                          float uDistance, Vec2 uPoint) {
    const LightsAlongRays& lights = scene.lightsAlongRays();
    const SegmentLightChoice choice(lights, s);
    s.choiceTotal = choice.total();
    const int32_t slot = choice.pick(uLight);
    if (slot < 0) return Color(0.0f);
    const LightsAlongRays::Beam& beam = lights.beam(size_t(slot));
    const Light& light = lights.light(size_t(slot));
    // An area light's point is drawn first, and the distances toward it.
    std::optional<LightPoint> y;
    if (beam.area && !(y = light.samplePointByArea(uPoint))) return Color(0.0f);
    const std::optional<EquiangularDistances> distances = distancesFor(s, beam, y ? y->p : Vec3(0.0f));
    if (!distances) return Color(0.0f);
    const float t = distances->sample(uDistance);
    const Vec3 x = s.o + s.d * t;
    const MediumDescription& m = scene.medium(medium);
    const Color sigmaS = m.scattering * m.densityAt(x);
    if (isBlack(sigmaS)) return Color(0.0f);
    const std::optional<LightSample> ls = y ? light.incidentFromPoint(x, *y) : light.sampleIncident(x, ReceiverSide(Vec3(0.0f), false, false), {0.5f, 0.5f});
    if (!ls) return Color(0.0f);
    const float phase = henyeyGreenstein(dot(-s.d, ls->wi), m.g);
    const Color transmittance = scene.shadowTransmittance(Ray{x, ls->wi, ls->distance * (1.0f - 1e-4f)}, medium);
    if (isBlack(transmittance)) return Color(0.0f);
    // The light sample's density for y: for the side of wo that wi is on.
    const Vec3 n = dot(ls->wi, s.d) < 0 ? -s.d : s.d;
    const float pLight = y ? light.pdfIncidentFrom(x, ReceiverSide(n, false, false), EmitterPoint{y->p, y->n, y->triangle}, ls->wi) : 0.0f;
    const float pickAlong = choice.probability(size_t(slot));
    const StrategyDensities p =
        densities(scene, s, medium, lights.index(size_t(slot)), t, *ls, y.has_value(), pLight, *distances, pickAlong);
    if (!(p.along > 0) || !(p.againstPhase > 0)) return Color(0.0f);
    // ls->weight is Le |cos| / (d^2 pointDensity) on an area light, I / d^2 for a point
    // light: over the rest of the draw's density, the pick and the distance.
    const Color toX = scene.transmittance(medium, s.o, s.d, t);
    return beta * toX * sigmaS * ls->weight * transmittance *
           (phase * p.againstPhase * powerHeuristic(p.along, p.flight) / (pickAlong * distances->pdf(t)));
}

float weightAgainstLightAlongRay(const Scene& scene, const FlightSegment& s, int32_t medium, size_t light,
                                 const LightSample& ls) {
    const LightsAlongRays& lights = scene.lightsAlongRays();
    const int32_t slot = lights.slotOf(light);
    if (!s.lightSampled || slot < 0) return 1.0f;
    const LightsAlongRays::Beam& beam = lights.beam(size_t(slot));
    const std::optional<EquiangularDistances> distances =
        distancesFor(s, beam, s.o + s.d * s.scatteredAt + ls.wi * ls.distance);
    if (!distances) return 1.0f;
    const float pickAlong = SegmentLightChoice::probability(lights, s, size_t(slot), s.choiceTotal);
    const StrategyDensities p =
        densities(scene, s, medium, light, s.scatteredAt, ls, beam.area, ls.pdf, *distances, pickAlong);
    return powerHeuristic(p.flight, p.along);
}

}  // namespace photon
