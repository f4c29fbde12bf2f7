#include "integrators/common/photon_paths.h"
#include <limits>
#include <vector>
#include "math/lanes.h"
#include "materials/fresnel.h"
#include "math/sampling.h"
#include "integrators/common/photon_roulette.h"
#include "media/free_flight.h"
#include "media/henyey_greenstein.h"

namespace photon {

namespace {

constexpr int kWalkLanes = 2 * kLanes;
// Eight lanes are refilled with new photons once this many of them are empty (or all are):
// emission costs the same for one photon as for eight, while the rays are cast lane by lane
// and do not mind empty lanes. Measured on photon-bench: 6 about 3% faster than refilling
// every empty lane at once; 4 and 8 between the two.
constexpr int kRefillThreshold = 6;

// Sixteen photons side by side, one per lane, structure of arrays so that eight lanes load
// into one SIMD register.
struct PhotonLanes {
    // The next rays, kept where Embree's packet query reads them: origins and directions
    // are its inputs, never written by it.
    Scene::RayPacket packet;
    float* ox() { return packet.rh.ray.org_x; }
    float* oy() { return packet.rh.ray.org_y; }
    float* oz() { return packet.rh.ray.org_z; }
    float* dx() { return packet.rh.ray.dir_x; }
    float* dy() { return packet.rh.ray.dir_y; }
    float* dz() { return packet.rh.ray.dir_z; }
    alignas(32) float betaR[kWalkLanes], betaG[kWalkLanes], betaB[kWalkLanes];  // flux
    alignas(64) uint64_t state[kWalkLanes], increment[kWalkLanes];             // PCG32 streams
    alignas(32) int32_t depth[kWalkLanes];         // surfaces reached so far
    alignas(32) int32_t walkEvents[kWalkLanes];    // scatterings under surfaces, which depth leaves out
    alignas(32) int32_t alive[kWalkLanes];         // masks: -1 true, 0 false
    alignas(32) int32_t onlySpecular[kWalkLanes];  // every bounce so far off a delta lobe
    alignas(32) uint32_t cell[kWalkLanes];         // EmittedPhoton::cell
    alignas(32) int32_t medium[kWalkLanes];        // the medium it is in (-1: none)
    alignas(32) int32_t firstArrival[kWalkLanes];  // the depth it arrives from (firstArrivalDepth)
    // Its flights in media that scatter (ChromaticFlight, free_flight.h): the hero channel,
    // and each channel's density over the hero's.
    alignas(32) int32_t hero[kWalkLanes];
    alignas(32) float ratioR[kWalkLanes], ratioG[kWalkLanes], ratioB[kWalkLanes];
    // A hit waiting for its bounce in lanes, off a Lambertian or a smooth specular surface:
    // which kind, where, the normals (turned toward the photon on two-sided surfaces), the
    // surface colour, and a specular surface's index (0: a mirror).
    alignas(32) int32_t lambertian[kWalkLanes];
    alignas(32) int32_t specular[kWalkLanes];
    alignas(32) float ior[kWalkLanes];
    alignas(32) float px[kWalkLanes], py[kWalkLanes], pz[kWalkLanes];
    alignas(32) float ngx[kWalkLanes], ngy[kWalkLanes], ngz[kWalkLanes];
    alignas(32) float nsx[kWalkLanes], nsy[kWalkLanes], nsz[kWalkLanes];
    alignas(32) float tintR[kWalkLanes], tintG[kWalkLanes], tintB[kWalkLanes];

    Vec3 direction(int i) const {
        const RTCRay16& r = packet.rh.ray;
        return {r.dir_x[i], r.dir_y[i], r.dir_z[i]};
    }
    Color beta(int i) const { return {betaR[i], betaG[i], betaB[i]}; }
    void setRay(int i, const Ray& r) {
        ox()[i] = r.o.x, oy()[i] = r.o.y, oz()[i] = r.o.z;
        dx()[i] = r.d.x, dy()[i] = r.d.y, dz()[i] = r.d.z;
    }
    void setBeta(int i, Color b) { betaR[i] = b.x, betaG[i] = b.y, betaB[i] = b.z; }
};

Vec3Lanes loadVec3(const float* x, const float* y, const float* z) {
    return {loadLanes<float, FloatLanes>(x), loadLanes<float, FloatLanes>(y), loadLanes<float, FloatLanes>(z)};
}
void storeVec3(float* x, float* y, float* z, const Vec3Lanes& v) {
    storeLanes(x, v.x);
    storeLanes(y, v.y);
    storeLanes(z, v.z);
}

// What follows a bounce sampled for the waiting lanes among [first, first + 8), exactly as
// photonAfterRoulette and spawnRay do it for one photon: Russian roulette (photon_roulette.h:
// survive with q = max(beta weight) / max(beta)), the next ray from just off the surface on
// the side it heads to (ray.h), the depth, and whether the path is still specular only.
PHOTON_LANES_INLINE void continueLanes(PhotonLanes& L, int first, IntLanes waiting, IntLanes sampled, const Vec3Lanes& wi,
                                       const Vec3Lanes& weight, IntLanes bounceIsDelta) {
    uint64_t* state = L.state + first;
    const uint64_t* increment = L.increment + first;
    Vec3Lanes beta = loadVec3(L.betaR + first, L.betaG + first, L.betaB + first);
    Vec3Lanes next = beta * weight;
    FloatLanes q = maxComponent(next) / maxComponent(beta);
    IntLanes rolls = sampled & (q < 1.0f);
    FloatLanes u = uniformLanes(state, increment, rolls);
    IntLanes survives = sampled & ~(rolls & (u >= q));
    next = select(rolls, next * (1.0f / q), next);
    survives &= (maxComponent(next) > 0.0f) & isFiniteLanes(next.x) & isFiniteLanes(next.y) & isFiniteLanes(next.z);

    Vec3Lanes p = loadVec3(L.px + first, L.py + first, L.pz + first);
    Vec3Lanes ng = loadVec3(L.ngx + first, L.ngy + first, L.ngz + first);
    FloatLanes eps = rayOffsetDistance(p.x, p.y, p.z);
    Vec3Lanes offset = ng * eps;
    Vec3Lanes o = select(dot(wi, ng) >= 0.0f, p + offset, p - offset);

    storeVec3(L.ox() + first, L.oy() + first, L.oz() + first, select(waiting, o, loadVec3(L.ox() + first, L.oy() + first, L.oz() + first)));
    storeVec3(L.dx() + first, L.dy() + first, L.dz() + first, select(waiting, wi, loadVec3(L.dx() + first, L.dy() + first, L.dz() + first)));
    storeVec3(L.betaR + first, L.betaG + first, L.betaB + first, select(waiting, next, beta));
    IntLanes depth = loadLanes<int32_t, IntLanes>(L.depth + first);
    storeLanes(L.depth + first, select(waiting, depth + 1, depth));
    IntLanes onlySpecular = loadLanes<int32_t, IntLanes>(L.onlySpecular + first);
    storeLanes(L.onlySpecular + first, onlySpecular & (~waiting | bounceIsDelta));
    IntLanes alive = loadLanes<int32_t, IntLanes>(L.alive + first);
    storeLanes(L.alive + first, select(waiting, survives, alive));
}

// The Lambertian bounce of lanes [first, first + 8) that hold a waiting hit: exactly what
// Diffuse::sample and the walk's continuation do for one photon, with the same random
// numbers, for eight at once.
PHOTON_LANES_INLINE void bounceLambertianLanes(PhotonLanes& L, int first) {
    const IntLanes waiting = loadLanes<int32_t, IntLanes>(L.lambertian + first);
    uint64_t* state = L.state + first;
    const uint64_t* increment = L.increment + first;
    // The lobe choice's number is drawn (as for any material) and unused: one lobe.
    (void)uniformLanes(state, increment, waiting);
    FloatLanes u1 = uniformLanes(state, increment, waiting), u2 = uniformLanes(state, increment, waiting);
    FloatLanes lx, ly, lz;
    cosineHemisphere(u1, u2, lx, ly, lz);

    Vec3Lanes d = loadVec3(L.dx() + first, L.dy() + first, L.dz() + first);
    Vec3Lanes ns = loadVec3(L.nsx + first, L.nsy + first, L.nsz + first);
    // Seen from below its shading normal, or sampled on the horizon, the surface ends the path.
    IntLanes sampled = waiting & (-dot(d, ns) > 0.0f) & (lz > 0.0f);
    Vec3Lanes s, t;
    orthonormalBasis(ns.x, ns.y, ns.z, s.x, s.y, s.z, t.x, t.y, t.z);
    Vec3Lanes wi = s * lx + t * ly + ns * lz;
    continueLanes(L, first, waiting, sampled, wi, loadVec3(L.tintR + first, L.tintG + first, L.tintB + first), IntLanes{});
    storeLanes(L.lambertian + first, IntLanes{});
}
PHOTON_LANES_KERNEL(bounceLambertian, bounceLambertianLanes, (PhotonLanes & L, int first), (L, first))

// The bounce off a perfect mirror or a smooth dielectric of lanes [first, first + 8) that
// hold a waiting hit: Mirror::sample and Dielectric::sample (Fresnel's choice between
// reflection and refraction, materials/fresnel.h) in the same local frame, for eight at once.
PHOTON_LANES_INLINE void bounceSpecularLanes(PhotonLanes& L, int first) {
    const IntLanes waiting = loadLanes<int32_t, IntLanes>(L.specular + first);
    uint64_t* state = L.state + first;
    const uint64_t* increment = L.increment + first;
    FloatLanes uLobe = uniformLanes(state, increment, waiting);
    // The two numbers any material is given for its direction: a Dirac lobe needs none.
    (void)uniformLanes(state, increment, waiting);
    (void)uniformLanes(state, increment, waiting);

    Vec3Lanes d = loadVec3(L.dx() + first, L.dy() + first, L.dz() + first);
    Vec3Lanes ns = loadVec3(L.nsx + first, L.nsy + first, L.nsz + first);
    Vec3Lanes s, t;
    orthonormalBasis(ns.x, ns.y, ns.z, s.x, s.y, s.z, t.x, t.y, t.z);
    const Vec3Lanes wo{-d.x, -d.y, -d.z};
    const FloatLanes ox = dot(wo, s), oy = dot(wo, t), oz = dot(wo, ns);  // in the local frame

    const FloatLanes ior = loadLanes<float, FloatLanes>(L.ior + first);
    const IntLanes mirror = ior == 0.0f;
    FloatLanes fresnel = fresnelDielectric(oz, ior);
    FloatLanes tx, ty, tz, etap;
    const FloatLanes zero{}, one = broadcast<FloatLanes>(1.0f);
    IntLanes totalReflection = refractComponents(ox, oy, oz, zero, zero, one, ior, tx, ty, tz, etap);
    IntLanes reflects = mirror | (uLobe < fresnel);
    // The conditions are written as the materials' tests negated, so that NaNs fare alike.
    IntLanes refracts = ~totalReflection & ~((1.0f - fresnel) <= 0.0f);
    IntLanes sampled = waiting & select(mirror, ~(oz <= 0.0f), (oz != 0.0f) & (reflects | refracts));
    Vec3Lanes local = select(reflects, Vec3Lanes{-ox, -oy, oz}, Vec3Lanes{tx, ty, tz});
    Vec3Lanes wi = s * local.x + t * local.y + ns * local.z;
    // The weight is the tint either way (importance is not scaled across the boundary).
    continueLanes(L, first, waiting, sampled, wi, loadVec3(L.tintR + first, L.tintG + first, L.tintB + first), ~IntLanes{});
    storeLanes(L.specular + first, IntLanes{});
}
PHOTON_LANES_KERNEL(bounceSpecular, bounceSpecularLanes, (PhotonLanes & L, int first), (L, first))

class PhotonWalk {
    // What the walk needs of each shape's material, looked up once per hit.
    // In lanes (two kinds), or not; or none: straight on through a surface that only bounds
    // media (Scene::passesThrough), as camera paths and shadow rays pass it.
    enum class Bounce { Lambertian, Specular, OneByOne, PassThrough };
    struct ShapeScattering {
        const Material* material;
        Bounce bounce;
        bool twoSided;  // the normals are turned toward the photon
        bool textured;  // its colour comes from a texture
        Color tint;     // else its colour
        float ior;      // of a smooth specular surface (0: a mirror)
        bool boundsMedium;  // a photon crossing it changes medium (it then bounces one by one)
    };

public:
    PhotonWalk(const Scene& scene, const PhotonEmitter& emitter, const PhotonPathSettings& settings,
               PhotonArrivalSink& sink, PhotonPathCounters& counters)
        : scene_(scene), emitter_(emitter), settings_(settings), stream_(settings.seed, settings.stream, StreamPurpose::Photon),
          sink_(sink), counters_(counters) {
        // Two-sided Lambertian surfaces bounce in lanes (the caustic map's walk ends at them
        // anyway: its paths stop at the first non-delta bounce), and so do mirrors and
        // smooth dielectrics.
        for (uint32_t i = 0; i < scene.shapeCount(); ++i) {
            const Material& m = scene.materialAt(scene.shape(i).material);
            const bool boundsMedium = scene.hasMedia() && scene.shape(i).boundsMedium();
            ShapeScattering sc{&m, Bounce::OneByOne, m.twoSided(), m.tint().textured(), m.tint().value, 0.0f, boundsMedium};
            if (scene.passesThrough(i)) {
                sc.bounce = Bounce::PassThrough;
                shapes_.push_back(sc);
                continue;
            }
            if (m.lambertian() && m.twoSided() && !settings.specularOnly && !boundsMedium) sc.bounce = Bounce::Lambertian;
            if (std::optional<Material::SmoothSpecular> smooth = m.smoothSpecular(); smooth && !boundsMedium) {
                sc.bounce = Bounce::Specular;
                sc.ior = smooth->ior;
            }
            shapes_.push_back(sc);
        }
        static_assert(Scene::RayPacket::kSize == kWalkLanes);
        RTCRay16& rays = lanes_.packet.rh.ray;
        for (int i = 0; i < kWalkLanes; ++i) {
            lanes_.alive[i] = lanes_.lambertian[i] = lanes_.specular[i] = 0;
            rays.tnear[i] = rays.time[i] = 0;  // the rest of the query that Embree does not change
            rays.mask[i] = ~0u;
            rays.flags[i] = 0;
        }
    }

    void run(int64_t begin, int64_t end) {
        int64_t next = begin;
        for (;;) {
            for (int half = 0; half < 2; ++half) refill(half * kLanes, next, end);
            bool anyAlive = false;
            for (int i = 0; i < kWalkLanes; ++i) anyAlive |= lanes_.alive[i] != 0;
            if (!anyAlive) return;
            castRays();
            unsigned waiting[2] = {0, 0};
            for (int i = 0; i < kWalkLanes; ++i)
                if (lanes_.alive[i]) waiting[i / kLanes] |= step(i);
            for (int half = 0; half < 2; ++half) {
                if (waiting[half] & kLambertianWaits) bounceLambertian(lanes_, half * kLanes);
                if (waiting[half] & kSpecularWaits) bounceSpecular(lanes_, half * kLanes);
            }
        }
    }

private:
    // New photons for the empty lanes among [first, first + 8), while any are left, once
    // enough of them are empty.
    void refill(int first, int64_t& next, int64_t end) {
        PhotonLanes& L = lanes_;
        int empty = 0;
        for (int k = 0; k < kLanes; ++k) empty += !L.alive[first + k];
        if (empty < kRefillThreshold && empty < kLanes) return;
        for (;;) {
            int64_t index[kLanes];
            alignas(32) int32_t want[kLanes];
            bool any = false;
            for (int k = 0; k < kLanes; ++k) {
                want[k] = !L.alive[first + k] && next < end ? -1 : 0;
                index[k] = want[k] ? next++ : 0;
                any |= want[k] != 0;
            }
            if (!any) return;
            emitter_.emitLanes(stream_, index, want, emitted_);
            for (int k = 0; k < kLanes; ++k) {
                if (!emitted_.emitted[k]) continue;
                const int i = first + k;
                L.ox()[i] = emitted_.ox[k], L.oy()[i] = emitted_.oy[k], L.oz()[i] = emitted_.oz[k];
                L.dx()[i] = emitted_.dx[k], L.dy()[i] = emitted_.dy[k], L.dz()[i] = emitted_.dz[k];
                L.betaR[i] = emitted_.betaR[k], L.betaG[i] = emitted_.betaG[k], L.betaB[i] = emitted_.betaB[k];
                L.state[i] = emitted_.state[k];
                L.increment[i] = emitted_.increment[k];
                L.depth[i] = 0;
                L.walkEvents[i] = 0;
                L.onlySpecular[i] = -1;
                L.cell[i] = emitted_.cell[k];
                L.medium[i] = scene_.hasMedia() ? scene_.lightMedium(size_t(emitted_.light[k])) : -1;
                L.firstArrival[i] = settings_.unsampledLightsArriveFirst &&
                                            !scene_.lights().light(size_t(emitted_.light[k])).sampledDirectly()
                                        ? 0
                                        : settings_.firstArrivalDepth;
                L.hero[i] = -1;
                L.ratioR[i] = L.ratioG[i] = L.ratioB[i] = 1.0f;
                L.alive[i] = -1;
            }
        }
    }

    // Every live lane's ray, in one packet query.
    void castRays() {
        Scene::RayPacket& p = lanes_.packet;
        for (int i = 0; i < kWalkLanes; ++i) {
            p.valid[i] = lanes_.alive[i];
            p.rh.ray.tfar[i] = std::numeric_limits<float>::infinity();
            p.rh.hit.geomID[i] = p.rh.hit.instID[0][i] = RTC_INVALID_GEOMETRY_ID;
        }
        scene_.intersect(p);
    }

    // What a lane's hit waits for after step(): nothing (its bounce is done, or its path
    // ended), or one of the bounces in lanes.
    static constexpr unsigned kLambertianWaits = 1, kSpecularWaits = 2;

    // Takes lane i's hit from the packet, hands the arrival to the sink, and bounces the
    // photon here unless its surface bounces in lanes.
    unsigned step(int i) {
        PhotonLanes& L = lanes_;
        SurfaceHit hit;
        ++counters_.rays;
        L.alive[i] = 0;
        const bool found = scene_.hitOf(L.packet, i, hit);
        if (scene_.scatters(L.medium[i])) {
            if (scattersOnTheWay(i, found ? hit.t : std::numeric_limits<float>::infinity())) return 0;
        } else if (found && L.medium[i] >= 0) {
            const Vec3 o{L.ox()[i], L.oy()[i], L.oz()[i]};
            L.setBeta(i, L.beta(i) * scene_.transmittance(L.medium[i], o, L.direction(i), hit.t));
        }
        if (!found) {
            counters_.missedAtEmission += L.depth[i] == 0;
            return 0;
        }
        ++counters_.segments;
        const Vec3 wi = -L.direction(i);
        const int depth = L.depth[i];
        const bool last = depth + 1 == settings_.maxDepth;
        const ShapeScattering& shape = shapes_[hit.shape];
        if (shape.bounce == Bounce::PassThrough) {
            // No vertex: the photon keeps its depth (its arrivals count as the light's
            // direct light where they would without the boundary) and goes on unbent.
            const Ray ray = spawnRay(hit.p, hit.ng, -wi);
            L.medium[i] = scene_.mediumToward(hit, ray.d, L.medium[i]);
            L.setRay(i, ray);
            L.alive[i] = -1;
            return 0;
        }
        if (shape.bounce == Bounce::Lambertian) {
            turnTowardViewer(hit, wi);  // the material is two-sided
            if (depth >= L.firstArrival[i])
                sink_.arrive({hit.p, hit.ns, wi, L.beta(i), depth, L.onlySpecular[i] != 0, L.cell[i]});
            if (last) return 0;
            keepHit(i, hit, shape);
            L.lambertian[i] = -1;
            return kLambertianWaits;
        }
        if (shape.bounce == Bounce::Specular) {  // delta lobes only: no arrival
            if (shape.twoSided) turnTowardViewer(hit, wi);
            if (last) return 0;
            keepHit(i, hit, shape);
            L.ior[i] = shape.ior;
            L.specular[i] = -1;
            return kSpecularWaits;
        }
        ShadingPoint sp = makeShadingPoint(scene_, hit, wi);
        // No visible point is ever on a fibre (Material::alignsToTangent): none gathers there.
        if (!sp.material->isDeltaOnly() && !sp.material->alignsToTangent() && depth >= L.firstArrival[i]) {
            // Photons measure flux through the geometric surface, |wi.ng|; a bent shading
            // normal reflects in proportion to |wi.ns| instead (what the camera side's light
            // samples weigh by), so the arrival carries their ratio (Veach 1997, sec. 5.3).
            Color beta = L.beta(i);
            if (sp.material->bendsNormal()) beta *= shadingCosineRatio(sp.hit, wi);
            sink_.arrive({sp.hit.p, sp.hit.ns, wi, beta, depth, L.onlySpecular[i] != 0, L.cell[i]});
        }
        if (!last) bounce(i, hit, shape, sp, wi);
        return 0;
    }

    // Lane i's photon in a medium that scatters, over its ray's segment of length `segment`:
    // true if it scatters before the end (sampleFreeFlight), where it then goes on toward a
    // direction drawn from the phase function (weight 1) unless its path ends there; false
    // if it reaches the end, its flux weighted by the flight's odds. Where it scatters it
    // arrives there too, with PhotonPathSettings::arrivesInMedia.
    bool scattersOnTheWay(int i, float segment) {
        PhotonLanes& L = lanes_;
        Rng rng = Rng::resume(L.state[i], L.increment[i]);
        const MediumDescription& m = scene_.medium(L.medium[i]);
        Color weight(1.0f);
        ChromaticFlight flight{L.hero[i], {L.ratioR[i], L.ratioG[i], L.ratioB[i]}};
        const Vec3 d = L.direction(i), o{L.ox()[i], L.oy()[i], L.oz()[i]};
        const float t = sampleFreeFlight(m, o, d, segment, rng.uniform(), weight, flight);
        L.hero[i] = flight.hero;
        L.ratioR[i] = flight.ratios.x, L.ratioG[i] = flight.ratios.y, L.ratioB[i] = flight.ratios.z;
        L.state[i] = rng.state();
        if (!(t < segment)) {
            L.setBeta(i, L.beta(i) * weight);
            return false;
        }
        ++counters_.segments;
        // Not under a surface: a walk of hundreds of events would leave as many photons, and
        // camera paths walk there instead of gathering them.
        if (settings_.arrivesInMedia && !m.subsurface && L.depth[i] >= L.firstArrival[i])
            sink_.arrive({o + d * t, Vec3{}, -d, L.beta(i) * weight, L.depth[i], L.onlySpecular[i] != 0, L.cell[i]});
        // A walk under a surface (MediumDescription::subsurface) is no vertex, as for camera paths.
        const bool underSurface = m.subsurface && L.walkEvents[i] < MediumDescription::kMaxSubsurfaceEvents;
        if (settings_.specularOnly || (!underSurface && L.depth[i] + 1 == settings_.maxDepth)) return true;
        std::optional<Color> next = photonAfterRoulette(L.beta(i), weight, rng);
        if (!next) return true;
        const PhaseSample s = sampleHenyeyGreenstein(-d, m.g, {rng.uniform(), rng.uniform()});
        L.setBeta(i, *next);
        L.setRay(i, Ray{o + d * t, s.wi});
        L.state[i] = rng.state();
        L.onlySpecular[i] = 0;
        ++(underSurface ? L.walkEvents : L.depth)[i];
        L.alive[i] = -1;
        return true;
    }

    // A hit that waits for its bounce in lanes.
    void keepHit(int i, const SurfaceHit& hit, const ShapeScattering& shape) {
        PhotonLanes& L = lanes_;
        Color tint = shape.textured ? shape.material->tint().eval({hit.uv, hit.p, hit.ng}) : shape.tint;
        L.px[i] = hit.p.x, L.py[i] = hit.p.y, L.pz[i] = hit.p.z;
        L.ngx[i] = hit.ng.x, L.ngy[i] = hit.ng.y, L.ngz[i] = hit.ng.z;
        L.nsx[i] = hit.ns.x, L.nsy[i] = hit.ns.y, L.nsz[i] = hit.ns.z;
        L.tintR[i] = tint.x, L.tintG[i] = tint.y, L.tintB[i] = tint.z;
    }

    // Any material's bounce, by BSDF sampling; `hit` as cast (its normal not turned), for the
    // medium the photon goes on in.
    void bounce(int i, const SurfaceHit& hit, const ShapeScattering& shape, const ShadingPoint& sp, Vec3 wi) {
        PhotonLanes& L = lanes_;
        Rng rng = Rng::resume(L.state[i], L.increment[i]);
        float uLobe = rng.uniform();
        Vec2 u{rng.uniform(), rng.uniform()};
        std::optional<BSDFSample> s =
            sp.material->sample(sp.frame.toLocal(wi), uLobe, u, sp.inputs, TransportMode::Importance);
        if (!s) return;
        const bool onlySpecular = L.onlySpecular[i] && s->delta;
        if (settings_.specularOnly && !onlySpecular) return;
        std::optional<Color> next = photonAfterRoulette(L.beta(i), s->weight, rng);
        if (!next) return;
        L.setBeta(i, *next);
        const Ray ray = spawnRay(sp.hit.p, sp.hit.ng, sp.frame.toWorld(s->wi));
        L.setRay(i, ray);
        const int32_t before = L.medium[i];
        if (shape.boundsMedium) L.medium[i] = scene_.mediumToward(hit, ray.d, L.medium[i]);
        L.state[i] = rng.state();
        L.onlySpecular[i] = onlySpecular ? -1 : 0;
        // A reflection off the inside of a subsurface medium's surface is part of its walk.
        const bool underSurface = shape.boundsMedium && before >= 0 && L.medium[i] == before &&
                                  scene_.medium(before).subsurface &&
                                  L.walkEvents[i] < MediumDescription::kMaxSubsurfaceEvents;
        ++(underSurface ? L.walkEvents : L.depth)[i];
        L.alive[i] = -1;
    }

    const Scene& scene_;
    const PhotonEmitter& emitter_;
    const PhotonPathSettings& settings_;
    const RngStream stream_;
    PhotonArrivalSink& sink_;
    PhotonPathCounters& counters_;
    std::vector<ShapeScattering> shapes_;  // by shape index
    PhotonLanes lanes_;
    PhotonEmitter::Lanes emitted_;
};

}  // namespace

void tracePhotonPaths(const Scene& scene, const PhotonEmitter& emitter, const PhotonPathSettings& settings,
                      int64_t begin, int64_t end, PhotonArrivalSink& sink, PhotonPathCounters& counters) {
    PhotonWalk(scene, emitter, settings, sink, counters).run(begin, end);
}

}  // namespace photon
