#include "scene/scene.h"
#include "scene/alpha_cutout.h"
#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>
#include "lights/light_factories.h"

namespace photon {

namespace {
void embreeError(void*, RTCError code, const char* message) {
    (void)code;
    (void)message;  // reported through rtcGetDeviceError where it matters
}
}  // namespace

std::shared_ptr<const Scene> Scene::build(SceneDescription description) {
    return std::shared_ptr<const Scene>(new Scene(std::move(description)));
}

Scene::Scene(SceneDescription description)
    : description_(std::move(description)), palettes_(description_.media), camera_(description_.camera) {
    takeSubsurfaceBoundaries();
    placeInstancedEmitters();
    for (ShapeDescription& shape : shapes_) padForEmbree(shape.mesh);
    for (ObjectDescription& object : description_.objects)
        for (ShapeDescription& shape : object.shapes) padForEmbree(shape.mesh);
    device_ = rtcNewDevice(nullptr);
    if (!device_) throw std::runtime_error("Embree: cannot create device");
    rtcSetDeviceErrorFunction(device_, embreeError, nullptr);
    rtcScene_ = rtcNewScene(device_);
    // Embree's compact layout (RTC_SCENE_FLAG_COMPACT, leaves that index the shared vertex
    // buffer) would hold 37 instead of 107 bytes a triangle at the build's peak, but cast
    // rays at 0.61x the speed on a 1M-triangle mesh (docs/sppm.md, "Memory"): not used.
    rtcSetSceneBuildQuality(rtcScene_, RTC_BUILD_QUALITY_HIGH);
    for (uint32_t i = 0; i < shapes_.size(); ++i) {
        addShape(shapes_[i], rtcScene_, i);
        slots_.push_back(&shapes_[i]);
    }
    addObjectsAndInstances();
    rtcCommitScene(rtcScene_);
    if (rtcGetDeviceError(device_) != RTC_ERROR_NONE) throw std::runtime_error("Embree: scene build failed");
    RTCBounds b;
    rtcGetSceneBounds(rtcScene_, &b);
    boundsMin_ = {b.lower_x, b.lower_y, b.lower_z};
    boundsMax_ = {b.upper_x, b.upper_y, b.upper_z};
    buildLights();
    prepareHitData();
    placeLightsInMedia();
    buildEmitterScene();
}

// The shapes that hold a subsurface medium (MediumDescription::subsurface) inside a
// dielectric take that boundary as one where light comes in as from a diffuse sky
// (materials/subsurface_boundary.cpp): a material of their own, one per boundary material.
void Scene::takeSubsurfaceBoundaries() {
    std::map<uint32_t, uint32_t> boundaryOf;
    auto take = [&](ShapeDescription& s) {
        if (s.insideMedium < 0 || !s.boundsMedium() || !description_.media[size_t(s.insideMedium)].subsurface) return;
        const std::optional<float> ior = materials_[s.material]->refractiveIndex();
        if (!ior || *ior == 1.0f) return;
        auto [it, added] = boundaryOf.try_emplace(s.material, uint32_t(materials_.size()));
        if (added) {
            description_.materialNames.resize(materials_.size());  // scenes built in code may name none
            materials_.push_back(makeSubsurfaceBoundary(materials_[s.material], *ior));
            description_.materialNames.push_back(description_.materialNames[s.material] + " (where light enters)");
        }
        s.material = it->second;
    };
    for (ShapeDescription& s : shapes_) take(s);
    for (ObjectDescription& object : description_.objects)
        for (ShapeDescription& s : object.shapes) take(s);
}

// The world's emitting shapes (an object's are copied into the world per instance), each
// under its own id, sharing its buffers with the whole scene's geometry.
void Scene::buildEmitterScene() {
    for (uint32_t i = 0; i < shapes_.size(); ++i) {
        if (isBlack(shapes_[i].emission) || shapes_[i].invisible) continue;
        if (!emitterScene_) emitterScene_ = rtcNewScene(device_);
        addShape(shapes_[i], emitterScene_, i);
    }
    if (emitterScene_) rtcCommitScene(emitterScene_);
}

Scene::~Scene() {
    if (rtcScene_) rtcReleaseScene(rtcScene_);
    if (emitterScene_) rtcReleaseScene(emitterScene_);
    for (RTCScene s : objectScenes_) rtcReleaseScene(s);
    if (device_) rtcReleaseDevice(device_);
}

// Embree reads each vertex with a 16-byte load, so the last one needs 4 bytes of room past
// it (rtcSetSharedGeometryBuffer's documentation; Embree checks it). The mesh readers leave
// that room; a mesh made otherwise (copied, written in a scene) gets it here, which costs
// one copy of its positions, once.
void Scene::padForEmbree(TriangleMesh& mesh) {
    if (mesh.positions.capacity() < mesh.positions.size() + 1) mesh.positions.reserve(mesh.positions.size() + 1);
}

// The mesh's own arrays are Embree's vertex and index buffers: the scene owns the mesh for
// as long as Embree's scene lives, and neither changes after the build. Copies into
// Embree-owned buffers held 18 more bytes a triangle (docs/sppm.md, "Memory").
RTCGeometry Scene::newMesh(const TriangleMesh& m) {
    RTCGeometry g = rtcNewGeometry(device_, RTC_GEOMETRY_TYPE_TRIANGLE);
    rtcSetSharedGeometryBuffer(g, RTC_BUFFER_TYPE_VERTEX, 0, RTC_FORMAT_FLOAT3, m.positions.data(), 0, sizeof(Vec3),
                               m.positions.size());
    rtcSetSharedGeometryBuffer(g, RTC_BUFFER_TYPE_INDEX, 0, RTC_FORMAT_UINT3, m.indices.data(), 0,
                               3 * sizeof(uint32_t), m.triangleCount());
    return g;
}

RTCGeometry Scene::newSphere(const ShapeDescription& s) {
    RTCGeometry g = rtcNewGeometry(device_, RTC_GEOMETRY_TYPE_SPHERE_POINT);
    auto* v = static_cast<float*>(
        rtcSetNewGeometryBuffer(g, RTC_BUFFER_TYPE_VERTEX, 0, RTC_FORMAT_FLOAT4, 4 * sizeof(float), 1));
    v[0] = s.center.x;
    v[1] = s.center.y;
    v[2] = s.center.z;
    v[3] = s.radius;
    return g;
}

void Scene::addShape(const ShapeDescription& s, RTCScene target, uint32_t id) {
    if (s.kind == ShapeDescription::Kind::Curves && (hasCutout(s) || !isBlack(s.emission) || s.boundsMedium()))
        throw std::runtime_error(s.name + ": curves cannot emit, have an alpha below 1 or bound a medium");
    RTCGeometry g = s.kind == ShapeDescription::Kind::Sphere   ? newSphere(s)
                    : s.kind == ShapeDescription::Kind::Curves ? newCurves(s)
                                                               : newMesh(s.mesh);
    if (hasCutout(s)) {
        // A light's power and its samples assume all of its surface emits.
        if (!isBlack(s.emission))
            throw std::runtime_error(s.name + ": an emissive shape cannot have an alpha below 1");
        attachAlphaCutout(g, s);
    }
    rtcCommitGeometry(g);
    rtcAttachGeometryByID(target, g, id);
    // Kept in the scene under its id, so that every other shape's stays; no ray meets it.
    if (s.invisible) rtcDisableGeometry(g);
    rtcReleaseGeometry(g);
}

void Scene::buildLights() {
    Vec3 c = (boundsMin_ + boundsMax_) * 0.5f;
    float r = std::max(length(boundsMax_ - c), 1e-3f);
    SceneSphere sphere{c, r};
    // Emitters are world shapes (an object's are copied into the world per instance); the
    // sampler keeps the lights' order, so a light's index there is its index here.
    lightOfShape_.assign(slots_.size(), -1);
    for (uint32_t i = 0; i < shapes_.size(); ++i) {
        const ShapeDescription& s = shapes_[i];
        if (isBlack(s.emission)) continue;
        lightOfShape_[i] = int32_t(ownedLights_.size());
        // An emitter that bounds a medium sends its photons into its outside medium (the
        // side its normal faces); one that bounds none, into the medium around it
        // (placeLightsInMedia).
        lightMedium_.push_back(s.outsideMedium);
        lightMediumSaid_.push_back(s.boundsMedium() || s.outsideMedium >= 0);
        std::unique_ptr<Light> light = s.kind == ShapeDescription::Kind::Sphere
                                           ? makeSphereAreaLight(s)
                                           : makeMeshAreaLight(s, description_.render.lightSampler);
        ownedLights_.push_back(s.invisible ? makeInvisibleAreaLight(std::move(light)) : std::move(light));
    }
    for (const LightDescription& d : description_.lights) {
        lightMedium_.push_back(d.medium);
        lightMediumSaid_.push_back(d.medium >= 0);
        switch (d.kind) {
            case LightDescription::Kind::Point: ownedLights_.push_back(makePointLight(d)); break;
            case LightDescription::Kind::Spot: ownedLights_.push_back(makeSpotLight(d)); break;
            case LightDescription::Kind::Projection: ownedLights_.push_back(makeProjectionLight(d)); break;
            case LightDescription::Kind::Directional: ownedLights_.push_back(makeDirectionalLight(d, sphere)); break;
            case LightDescription::Kind::Environment:
                ownedLights_.push_back(makeEnvironmentLight(d, sphere));
                environmentLights_.push_back({ownedLights_.back().get(), 0.0f});
                break;
        }
    }
    // Media that emit send their photons into themselves, from the points of their grid
    // that lie in them.
    for (size_t i = 0; i < description_.media.size(); ++i) {
        const MediumDescription& medium = description_.media[i];
        if (!medium.emits()) continue;
        const int32_t m = int32_t(i);
        std::shared_ptr<const DensityGrid> region = medium.emissionRegion();
        if (!region) region = boxAroundShapesHolding(m);
        if (!region) continue;  // a homogeneous medium no shape holds: nowhere in the scene
        lightMedium_.push_back(m);
        lightMediumSaid_.push_back(1);
        ownedLights_.push_back(makeMediumLight(medium, std::move(region), [this, m](Vec3 p) { return inMedium(p, m); }));
    }
    std::vector<const Light*> lights;
    for (const auto& l : ownedLights_) lights.push_back(l.get());
    lightSampler_ = LightSampler(std::move(lights));
    directLightSampler_ = DirectLightSampler(lightSampler_, description_.render.lightSampler);
    for (size_t i = 0; i < lightSampler_.size(); ++i)
        for (EnvironmentLight& e : environmentLights_)
            if (&lightSampler_.light(i) == e.light) e.pickProbability = directLightSampler_.probability(i, Vec3(0.0f), Vec3(0.0f));
    const bool anyScatters = std::any_of(description_.media.begin(), description_.media.end(),
                                         [](const MediumDescription& m) { return m.scatters(); });
    if (description_.render.equiangular && anyScatters) lightsAlongRays_ = LightsAlongRays(lightSampler_);

}

void Scene::prepareHitData() {
    for (const MediumDescription& m : description_.media) {
        scatteringMedia_ = scatteringMedia_ || m.scatters();
        emittingMedia_ = emittingMedia_ || m.emits();
    }
    mediumBounded_.assign(description_.media.size(), 0);
    mediumOutside_.assign(description_.media.size(), 0);
    for (const ShapeDescription* shape : slots_) {
        if (!shape->boundsMedium()) continue;
        for (int32_t m : {shape->insideMedium, shape->outsideMedium})
            if (m >= 0) mediumBounded_[size_t(m)] = 1;
        if (shape->outsideMedium >= 0) mediumOutside_[size_t(shape->outsideMedium)] = 1;
    }
    for (size_t m = 0; m < description_.media.size(); ++m) {
        const size_t family = size_t(palettes_.family(int32_t(m)));
        mediumBounded_[m] = mediumBounded_[family], mediumOutside_[m] = mediumOutside_[family];
    }
    for (const ShapeDescription* shape : slots_) {
        materialOf_.push_back(shape->material);
        const std::optional<Material::SmoothSpecular> smooth = materials_[shape->material]->smoothSpecular();
        passThrough_.push_back(smooth && smooth->ior == 1.0f);
        auto curve = curveOfShape_.find(shape);
        curveOfSlot_.push_back(curve == curveOfShape_.end() ? nullptr : curve->second);
    }
    hitData_.resize(slots_.size());
    for (size_t i = 0; i < slots_.size(); ++i) {
        const ShapeDescription& shape = *slots_[i];
        ShapeHitData& d = hitData_[i];
        d.normalSign = shape.flipNormals ? -1.0f : 1.0f;
        d.needsUv = materials_[shape.material]->textured() || shape.emissionTexture || palettes_.textured(shape.insideMedium);
        if (shape.kind != ShapeDescription::Kind::Mesh) continue;
        const TriangleMesh& m = shape.mesh;
        // Vertex normals equal to their faces' (a quad's, a flat mesh's) change nothing.
        for (size_t t = 0; t < m.triangleCount() && !m.normals.empty() && !d.smoothNormals; ++t) {
            const uint32_t* v = &m.indices[3 * t];
            const Vec3 n = m.faceNormal(t);
            for (int k = 0; k < 3; ++k) d.smoothNormals = d.smoothNormals || lengthSquared(m.normals[v[k]] - n) > 1e-10f;
        }
    }
    firstFlatTriangle_.assign(slots_.size(), kNotFlat);
    plainSpheres_.assign(slots_.size(), PlainSphere{});
    for (size_t i = 0; i < slots_.size(); ++i) {
        const ShapeDescription& shape = *slots_[i];
        ShapeHitData& d = hitData_[i];
        if (shape.kind == ShapeDescription::Kind::Sphere) {
            if (!d.needsUv) plainSpheres_[i] = {shape.center, shape.radius, d.normalSign};
            continue;
        }
        if (shape.kind == ShapeDescription::Kind::Curves || d.smoothNormals || d.needsUv) continue;
        const TriangleMesh& m = shape.mesh;
        firstFlatTriangle_[i] = static_cast<uint32_t>(flatTriangles_.size());
        for (size_t t = 0; t < m.triangleCount(); ++t) {
            const uint32_t* v = &m.indices[3 * t];
            flatTriangles_.push_back({m.positions[v[0]], m.positions[v[1]], m.positions[v[2]], m.faceNormal(t) * d.normalSign});
        }
    }
    // What a hit on a triangle reads: the flat records, and the other meshes' indices and
    // vertices. Past a core's L2 it cannot all stay in cache, and packets prefetch it.
    size_t hitBytes = flatTriangles_.size() * sizeof(FlatTriangle);
    for (size_t i = 0; i < slots_.size(); ++i) {
        const ShapeDescription& shape = *slots_[i];
        if (shape.kind != ShapeDescription::Kind::Mesh || firstFlatTriangle_[i] != kNotFlat) continue;
        const TriangleMesh& m = shape.mesh;
        hitBytes += m.indices.size() * sizeof(uint32_t) + m.positions.size() * sizeof(Vec3) +
                    m.normals.size() * sizeof(Vec3) + m.uvs.size() * sizeof(Vec2);
    }
    prefetchesHits_ = hitBytes > kHitBytesInCache;
}

void Scene::completeOtherHit(const Ray& ray, SurfaceHit& hit) const {
    hit.uv = hit.barycentric;
    const ShapeDescription& shape = *slots_[hit.shape];
    if (shape.kind == ShapeDescription::Kind::Sphere) {
        hit.p = sphereHitPoint(ray, shape.center, shape.radius, hit.t);
        fillSphereHit(shape, hit);
    } else if (shape.kind == ShapeDescription::Kind::Curves) {
        fillCurveHit(ray, hit);
    } else {
        fillTriangleHit(shape, hit);
    }
}

// Where the ray meets the sphere, computed from the ray rather than from Embree's distance,
// whose last bit Embree's single-ray and packet kernels may round differently: the root of
// |o + t d - c|^2 = r^2 nearer that distance, in double precision (the origin may be far
// from the sphere, and the roots nearly equal on a grazing ray).
Vec3 Scene::sphereHitPoint(const Ray& ray, Vec3 center, float radius, float tEmbree) {
    const double ox = static_cast<double>(ray.o.x) - center.x, oy = static_cast<double>(ray.o.y) - center.y,
                 oz = static_cast<double>(ray.o.z) - center.z;
    const double dx = ray.d.x, dy = ray.d.y, dz = ray.d.z;
    const double a = dx * dx + dy * dy + dz * dz, b = ox * dx + oy * dy + oz * dz;
    const double c = ox * ox + oy * oy + oz * oz - static_cast<double>(radius) * radius;
    const double s = std::sqrt(std::max(b * b - a * c, 0.0));
    // The roots (-b -+ s) / a lie either side of -b / a: the far one if Embree's is past it.
    const double t = (-b + (tEmbree * a > -b ? s : -s)) / a;
    return {static_cast<float>(ray.o.x + dx * t), static_cast<float>(ray.o.y + dy * t),
            static_cast<float>(ray.o.z + dz * t)};
}

void Scene::prefetchHitsOf(const RayPacket& packet) const {
    if (!prefetchesHits_) return;
    const RTCRayHit16& p = packet.rh;
    // Into L1 (prefetcht0): hitOf() reads them right after. Into L2 only, the coffee maker's
    // photon pass was no faster than without (3 rounds), unlike the gather's (sppm_gather.cpp),
    // whose lines wait a whole batch.
    auto prefetch = [](const void* address) { __builtin_prefetch(address, 0, 3); };
    // Each round asks for what the next one reads, for every lane before any lane reads it:
    // an instance's placement (which names its shape), then each triangle's line of corner
    // indices (or its flat record), then the corners they name.
    constexpr uint32_t kNone = ~0u;
    uint32_t shape[RayPacket::kSize];
    for (int lane = 0; lane < RayPacket::kSize; ++lane) {
        shape[lane] = kNone;
        const unsigned geomID = p.hit.geomID[lane], instID = p.hit.instID[0][lane];
        if (geomID == RTC_INVALID_GEOMETRY_ID) continue;
        if (instID != RTC_INVALID_GEOMETRY_ID) prefetch(&placements_[instID - firstInstanceId_]);
        else shape[lane] = geomID;
    }
    for (int lane = 0; lane < RayPacket::kSize; ++lane) {
        const unsigned geomID = p.hit.geomID[lane], instID = p.hit.instID[0][lane];
        if (geomID == RTC_INVALID_GEOMETRY_ID) continue;
        if (instID != RTC_INVALID_GEOMETRY_ID) shape[lane] = placements_[instID - firstInstanceId_].firstShape + geomID;
        const unsigned prim = p.hit.primID[lane];
        if (const uint32_t first = firstFlatTriangle_[shape[lane]]; first != kNotFlat) {
            prefetch(&flatTriangles_[first + prim]);
            shape[lane] = kNone;  // its record is all it reads
        } else if (slots_[shape[lane]]->kind == ShapeDescription::Kind::Mesh) {
            prefetch(&slots_[shape[lane]]->mesh.indices[3 * prim]);
        } else {
            shape[lane] = kNone;
        }
    }
    for (int lane = 0; lane < RayPacket::kSize; ++lane) {
        if (shape[lane] == kNone) continue;
        const TriangleMesh& m = slots_[shape[lane]]->mesh;
        const ShapeHitData& d = hitData_[shape[lane]];
        const uint32_t* corner = &m.indices[3 * p.hit.primID[lane]];
        for (int k = 0; k < 3; ++k) {
            prefetch(&m.positions[corner[k]]);
            if (d.smoothNormals) prefetch(&m.normals[corner[k]]);
            if (d.needsUv && !m.uvs.empty()) prefetch(&m.uvs[corner[k]]);
        }
    }
}

void Scene::fillTriangleHit(const ShapeDescription& shape, SurfaceHit& hit) const {
    const unsigned prim = hit.primitive;
    const float u = hit.barycentric.x, v = hit.barycentric.y;
    const TriangleMesh& m = shape.mesh;
    const ShapeHitData& d = hitData_[hit.shape];
    uint32_t i0 = m.indices[3 * prim], i1 = m.indices[3 * prim + 1], i2 = m.indices[3 * prim + 2];
    // p from Embree's barycentrics: more accurate than o + t d far from the origin.
    const Vec3 p0 = m.positions[i0], p1 = m.positions[i1], p2 = m.positions[i2];
    hit.p = atBarycentric(p0, p1, p2, u, v);
    // The face normal from the corners just loaded, as TriangleMesh::faceNormal computes it:
    // stored per triangle it cost 12 bytes a triangle for a load no faster.
    hit.ng = hit.ns = normalize(cross(p1 - p0, p2 - p0)) * d.normalSign;
    if (d.smoothNormals) {
        Vec3 ns = atBarycentric(m.normals[i0], m.normals[i1], m.normals[i2], u, v);
        float len = length(ns);
        if (len > 0) hit.ns = ns / len;
        // Keep the shading normal on the geometric side so the two agree on which side is up.
        if (dot(hit.ns, hit.ng) < 0) hit.ns = -hit.ns;
    }
    if (d.needsUv) hit.uv = m.uvAt(prim, u, v);
}

void Scene::fillSphereHit(const ShapeDescription& shape, SurfaceHit& hit) const {
    const ShapeHitData& d = hitData_[hit.shape];
    sphereNormals(shape.center, shape.radius, d.normalSign, hit);
    // Spherical (longitude, latitude) parameterisation, y up; the trigonometry is only
    // worth doing for textured spheres.
    if (!d.needsUv) return;
    hit.uv = sphereUv(hit.ng * d.normalSign);
}

bool Scene::occluded(const Ray& ray) const { return occludedIn(rtcScene_, ray); }

std::shared_ptr<const DensityGrid> Scene::boxAroundShapesHolding(int32_t medium) const {
    Vec3 lo(std::numeric_limits<float>::infinity()), hi = -lo;
    for (const ShapeDescription& s : shapes_) {
        if (!s.boundsMedium() || s.insideMedium != medium) continue;
        if (s.kind == ShapeDescription::Kind::Sphere) {
            lo = vmin(lo, s.center - Vec3(s.radius)), hi = vmax(hi, s.center + Vec3(s.radius));
        } else {
            for (Vec3 p : s.mesh.positions) lo = vmin(lo, p), hi = vmax(hi, p);
        }
    }
    if (!(lo.x < hi.x && lo.y < hi.y && lo.z < hi.z)) return nullptr;
    // A homogeneous medium's cells, all alike: 16^3 over the box (a margin keeps its faces
    // inside the grid's).
    const Vec3 margin = (hi - lo) * (1.0f / 64);
    constexpr int kCells = 16;
    return std::make_shared<const DensityGrid>(kCells, kCells, kCells, std::vector<float>(kCells * kCells * kCells, 1.0f),
                                               DensityGrid::latticeFromBox(kCells, kCells, kCells, lo - margin, hi + margin));
}

bool Scene::inMedium(Vec3 p, int32_t medium) const {
    if (!mediumBounded_[size_t(medium)]) return true;
    const std::optional<int32_t> around = mediumAround(p);
    return around ? *around == palettes_.family(medium) : mediumOutside_[size_t(medium)] != 0;
}

std::optional<int32_t> Scene::mediumAround(Vec3 p) const {
    // A direction along no axis, so that a ray from a grid's lattice rarely grazes a box's
    // edge; a ray caught between more surfaces than this gives up as one that met none.
    constexpr int kMaxCrossings = 64;
    Ray ray{p, normalize(Vec3{0.5377f, 0.6261f, 0.5647f})};
    for (int crossing = 0; crossing < kMaxCrossings; ++crossing) {
        SurfaceHit hit;
        if (!intersect(ray, hit)) break;
        const ShapeDescription& s = shape(hit.shape);
        // Leaving through the side the normal faces: p is inside (mediumToward's sides).
        if (s.boundsMedium()) return dot(ray.d, hit.ng) > 0 ? s.insideMedium : s.outsideMedium;
        ray = spawnRay(hit.p, hit.ng, ray.d);
    }
    return std::nullopt;
}

// A light whose medium the scene leaves unsaid (a point light with no "medium", an emissive
// shape that bounds none) sends its photons into the medium around it, where camera paths'
// light samples toward it already see it: a bulb inside a box of fog lights the fog by its
// photons too. (Before, its photons started in no medium and crossed the fog unscattered:
// SPPM rendered such a scene 11% darker than the path tracer away from the light.) Point
// lights are placed by where they are, area lights by a point just off their emitting side
// (not the centre of their bounds: walls that glow around a room hold the room's centre).
void Scene::placeLightsInMedia() {
    if (description_.media.empty()) return;
    // So is a camera whose medium is unsaid: the fog it stands in shows between it and the
    // surfaces it sees.
    if (description_.camera.medium < 0) description_.camera.medium = mediumAround(description_.camera.position).value_or(-1);
    // Where the ray meets no boundary the light is in the medium of no shape: the camera's
    // where no shape bounds that (fog filling the scene), else none.
    const int32_t cameraMedium = description_.camera.medium;
    const int32_t unbounded = cameraMedium >= 0 && !mediumBounded_[size_t(cameraMedium)] ? cameraMedium : -1;
    for (size_t i = 0; i < lightSampler_.size(); ++i) {
        if (lightMediumSaid_[i]) continue;
        const Light& light = lightSampler_.light(i);
        const EmissionGeometry g = light.emissionGeometry();
        std::optional<Vec3> at;
        if (g.kind == EmissionGeometry::Kind::Point) {
            at = g.position;
        } else if (const std::optional<LightPoint> y = light.samplePointByArea({0.5f, 0.5f})) {
            const float scale = std::max({1.0f, std::abs(y->p.x), std::abs(y->p.y), std::abs(y->p.z)});
            at = y->p + y->n * (1e-4f * scale);
        }
        if (at) lightMedium_[i] = mediumAround(*at).value_or(unbounded);
    }
}

bool Scene::mayFindLight(const Ray& ray) const {
    return !environmentLights_.empty() || emittingMedia_ || (emitterScene_ && occludedIn(emitterScene_, ray));
}

bool Scene::occludedIn(RTCScene scene, const Ray& ray) {
    RTCIntersectContext context;
    rtcInitIntersectContext(&context);
    RTCRay r;
    r.org_x = ray.o.x;
    r.org_y = ray.o.y;
    r.org_z = ray.o.z;
    r.dir_x = ray.d.x;
    r.dir_y = ray.d.y;
    r.dir_z = ray.d.z;
    r.tnear = 0;
    r.tfar = ray.tMax;
    r.mask = ~0u;
    r.flags = 0;
    r.time = 0;
    rtcOccluded1(scene, &context, &r);
    return r.tfar < 0;  // Embree sets tfar to -inf on a hit
}

int32_t Scene::paletteMediumToward(int32_t next, bool inward, const SurfaceHit& hit, int32_t current) const {
    if (!palettes_.textured(next)) return next;
    if (palettes_.family(current) == next) return current;
    return inward ? palettes_.entered(next, {hit.uv, hit.p, hit.ng}) : next;
}

Color Scene::shadowTransmittance(Ray ray, int32_t medium) const {
    if (!hasMedia()) return occluded(ray) ? Color(0.0f) : Color(1.0f);
    Color t(1.0f);
    // Each crossing moves the origin past the boundary; a ray that met more boundaries than
    // this is taken as blocked rather than followed without end.
    constexpr int kMaxCrossings = 64;
    // A ray to a point (a light sample's) goes on from each crossing toward where it ends:
    // the origin's offset off the boundary moves it along the ray too, by more than the
    // margin it stops short of the light by, and it met the light it was cast to (measured:
    // shadow rays from the Cornell box's upper walls through a fog box's top face 1 cm
    // under the light were all blocked, 40% of those walls' direct light lost).
    const bool toPoint = std::isfinite(ray.tMax);
    const Vec3 end = toPoint ? ray.o + ray.d * ray.tMax : Vec3{};
    for (int crossing = 0; crossing <= kMaxCrossings; ++crossing) {
        SurfaceHit hit;
        if (!intersect(ray, hit)) return t * transmittance(medium, ray.o, ray.d, ray.tMax);
        if (!passesThrough(hit)) return Color(0.0f);
        t *= transmittance(medium, ray.o, ray.d, hit.t);
        if (isBlack(t)) return t;
        medium = mediumToward(hit, ray.d, medium);
        ray = toPoint ? spawnRayTo(hit.p, hit.ng, end) : spawnRay(hit.p, hit.ng, ray.d);
    }
    return Color(0.0f);
}

SurfaceTangents Scene::tangentsAt(const SurfaceHit& hit) const {
    if (hit.instance != kNoInstance) {
        // In the object's frame, then the tangents (vectors) to the world.
        const Placement& place = placements_[hit.instance];
        SurfaceHit local = hit;
        local.instance = kNoInstance;
        local.p = place.toObject.point(hit.p);
        local.ns = place.toObject.normal(hit.ns);
        const SurfaceTangents t = tangentsAt(local);
        return {place.toWorld.vector(t.dpdu), place.toWorld.vector(t.dpdv)};
    }
    const ShapeDescription& s = *slots_[hit.shape];
    if (s.kind == ShapeDescription::Kind::Sphere) {
        // p = c + r (cos l cos f, sin l, cos l sin f) with u = 0.5 + f / 2 pi and
        // v = 0.5 + l / pi (sphereUv); degenerate at the poles.
        Vec3 n = normalize(hit.p - s.center);
        float cosLat = std::sqrt(std::max(0.0f, 1.0f - n.y * n.y));
        if (cosLat < 1e-4f) return {};
        const float r = s.radius;
        return {Vec3(-n.z, 0, n.x) * (2.0f * kPi * r),
                Vec3(-n.y * n.x / cosLat, cosLat, -n.y * n.z / cosLat) * (kPi * r)};
    }
    if (s.kind == ShapeDescription::Kind::Curves) return curveTangents(hit);
    const TriangleMesh& m = s.mesh;
    if (m.uvs.empty()) return {};
    const uint32_t* v = &m.indices[3 * hit.primitive];
    // Solve e1 = du1 dpdu + dv1 dpdv, e2 = du2 dpdu + dv2 dpdv (pbrt-v4 sec. 6.5.3).
    Vec3 e1 = m.positions[v[1]] - m.positions[v[0]], e2 = m.positions[v[2]] - m.positions[v[0]];
    Vec2 d1 = {m.uvs[v[1]].x - m.uvs[v[0]].x, m.uvs[v[1]].y - m.uvs[v[0]].y};
    Vec2 d2 = {m.uvs[v[2]].x - m.uvs[v[0]].x, m.uvs[v[2]].y - m.uvs[v[0]].y};
    float det = d1.x * d2.y - d1.y * d2.x;
    if (!(std::abs(det) > 1e-12f)) return {};
    return {(e1 * d2.y - e2 * d1.y) / det, (e2 * d1.x - e1 * d2.x) / det};
}

Color Scene::emitted(const SurfaceHit& hit, Vec3 w) const {
    const ShapeDescription& s = *slots_[hit.shape];
    return dot(hit.ng, w) > 0 || s.twoSidedEmission ? s.emissionAt({hit.uv, hit.p, hit.ng}) : Color(0.0f);
}

Color Scene::environment(const Ray& ray) const {
    Color L(0.0f);
    for (const EnvironmentLight& e : environmentLights_) L += e.light->radianceFromDirection(ray.o, ray.d);
    return L;
}

}  // namespace photon
