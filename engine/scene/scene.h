// The immutable scene an integrator renders: Embree geometry, materials, lights, camera.
#pragma once
#include <algorithm>
#include <embree3/rtcore.h>
#include <deque>
#include <map>
#include <memory>
#include <vector>
#include "camera/camera.h"
#include "lights/light.h"
#include "lights/direct_light_sampler.h"
#include "lights/lights_along_rays.h"
#include "lights/light_sampler.h"
#include "math/ray.h"
#include "description/scene_description.h"
#include "scene/medium_palette.h"

namespace photon {

// SurfaceHit::instance of a hit on a shape placed directly in the world.
inline constexpr uint32_t kNoInstance = ~0u;

// What a ray hit. Normals face the side the surface emits from (flip_normals applied).
struct SurfaceHit {
    Vec3 p;          // hit point
    Vec3 ng;         // geometric normal, unit length
    Vec3 ns;         // shading normal, unit length, same side as ng
    Vec2 uv;         // surface parameterisation for textures
    float t = 0;     // ray distance
    // The shape hit: an index into Scene::shape(), which lists the world's shapes and then
    // the objects' (the same slot for every instance of an object's shape).
    uint32_t shape = 0;
    uint32_t instance = kNoInstance;  // the object instance hit, if any
    uint32_t primitive = 0;  // triangle index within a mesh shape
    Vec2 barycentric;        // Embree's (u, v) on that triangle: p = (1-u-v) p0 + u p1 + v p2
};

class Scene {
public:
    // Builds the Embree BVH and the light set. Throws std::runtime_error if Embree fails.
    static std::shared_ptr<const Scene> build(SceneDescription description);
    ~Scene();
    Scene(const Scene&) = delete;
    Scene& operator=(const Scene&) = delete;

    // Closest hit along the ray within (0, ray.tMax). Inline, so that the ray goes to
    // Embree from the caller's registers: a copy of the Ray through memory, stored field by
    // field and read back in wider pieces, stalled every photon ray's setup.
    bool intersect(const Ray& ray, SurfaceHit& hit) const {
        RTCIntersectContext context;
        rtcInitIntersectContext(&context);
        RTCRayHit rh = embreeQuery(ray);
        rtcIntersect1(rtcScene_, &context, &rh);
        if (rh.hit.geomID == RTC_INVALID_GEOMETRY_ID) return false;
        hit.t = rh.ray.tfar;
        hit.primitive = rh.hit.primID;
        hit.barycentric = {rh.hit.u, rh.hit.v};
        completeHit(ray, rh.hit.geomID, rh.hit.instID[0], hit);
        return true;
    }
    // Up to sixteen rays cast together by Embree's packet query, for callers that hold many
    // independent rays at once (the photon walk's lanes). On this renderer's incoherent
    // photon rays it spends a sixth less time per ray than casting them one by one, even
    // with half the lanes empty (docs/sppm.md). A lane's hit is exactly the one intersect()
    // finds for its ray: Embree's packet and single-ray kernels agree on the primitive and
    // its barycentrics, from which hit points are made (on spheres from the ray itself), and
    // may differ only in the last bit of the distance.
    struct RayPacket {
        static constexpr int kSize = 16;
        alignas(64) int valid[kSize];  // -1: the lane holds a ray, 0: it is empty
        RTCRayHit16 rh;

        void setLane(int lane, const Ray& ray) {
            const RTCRayHit one = embreeQuery(ray);
            valid[lane] = -1;
            rh.ray.org_x[lane] = one.ray.org_x, rh.ray.org_y[lane] = one.ray.org_y, rh.ray.org_z[lane] = one.ray.org_z;
            rh.ray.dir_x[lane] = one.ray.dir_x, rh.ray.dir_y[lane] = one.ray.dir_y, rh.ray.dir_z[lane] = one.ray.dir_z;
            rh.ray.tnear[lane] = one.ray.tnear, rh.ray.tfar[lane] = one.ray.tfar, rh.ray.time[lane] = one.ray.time;
            rh.ray.mask[lane] = one.ray.mask, rh.ray.flags[lane] = one.ray.flags;
            rh.hit.geomID[lane] = one.hit.geomID;
            rh.hit.instID[0][lane] = one.hit.instID[0];
        }
        void clearLane(int lane) {
            valid[lane] = 0;
            rh.hit.geomID[lane] = rh.hit.instID[0][lane] = RTC_INVALID_GEOMETRY_ID;
        }
    };
    void intersect(RayPacket& packet) const {
        RTCIntersectContext context;
        rtcInitIntersectContext(&context);
        rtcIntersect16(packet.valid, rtcScene_, &context, &packet.rh);
        prefetchHitsOf(packet);
    }
    // The hit of a lane of a packet that intersect() has cast, if any.
    bool hitOf(const RayPacket& packet, int lane, SurfaceHit& hit) const {
        const RTCRayHit16& p = packet.rh;
        if (p.hit.geomID[lane] == RTC_INVALID_GEOMETRY_ID) return false;
        hit.t = p.ray.tfar[lane];
        hit.primitive = p.hit.primID[lane];
        hit.barycentric = {p.hit.u[lane], p.hit.v[lane]};
        const Ray ray{{p.ray.org_x[lane], p.ray.org_y[lane], p.ray.org_z[lane]},
                      {p.ray.dir_x[lane], p.ray.dir_y[lane], p.ray.dir_z[lane]}};
        completeHit(ray, p.hit.geomID[lane], p.hit.instID[0][lane], hit);
        return true;
    }
    // Embree's closest-hit query for the ray, nothing found yet.
    static RTCRayHit embreeQuery(const Ray& ray) {
        RTCRayHit rh;
        rh.ray.org_x = ray.o.x;
        rh.ray.org_y = ray.o.y;
        rh.ray.org_z = ray.o.z;
        rh.ray.dir_x = ray.d.x;
        rh.ray.dir_y = ray.d.y;
        rh.ray.dir_z = ray.d.z;
        rh.ray.tnear = 0;
        rh.ray.tfar = ray.tMax;
        rh.ray.mask = ~0u;
        rh.ray.flags = 0;
        rh.ray.time = 0;
        rh.hit.geomID = rh.hit.instID[0] = RTC_INVALID_GEOMETRY_ID;
        return rh;
    }
    // Whether packets prefetch their triangles' hit data (prefetchesHits_), for tests.
    bool prefetchesHits() const { return prefetchesHits_; }
    // True if anything blocks the ray within (0, tMax).
    bool occluded(const Ray& ray) const;
    // False where the ray cannot find light however it ends: no environment light shines,
    // no medium emits and no emitting shape lies anywhere along it within (0, tMax),
    // whatever stands in front. It asks Embree about the emitters alone, a handful of primitives in most
    // scenes, so that a look-up of the light along a direction costs a whole ray only where
    // it may find some.
    bool mayFindLight(const Ray& ray) const;

    // The shapes a hit can name (SurfaceHit::shape): the world's, then each object's in
    // its own frame.
    size_t shapeCount() const { return slots_.size(); }
    const ShapeDescription& shape(uint32_t index) const { return *slots_[index]; }
    const Material& material(const SurfaceHit& hit) const { return *materials_[materialOf_[hit.shape]]; }
    uint32_t materialIndex(const SurfaceHit& hit) const { return materialOf_[hit.shape]; }
    const Material& materialAt(uint32_t index) const { return *materials_[index]; }
    // Absorbing media (MediumDescription, docs/scene-format.md#media). A path carries the
    // medium it is in (-1: none), changed where it crosses a shape that bounds one.
    bool hasMedia() const { return !description_.media.empty(); }
    bool hasScatteringMedia() const { return scatteringMedia_; }
    // Whether any medium emits light (MediumDescription::emits): camera paths then carry a
    // sampler through every medium, for the emission along their segments.
    bool hasEmittingMedia() const { return emittingMedia_; }
    // Whether point p lies in `medium`: the side facing p of the first shape bounding a
    // medium that a ray from p meets (other surfaces crossed), or with none, whether the
    // medium is on the outside of a shape that bounds it (and so around them all); true for
    // a medium no shape bounds, which fills the scene. (Not the camera's medium as such:
    // the camera may sit inside a shape.) What a light inside a grid larger than its
    // medium's shapes asks before it emits there.
    bool inMedium(Vec3 p, int32_t medium) const;
    // The medium around p: the one on p's side of the first boundary between media that a
    // ray from p meets (-1: none on that side); nothing where the ray meets none.
    std::optional<int32_t> mediumAround(Vec3 p) const;
    // A grid of cells over the shapes that have `medium` inside: where a homogeneous medium
    // that emits sends its photons from (none where no shape has it inside; the scene loader
    // refuses such a medium where anything else names it).
    std::shared_ptr<const DensityGrid> boxAroundShapesHolding(int32_t medium) const;
    const MediumDescription& medium(int32_t index) const { return description_.media[size_t(index)]; }
    // True if paths in `medium` (-1: none) may scatter in it (medium_scattering.h).
    bool scatters(int32_t medium) const { return medium >= 0 && scatteringMedia_ && this->medium(medium).scatters(); }
    // What light keeps unscattered over `distance` along the ray o + t d (|d| = 1) in the
    // medium (Beer-Lambert on its extinction, times its density's integral where it varies);
    // an infinite distance in a homogeneous medium that absorbs or scatters a channel keeps
    // none of it.
    Color transmittance(int32_t medium, Vec3 o, Vec3 d, float distance) const {
        if (medium < 0) return Color(1.0f);
        const MediumDescription& m = this->medium(medium);
        return m.transmittanceOver(m.densityLength(o, d, distance));
    }
    // The medium a path is in after leaving the hit along w: the shape's outside where w
    // leaves on the side its normal faces, else its inside; `current` where the shape bounds
    // no medium (pbrt-v4's SurfaceInteraction::GetMedium). `hit` as intersect() gave it,
    // before any turning toward the viewer.
    int32_t mediumToward(const SurfaceHit& hit, Vec3 w, int32_t current) const {
        if (!hasMedia()) return current;
        const ShapeDescription& s = shape(hit.shape);
        if (!s.boundsMedium()) return current;
        const bool inward = dot(w, hit.ng) <= 0;
        const int32_t next = inward ? s.insideMedium : s.outsideMedium;
        if (palettes_.any()) [[unlikely]]
            return paletteMediumToward(next, inward, hit, current);
        return next;
    }
    // The scene's medium an index a path carries stands for (a textured medium's palette:
    // scene/medium_palette.h).
    int32_t mediumFamily(int32_t medium) const { return palettes_.family(medium); }
    // True if the hit is on a surface that only separates media (a smooth dielectric of
    // index 1: pbrt-v4's "interface"): rays cross it unbent and unweakened, so camera paths
    // and shadow rays pass it without a vertex, taking on each medium's absorption.
    bool passesThrough(const SurfaceHit& hit) const { return passesThrough(hit.shape); }
    bool passesThrough(uint32_t shape) const { return hasMedia() && passThrough_[shape]; }
    // What reaches the end of a shadow ray that starts in `medium`: 0 if anything but a
    // surface that passesThrough() blocks it, else the product of the media's
    // transmittances along it (1 in a scene without media).
    Color shadowTransmittance(Ray ray, int32_t medium) const;
    // dp/du and dp/dv at the hit: the tangent frame of normal and bump maps.
    SurfaceTangents tangentsAt(const SurfaceHit& hit) const;
    // Radiance emitted from the hit toward direction w (zero on the back side).
    Color emitted(const SurfaceHit& hit, Vec3 w) const;
    // Radiance arriving along a ray that leaves the scene: the environment lights' sum.
    Color environment(const Ray& ray) const;
    // The environment lights (several when each comes in through its own portal: one per
    // window) and the probability with which directLights() picks each: what a
    // BSDF-sampled ray that leaves the scene needs to weigh itself against light sampling.
    struct EnvironmentLight {
        const Light* light;
        float pickProbability;
    };
    const std::vector<EnvironmentLight>& environmentLights() const { return environmentLights_; }
    // The area light of the emitting shape a hit landed on (null if it emits nothing) and
    // its index among the lights: for weighting emission a BSDF sample found against the
    // light sample that could have found it too (directLights().probability).
    struct Emitter {
        const Light* light = nullptr;
        size_t index = 0;
    };
    // Whether any shape emits (an area light, a sky dome).
    bool hasEmittingShapes() const {
        return std::any_of(lightOfShape_.begin(), lightOfShape_.end(), [](int32_t i) { return i >= 0; });
    }
    Emitter emitterAt(const SurfaceHit& hit) const {
        const int32_t i = lightOfShape_[hit.shape];
        return i < 0 ? Emitter{} : Emitter{&lightSampler_.light(size_t(i)), size_t(i)};
    }

    const Camera& camera() const { return camera_; }
    const RenderSettings& settings() const { return description_.render; }
    const SceneDescription& description() const { return description_; }
    // By power: how photons leave the lights.
    const LightSampler& lights() const { return lightSampler_; }
    // The absorbing medium light i of lights() is in, where its photons start (-1: none):
    // a point or spot light's own (LightDescription::medium), an emissive shape's outside.
    int32_t lightMedium(size_t i) const { return lightMedium_[i]; }
    // How shadow rays pick a light (render.light_sampler).
    const DirectLightSampler& directLights() const { return directLightSampler_; }
    // The point and spot lights camera paths sample along their rays through media that
    // scatter (render.equiangular): none without such media, or with the setting off.
    const LightsAlongRays& lightsAlongRays() const { return lightsAlongRays_; }
    Vec3 boundsMin() const { return boundsMin_; }
    Vec3 boundsMax() const { return boundsMax_; }
    RTCScene embreeScene() const { return rtcScene_; }

private:
    explicit Scene(SceneDescription description);
    // mediumToward() where media have palettes: a path entering a textured medium through a
    // shape that holds it takes the palette's medium for the reflectance where it enters; one
    // that stays in the same medium (crossing a surface inside it) keeps the one it has;
    // entering through a shape's outside, it takes the medium's mean.
    int32_t paletteMediumToward(int32_t next, bool inward, const SurfaceHit& hit, int32_t current) const;
    // Adds the shape's Embree geometry, with its alpha cutout if any, to `target` as
    // geometry `id`.
    void addShape(const ShapeDescription& shape, RTCScene target, uint32_t id);
    void buildEmitterScene();
    static bool occludedIn(RTCScene scene, const Ray& ray);
    RTCGeometry newMesh(const TriangleMesh& mesh);
    static void padForEmbree(TriangleMesh& mesh);
    RTCGeometry newSphere(const ShapeDescription& shape);
    // Curves (scene_curves.cpp): their Embree geometry, hit record and tangents.
    RTCGeometry newCurves(const ShapeDescription& shape);
    static void curveFilter(const RTCFilterFunctionNArguments* args);
    void fillCurveHit(const Ray& ray, SurfaceHit& hit) const;
    SurfaceTangents curveTangents(const SurfaceHit& hit) const;
    // A world-space copy of each emissive shape of each instance, among the world's shapes:
    // a light samples and emits from its surface in the world (scene_instances.cpp).
    void placeInstancedEmitters();
    // Each object's Embree scene and its instances in the world's (scene_instances.cpp).
    void addObjectsAndInstances();
    void takeSubsurfaceBoundaries();
    void buildLights();
    void prepareHitData();
    void placeLightsInMedia();  // and the camera
    // The rest of the hit record, once Embree's answer (t, shape, primitive, barycentric)
    // is in it: inline for flat triangles and plain spheres, out of line for the others.
    // Embree's geometry and instance ids name the shape and the instance. A hit on an
    // instance goes out of line, so that the common case's inline code stays as it was
    // before instancing (photon-bench measured 3% slower with the two in one path).
    void completeHit(const Ray& ray, unsigned geomID, unsigned instID, SurfaceHit& hit) const {
        if (instID != RTC_INVALID_GEOMETRY_ID) [[unlikely]] {
            completeInstanceHit(ray, geomID, instID, hit);
            return;
        }
        hit.shape = geomID;
        hit.instance = kNoInstance;
        completeLocalHit(ray, hit);
    }
    // The same in the frame of the hit's shape (the world's, or its object's).
    void completeLocalHit(const Ray& ray, SurfaceHit& hit) const {
        if (!completeFlatTriangleHit(hit) && !completePlainSphereHit(ray, hit)) completeOtherHit(ray, hit);
    }
    // A hit on an object's instance: completed in the object's frame, then taken to the world.
    void completeInstanceHit(const Ray& ray, unsigned geomID, unsigned instID, SurfaceHit& hit) const;
    // Textured shapes and meshes with vertex normals.
    void completeOtherHit(const Ray& ray, SurfaceHit& hit) const;
    // Embree's barycentrics (u, v) at a triangle's corners' values: (1-u-v) a + u b + v c.
    static Vec3 atBarycentric(Vec3 a, Vec3 b, Vec3 c, float u, float v) { return a * (1.0f - u - v) + b * u + c * v; }
    // The same for an untextured sphere (see PlainSphere), inline; false for other shapes.
    bool completePlainSphereHit(const Ray& ray, SurfaceHit& hit) const {
        const PlainSphere& s = plainSpheres_[hit.shape];
        if (!(s.radius > 0)) return false;
        hit.uv = hit.barycentric;
        hit.p = sphereHitPoint(ray, s.center, s.radius, hit.t);
        sphereNormals(s.center, s.radius, s.normalSign, hit);
        return true;
    }
    // The normals of a hit on a sphere, and its point moved onto the surface.
    static void sphereNormals(Vec3 center, float radius, float normalSign, SurfaceHit& hit) {
        Vec3 n = normalize(hit.p - center);
        hit.p = center + n * radius;  // reproject: removes the error of o + t d
        hit.ng = hit.ns = n * normalSign;
    }
    // The same for a flat triangle (see FlatTriangle), inline; false for other shapes.
    bool completeFlatTriangleHit(SurfaceHit& hit) const {
        const uint32_t first = firstFlatTriangle_[hit.shape];
        if (first == kNotFlat) return false;
        const FlatTriangle& f = flatTriangles_[first + hit.primitive];
        hit.uv = hit.barycentric;
        hit.p = atBarycentric(f.p0, f.p1, f.p2, hit.barycentric.x, hit.barycentric.y);
        hit.ng = hit.ns = f.n;
        return true;
    }
    void fillTriangleHit(const ShapeDescription& shape, SurfaceHit& hit) const;
    // Asks for what hitOf() will read of each lane's triangle (its corners, normals and uvs),
    // so that the lanes' cache misses overlap rather than follow each other.
    void prefetchHitsOf(const RayPacket& packet) const;
    void fillSphereHit(const ShapeDescription& shape, SurfaceHit& hit) const;
    static Vec3 sphereHitPoint(const Ray& ray, Vec3 center, float radius, float tEmbree);

    // Per shape, what turning Embree's answer into a SurfaceHit needs, prepared once: a
    // hit is the photon walk's hottest step after the ray itself.
    struct ShapeHitData {
        bool smoothNormals = false;     // vertex normals that bend the shading normal
        bool needsUv = false;           // the material reads a texture
        float normalSign = 1;           // -1 with flip_normals (spheres)
    };

    SceneDescription description_;
    std::vector<ShapeDescription>& shapes_ = description_.shapes;
    std::vector<MaterialPtr>& materials_ = description_.materials;
    std::vector<const ShapeDescription*> slots_;  // what shape() returns
    std::vector<uint32_t> materialOf_;            // by shape: its material, one load away
    std::vector<int32_t> lightOfShape_;           // by shape: its area light's index in lightSampler_, or -1
    std::vector<uint8_t> passThrough_;            // by shape: see passesThrough()
    bool scatteringMedia_ = false;                // any medium scatters
    bool emittingMedia_ = false;                  // any medium emits
    std::vector<uint8_t> mediumBounded_;          // by medium: some shape bounds it
    std::vector<uint8_t> mediumOutside_;          // by medium: it is where no shape's inside is
    std::vector<int32_t> lightMedium_;            // by light, in lightSampler_'s order
    std::vector<uint8_t> lightMediumSaid_;        // by light: its medium is the scene's word, not placeLightsInMedia's
    MediumPalettes palettes_;                     // textured media's palettes, after the scene's media
    // An object's instance: where it is, and where its shapes start in slots_. Embree's
    // geometry id of instance k is firstInstanceId_ + k (the world's shapes come first).
    struct Placement {
        Transform toWorld, toObject;
        uint32_t firstShape = 0;
    };
    std::vector<Placement> placements_;
    uint32_t firstInstanceId_ = 0;
    std::vector<RTCScene> objectScenes_;
    std::vector<ShapeHitData> hitData_;  // by shape
    // Whether the triangles' hit data outgrows kHitBytesInCache (a core's L2), so that
    // prefetchHitsOf() pays. photon-bench, 2 threads, 2M photons a pass, each build
    // interleaved with the one before: the photon pass took 0.90x the time with a sphere of
    // 1M smoothly shaded triangles in the Cornell box (894 -> 807 ms, 4 rounds), 0.94x with
    // three instances of it (1029 -> 970 ms, 3 rounds) and 0.95x on the Bitterli coffee
    // maker (615 -> 584 ms, 5 rounds); on photon-bench's own glass box (kilobytes, in cache)
    // prefetching made it 4% slower, hence the threshold.
    bool prefetchesHits_ = false;
    static constexpr size_t kHitBytesInCache = size_t(1) << 20;
    // A triangle of a mesh without textures or bending vertex normals (a quad, a faceted
    // mesh): all that a hit on it needs in one place, so that its hit record is one load
    // after Embree's answer instead of a chain of them (shape, mesh, indices, positions,
    // face normal). photon-bench's photon pass: 1.5-4% faster (docs/sppm.md).
    struct FlatTriangle {
        Vec3 p0, p1, p2;
        Vec3 n;  // unit, flip_normals applied
    };
    static constexpr uint32_t kNotFlat = ~0u;
    std::vector<FlatTriangle> flatTriangles_;
    std::vector<uint32_t> firstFlatTriangle_;  // by shape: its first in flatTriangles_, or kNotFlat
    // An untextured sphere's hit record needs these alone (radius 0: another shape).
    struct PlainSphere {
        Vec3 center;
        float radius = 0;
        float normalSign = 1;
    };
    std::vector<PlainSphere> plainSpheres_;  // by shape
    // A curve shape's control points and its segments as Embree has them.
    struct CurveGeometry {
        const CurveSet* curves;
        CurveSegments segments;
    };
    std::deque<CurveGeometry> curveGeometry_;  // a deque: Embree keeps pointers into each
    std::map<const ShapeDescription*, const CurveGeometry*> curveOfShape_;
    std::vector<const CurveGeometry*> curveOfSlot_;  // by shape; null for other kinds
    std::vector<std::unique_ptr<Light>> ownedLights_;
    LightSampler lightSampler_;
    DirectLightSampler directLightSampler_;  // refers to lightSampler_
    LightsAlongRays lightsAlongRays_;       // refers to lightSampler_
    std::vector<EnvironmentLight> environmentLights_;
    Camera camera_;
    Vec3 boundsMin_, boundsMax_;
    RTCDevice device_ = nullptr;
    RTCScene rtcScene_ = nullptr;
    RTCScene emitterScene_ = nullptr;  // the emitting shapes a ray can meet (mayFindLight)
};

}  // namespace photon
