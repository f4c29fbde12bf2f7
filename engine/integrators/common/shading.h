// What integrators need at a surface hit: the material, its local frame and its colour.
#pragma once
#include <bit>
#include <limits>
#include "integrators/common/light_along_ray.h"
#include "math/ball_in_half_spaces.h"
#include "math/frame.h"
#include "math/path_sampler.h"
#include "math/sampling.h"
#include "media/emission_along.h"
#include "media/free_flight.h"
#include "media/henyey_greenstein.h"
#include "scene/scene.h"

namespace photon {

struct ShadingPoint {
    SurfaceHit hit;
    const Material* material = nullptr;
    Frame frame;
    MaterialInputs inputs;  // what the material reads here: uv, and its tint there
};

// `wo` points back along the arriving ray. Two-sided materials see their normals turned
// toward it, so a quad or mesh shades alike whichever way its winding faces.
inline void turnTowardViewer(SurfaceHit& hit, Vec3 wo) {
    if (dot(wo, hit.ng) < 0) {
        hit.ng = -hit.ng;
        hit.ns = -hit.ns;
    }
}
inline void turnTowardViewer(const Material& m, SurfaceHit& hit, Vec3 wo) {
    if (m.twoSided()) turnTowardViewer(hit, wo);
}
inline ShadingPoint makeShadingPoint(const Scene& scene, const SurfaceHit& hit, Vec3 wo) {
    const Material& m = scene.material(hit);
    const TexturePoint at{hit.uv, hit.p, hit.ng};
    ShadingPoint sp{hit, &m, {}, m.inputsAt(at)};
    turnTowardViewer(m, sp.hit, wo);
    if (m.bendsNormal()) sp.hit.ns = m.bentNormal(at, sp.hit.ns, sp.hit.ng, scene.tangentsAt(hit));
    // A fibre's frame runs along it (Material::alignsToTangent).
    sp.frame = m.alignsToTangent() ? Frame::fromNormalAndTangent(sp.hit.ns, scene.tangentsAt(hit).dpdu)
                                   : Frame::fromNormal(sp.hit.ns);
    return sp;
}

// |w.ns| / |w.ng|: how much more a bent shading normal sees of light along w than the
// surface does; 0 for grazing light, where the ratio would explode.
inline float shadingCosineRatio(const SurfaceHit& hit, Vec3 w) {
    float cosG = std::abs(dot(w, hit.ng));
    return cosG > 1e-3f ? std::abs(dot(w, hit.ns)) / cosG : 0.0f;
}

// A path's throughput after its ray's segment through the medium it is in (-1: none): to
// the hit, or for a ray that leaves the scene, to infinity.
inline void absorbAlong(const Scene& scene, int32_t medium, const Ray& ray, float distance, Color& beta) {
    if (medium >= 0) beta *= scene.transmittance(medium, ray.o, ray.d, distance);
}

// Whether the surface hit ends the medium a path is in toward w: beyond it lies another
// medium that does not scatter (vacuum, the glass of a ball). A surface inside the medium
// (a mirror in fog) has it on both sides, and its photons too.
inline bool boundsMediumToward(const Scene& scene, const SurfaceHit& hit, Vec3 w, int32_t medium) {
    const int32_t beyond = scene.mediumToward(hit, w, medium);
    return beyond != medium && !scene.scatters(beyond);
}

// Where a camera path's ray ended: it left the scene, met a surface, or scattered in a
// medium on the way.
enum class RayEnd { Left, Surface, Scattered };

// What a camera path needs to scatter in media: the numbers for its flights (one a segment
// in a medium that scatters), and what its flights so far weigh by colour (free_flight.h).
struct PathInMedia {
    PathSampler& sampler;
    ChromaticFlight flight;
    // The normal of the medium's boundary the ray's segment starts on (zero: none, e.g. the
    // camera or a scattering point), which the caller sets; castPastBoundaries sets it where
    // the ray crosses into another medium, and where the ray scatters gives the planes of
    // that boundary and, with `seesAhead`, of the surface its segment would have ended at
    // where that bounds the medium too (boundsMediumToward): SPPM's volume
    // points count the part of their ball that lies in the medium (storeVolumePoint).
    // `seesAhead` casts the segment whole where a homogeneous medium's flight would only
    // need it to the point (nothing is drawn differently).
    Vec3 boundaryNormal{0.0f};
    bool seesAhead = false;
    CuttingPlane behind{}, ahead{};
    // Under a surface (MediumDescription::subsurface): the outward normal of the surface the
    // path came in by (zero: none), toward which its walk is guided, and how the step under
    // way was drawn (media/guided_walk.h), which its next flight consumes.
    Vec3 walkNormal{0.0f};
    GuidedStep step{};
    // Where light sampled along the ray's segments through media that scatter goes
    // (sampleLightAlongRay, render.equiangular), which the caller sets where a light sample
    // would be taken at a point the ray scatters at (null: none is), and the last such
    // segment, whose light sample sampleDirectLightInMedium weighs against those.
    // `lightAlongContinues`: whether such a point traces the phase function's direction for
    // the light it finds (FlightSegment::continues).
    Color* lightAlong = nullptr;
    bool lightAlongContinues = true;
    FlightSegment segment{};
    int raysAlong = 0;  // the shadow rays of those samples, one each whether or not cast (SPPM's cost)
};

// A number in [0, 1) drawn from the ray itself, for the emission estimate of a path that
// carries no sampler: rays of camera paths differ from sample to sample, so their hashes are
// as good as fresh numbers, and the same ray always draws the same.
inline float numberOfRay(const Ray& ray) {
    uint64_t h = 0;
    for (float f : {ray.o.x, ray.o.y, ray.o.z, ray.d.x, ray.d.y, ray.d.z})
        h = mix64<uint64_t>(h ^ std::bit_cast<uint32_t>(f));
    return static_cast<float>(h >> 40) * 0x1p-24f;
}

// Casts the ray from inside `medium` to the first surface that is more than a boundary
// between media (Scene::passesThrough), straight through those, as pbrt-v4's integrators
// skip its "interface" surfaces: no path vertex there. beta takes on each medium's
// absorption on the way (to infinity if the ray leaves the scene), `medium` follows the
// crossings, and hit.t is the whole distance along the ray. With `media`, a ray in a medium
// that scatters may scatter first (sampleFreeFlight): hit then holds only the point (p) and
// the distance (t). Without, the ray keeps only what crosses every medium unscattered (the
// light it finds is the unscattered part, the expected value of what a sampled flight
// would bring). Light the media emit along each segment, to its end at the next surface
// whether or not the path scatters before (sampleEmissionAlong; its number is the flight's,
// each estimate unbiased on its own), is added to `emitted` with weight beta: in full,
// since no light sample is ever taken toward a medium (Light::sampledDirectly).
inline RayEnd castPastBoundaries(const Scene& scene, Ray ray, Color& beta, int32_t& medium, SurfaceHit& hit,
                                 PathInMedia* media = nullptr, Color* emitted = nullptr) {
    // A ray caught between more boundaries than this stops at the last as at a surface (a
    // dielectric of index 1, which sends it on unbent).
    constexpr int kMaxCrossings = 64;
    float travelled = 0;
    for (int crossing = 0;; ++crossing) {
        const bool emits = emitted && medium >= 0 && scene.medium(medium).emits();
        const bool flies = media && scene.scatters(medium);
        const float u = flies || (emits && media) ? media->sampler.get1D() : emits ? numberOfRay(ray) : 0.0f;
        // Light is sampled along the segment where a point it scatters at would take a light
        // sample (not under a surface: walksUnderSurface).
        const bool sampledAlong = flies && media->lightAlong && !scene.lightsAlongRays().empty() &&
                                  !scene.medium(medium).subsurface && !media->step.on;
        // In a homogeneous medium the flight's distance is known first: the ray need only
        // reach that far, which spares Embree the rest of the scene (a walk under skin
        // scatters every few tenths of a millimetre). Nothing is drawn differently. Light
        // sampled along the segment needs all of it.
        Ray probe = ray;
        if (flies && !emits && !sampledAlong && !media->seesAhead && !scene.medium(medium).density)
            probe.tMax = std::min(probe.tMax, homogeneousFlightDistance(scene.medium(medium), u, media->flight, &media->step));
        const bool found = scene.intersect(probe, hit);
        const float segment = found ? hit.t : std::numeric_limits<float>::infinity();
        if (emits) *emitted += beta * sampleEmissionAlong(scene.medium(medium), ray.o, ray.d, segment, u);
        if (flies) {
            media->segment = FlightSegment{ray.o, ray.d, segment, media->flight.ratios, 0.0f, sampledAlong,
                                           media->lightAlongContinues};
            if (sampledAlong) {
                ++media->raysAlong;
                const float uLight = media->sampler.get1D(), uDistance = media->sampler.get1D();
                // A point on an area light, drawn only where there are some: scenes with point
                // lights alone draw what they did before area lights were sampled along rays.
                const Vec2 uPoint = scene.lightsAlongRays().hasAreaLights() ? media->sampler.get2D() : Vec2{};
                *media->lightAlong += sampleLightAlongRay(scene, media->segment, medium, beta, uLight, uDistance, uPoint);
            }
            const float t = sampleFreeFlight(scene.medium(medium), ray.o, ray.d, segment, u, beta, media->flight, &media->step);
            media->step.on = false;
            media->segment.scatteredAt = t;
            if (t < segment) {
                const Vec3 n = media->boundaryNormal;
                media->behind = n.x != 0 || n.y != 0 || n.z != 0
                                    ? CuttingPlane{dot(ray.d, n) > 0 ? -n : n, t * std::abs(dot(ray.d, n))}
                                    : CuttingPlane{};
                media->ahead = media->seesAhead && found && boundsMediumToward(scene, hit, ray.d, medium)
                                   ? CuttingPlane{dot(ray.d, hit.ng) > 0 ? hit.ng : -hit.ng,
                                                  (segment - t) * std::abs(dot(ray.d, hit.ng))}
                                   : CuttingPlane{};
                hit = SurfaceHit{};
                hit.p = ray.o + ray.d * t;
                hit.t = travelled + t;
                return RayEnd::Scattered;
            }
        } else {
            absorbAlong(scene, medium, ray, segment, beta);
        }
        if (!found) return RayEnd::Left;
        travelled += hit.t;
        if (!scene.passesThrough(hit) || crossing == kMaxCrossings) break;
        const int32_t before = medium;
        medium = scene.mediumToward(hit, ray.d, medium);
        if (media) media->boundaryNormal = medium != before && !scene.scatters(before) ? hit.ng : Vec3(0.0f);
        ray = spawnRay(hit.p, hit.ng, ray.d);
    }
    hit.t = travelled;
    return RayEnd::Surface;
}

// Casts a camera path's ray from inside `medium` (castPastBoundaries); returns whether it
// hit. Light the ray reaches directly (the environment when it leaves, emission where it
// lands) is added to L with weight beta when `countEmitted`: all of it on camera paths that
// no light sample could have served (the photon mapper's delta-only paths, radiosity's).
// Integrators that sample lights at non-delta vertices use the form with a BounceSampling
// below.
inline bool traceCameraRay(const Scene& scene, const Ray& ray, Color& beta, int32_t& medium, bool countEmitted,
                           SurfaceHit& hit, Color& L) {
    if (castPastBoundaries(scene, ray, beta, medium, hit, nullptr, countEmitted ? &L : nullptr) == RayEnd::Left) {
        if (countEmitted) L += beta * scene.environment(ray);
        return false;
    }
    if (countEmitted) L += beta * scene.emitted(hit, -ray.d);
    return true;
}

// Russian roulette on a camera path's throughput: survives with probability min(1, its
// largest channel) and is then divided by it; false if the path ends.
inline bool survivesRoulette(Color& beta, float u) {
    const float q = std::min(1.0f, maxComponent(beta));
    if (u >= q) return false;
    beta /= q;
    return true;
}

// How a camera path chose its current ray, for weighting the environment light the ray may
// find against the light sample taken at the vertex it left (multiple importance sampling,
// Veach 1997 ch. 9).
struct BounceSampling {
    bool delta = true;  // the camera ray or a delta bounce: no light sample could find that light
    float pdf = 0;      // the solid-angle density the direction was drawn with, lobe choices included
    Vec3 p, n;          // the vertex left, and its shading normal
    float sideProbability = 1;  // see lightSampleSideProbability
    bool cosine = true;  // a surface's vertex; false: a point in a medium (ReceiverSide)
    bool fitted = true;  // the vertex's light sample was fitted to it (ReceiverSide)
};

// Light samples at a surface that transmits are taken for one side, picked with this
// probability, and keep only light from that side (direct_lighting.cpp); 1 elsewhere.
inline float lightSampleSideProbability(const Material& m) { return m.transmits() ? 0.5f : 1.0f; }

// How the ray leaving sp along a sample s (drawn with probability `pick` among the ways the
// path could continue) was chosen.
inline BounceSampling bounceFrom(const ShadingPoint& sp, const BSDFSample& s, float pick = 1.0f) {
    if (s.delta) return BounceSampling{};
    return BounceSampling{false, pick * s.pdf, sp.hit.p, sp.hit.ns, lightSampleSideProbability(*sp.material)};
}

// Environment light arriving along the ray after `bounce`, each light's radiance weighted
// by the power heuristic: in full after delta bounces; otherwise against the density with
// which the light sample at the vertex, picking that light among the lights, would have
// chosen the ray's direction.
inline Color environmentAfterBounce(const Scene& scene, const BounceSampling& bounce, const Ray& ray) {
    Color L(0.0f);
    // A light sample at a surface that transmits is taken for the side d leaves from.
    const Vec3 n = bounce.sideProbability < 1 && dot(ray.d, bounce.n) < 0 ? -bounce.n : bounce.n;
    for (const Scene::EnvironmentLight& e : scene.environmentLights()) {
        const Color Le = e.light->radianceFromDirection(ray.o, ray.d);
        if (isBlack(Le)) continue;
        if (bounce.delta) {
            L += Le;
            continue;
        }
        const float pLight = bounce.sideProbability * e.pickProbability * e.light->pdfIncident(bounce.p, ReceiverSide(n, bounce.cosine, bounce.fitted), ray.d);
        L += Le * powerHeuristic(bounce.pdf, pLight);
    }
    return L;
}

// The same for emission from the area light e where the ray from `bounce` lands (hit): the
// light sample there picks e for the side d leaves from with a probability that depends on
// the vertex (Scene::directLights).
inline float areaLightBounceWeight(const Scene& scene, const BounceSampling& bounce, const Scene::Emitter& e,
                                   const SurfaceHit& hit, Vec3 d) {
    const Vec3 n = bounce.sideProbability < 1 && dot(d, bounce.n) < 0 ? -bounce.n : bounce.n;
    const float pick = scene.directLights().probability(e.index, bounce.p, n);
    const float pLight = bounce.sideProbability * pick * e.light->pdfIncidentFrom(bounce.p, ReceiverSide(n, bounce.cosine, bounce.fitted), {hit.p, hit.ng, hit.primitive}, d);
    return powerHeuristic(bounce.pdf, pLight);
}

// traceCameraRay for integrators that sample lights at every non-delta vertex with
// sampleDirectLight's BSDF continuation (direct_lighting.h): light the ray finds (emission
// where it lands, the environment where it leaves) counts in full after delta bounces and
// otherwise weighted against the light sample that could have found it too, so that a
// small bright light in a sharp highlight comes from BSDF samples and a large dim one from
// light samples (Veach 1997, ch. 9). With `media` the ray may scatter in a medium on the
// way (castPastBoundaries), where it finds no light.
inline RayEnd traceCameraRay(const Scene& scene, const Ray& ray, Color& beta, int32_t& medium,
                             const BounceSampling& bounce, SurfaceHit& hit, Color& L, PathInMedia* media) {
    const RayEnd end = castPastBoundaries(scene, ray, beta, medium, hit, media, &L);
    if (end == RayEnd::Left) {
        L += beta * environmentAfterBounce(scene, bounce, ray);
    } else if (end == RayEnd::Surface && bounce.delta) {
        L += beta * scene.emitted(hit, -ray.d);
    } else if (end == RayEnd::Surface) {
        if (Scene::Emitter e = scene.emitterAt(hit); e.light) {
            const Color Le = scene.emitted(hit, -ray.d);
            if (!isBlack(Le)) L += beta * Le * areaLightBounceWeight(scene, bounce, e, hit, ray.d);
        }
    }
    return end;
}
// The same for a ray that crosses media unscattered; true if it met a surface.
inline bool traceCameraRay(const Scene& scene, const Ray& ray, Color& beta, int32_t& medium,
                           const BounceSampling& bounce, SurfaceHit& hit, Color& L) {
    return traceCameraRay(scene, ray, beta, medium, bounce, hit, L, nullptr) == RayEnd::Surface;
}

// How a camera path that scattered at p in a medium goes on: toward a direction drawn from
// the medium's phase function (weight 1: it is drawn exactly), weighted against the light
// sample taken there (sampleDirectLightInMedium, whose side of wo the BounceSampling
// records, as a transmitting surface's); with `noLightSample`, where none was taken, the
// light its ray finds counts in full.
inline Ray scatterInMedium(const Scene& scene, Vec3 p, Vec3 wo, int32_t medium, Vec2 u, BounceSampling& bounce,
                           bool noLightSample = false) {
    const PhaseSample s = sampleHenyeyGreenstein(wo, scene.medium(medium).g, u);
    bounce = noLightSample ? BounceSampling{} : BounceSampling{false, s.pdf, p, wo, 0.5f, false, false};
    return Ray{p, s.wi};
}

// How a camera path's walk under a surface goes on from p (a scattering event that
// walksUnderSurface counts): toward the surface it came in by with probability
// GuidedStep::kGuidedProbability (guided_walk.h), else by the phase function; its next flight
// weighs the two (sampleFreeFlight). No light sample was taken: the light its ray finds
// counts in full. Without a walk normal (the camera inside the medium) or in a medium whose
// density varies, the phase function's step as in scatterInMedium.
inline Ray stepUnderSurface(const Scene& scene, Vec3 p, Vec3 wo, int32_t medium, PathInMedia& media,
                            BounceSampling& bounce) {
    const MediumDescription& m = scene.medium(medium);
    const float uChoice = media.sampler.get1D();
    const Vec2 u = media.sampler.get2D();
    bounce = BounceSampling{};
    const Vec3 n = media.walkNormal;
    if ((n.x == 0 && n.y == 0 && n.z == 0) || m.density || media.flight.hero < 0)
        return Ray{p, sampleHenyeyGreenstein(wo, m.g, u).wi};
    GuidedStep& step = media.step;
    step.on = true;
    const Color sigmaT = m.extinction();
    for (int c = 0; c < 3; ++c) step.nu0[c] = dwivediEigenvalue(sigmaT[c] > 0 ? m.scattering[c] / sigmaT[c] : 0.0f);
    Vec3 wi;
    step.guided = uChoice < GuidedStep::kGuidedProbability;
    if (step.guided) {
        const float mu = GuidedStep::sampleMu(u.x, step.nu0[media.flight.hero]);
        const float sine = std::sqrt(std::max(0.0f, 1 - mu * mu)), phi = 2 * 3.14159265358979f * u.y;
        wi = Frame::fromNormal(n).toWorld({sine * std::cos(phi), sine * std::sin(phi), mu});
    } else {
        wi = sampleHenyeyGreenstein(wo, m.g, u).wi;
    }
    step.mu = std::clamp(dot(wi, n), -1.0f, 1.0f);
    step.phase = henyeyGreenstein(dot(wo, wi), m.g);
    return Ray{p, wi};
}

// Whether a path's scattering event in `medium` is one of a walk under a surface
// (MediumDescription::subsurface) that counts as no vertex toward render.max_depth: true
// while the path has taken fewer than kMaxSubsurfaceEvents such events (counted in
// `events`), after which they count as any other. Such events take no light sample: under
// a refracting surface every shadow ray would end on it (Scene::shadowTransmittance), one
// wasted ray an event, hundreds a walk; the ray the event sends on counts the light it
// finds in full instead, so a light inside the medium is still rendered, unbiased.
inline bool walksUnderSurface(const Scene& scene, int32_t medium, int& events) {
    if (!scene.medium(medium).subsurface || events >= MediumDescription::kMaxSubsurfaceEvents) return false;
    ++events;
    return true;
}

// Where a camera path's bounce at `hit` took it from medium `before` into a subsurface
// medium `after`, its walk there is guided back toward this surface (stepUnderSurface).
inline void entersUnderSurface(const Scene& scene, const SurfaceHit& hit, int32_t before, int32_t after, PathInMedia& media) {
    if (after >= 0 && after != before && scene.medium(after).subsurface) media.walkNormal = hit.ng;
}

// Whether a camera path's bounce at `hit`, which took it from medium `before` to `after`,
// is a reflection off the inside of a subsurface medium's surface: part of the walk, no
// vertex toward render.max_depth (walksUnderSurface, which counts it in `events`).
inline bool reflectsUnderSurface(const Scene& scene, const SurfaceHit& hit, int32_t before, int32_t after, int& events) {
    if (before < 0 || after != before || !scene.shape(hit.shape).boundsMedium()) return false;
    return walksUnderSurface(scene, before, events);
}

}  // namespace photon
