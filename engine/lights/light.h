// The one interface every light implements: sampling incident light at a point (for
// direct lighting) and emitting photons (for the photon pass).
#pragma once
#include <cstdint>
#include <limits>
#include <optional>
#include "math/frame.h"
#include "math/sampling.h"
#include "lights/light_bounds.h"
#include <photon/vec.h>

namespace photon {

struct LightSample {
    Vec3 wi;                 // unit direction from the shading point toward the light
    float distance = std::numeric_limits<float>::infinity();  // to the sampled point; inf for infinite lights
    Color weight;            // incident radiance / pdf (solid angle), or irradiance for delta lights
    float pdf = 0;           // the solid-angle density wi was drawn with; 0 for delta lights
    Vec3 normal{0.0f};       // area lights: the light's normal at the point sampled (else 0)
    // Mesh lights: the triangle the point lies on. A point on an edge two triangles share is
    // either's to rounding (a ray may name the other), and their densities may differ there.
    uint32_t triangle = 0;
};

// A point drawn on an area light by area (Light::samplePointByArea).
struct LightPoint {
    Vec3 p, n;              // where, and the normal of the (front) emitting side
    Vec2 uv;                // only where the emission is textured
    uint32_t triangle = 0;  // the mesh's triangle (meshes only)
};

// A point on an area light that a ray met.
struct EmitterPoint {
    Vec3 p;                 // where
    Vec3 ng;                // the geometric normal there
    uint32_t triangle = 0;  // the mesh's triangle (meshes only)
};

struct PhotonEmission {
    Vec3 origin, direction;  // direction is unit length
    Color flux;              // Le * |cos| / (pdf_position * pdf_direction): the photon's power, W
    Vec3 normal;             // surface normal at the origin for area lights (the ray is offset along it), else 0
};

// The scene's bounding sphere, which infinite lights need to emit photons.
struct SceneSphere {
    Vec3 center;
    float radius = 1;

    // Infinite lights send photons in direction d from a disc of the sphere's radius,
    // facing d, on the far side of the scene (pbrt-v4 12.4): a uniform point on it.
    Vec3 pointOnDiscFacing(const Frame& d, Vec2 u) const {
        Vec2 disk = sampleUniformDiskConcentric(u);
        return center + (-d.n + d.s * disk.x + d.t * disk.y) * radius;
    }
};

// How a light's photons leave it, for projection maps (Jensen 2001, sec. 5.1.3): from one
// point into a cone of directions (point and spot lights), or along one direction from a
// disc (directional lights). Other lights emit without a projection map.
struct EmissionGeometry {
    enum class Kind { Other, Point, Parallel } kind = Kind::Other;
    Vec3 position;      // Point: where every photon starts
    Frame frame;        // Point: n is the cone's axis; Parallel: n is the direction of travel
    float cosMax = -1;  // Point: no power leaves at more than acos(cosMax) from frame.n
    SceneSphere disc;   // Parallel: photons start on this sphere's disc facing frame.n
};

class EmissionTriangles;

// The side of a receiving point that a light sample is for: the directions above the plane
// through it normal to n. A surface weighs the light it receives by its cosine to n, and a
// light may shape its samples by that cosine (warped_light_pieces.h, the uniform sky); a
// point in a medium does not, and its n only splits the sphere of directions in two
// (sampleDirectLightInMedium). A surface's normal converts to its side.
// `fitted`: whether the light may spend arithmetic on fitting its samples to what it brings
// to this receiver (warped_light_pieces.h); the path tracer asks it at a path's first vertex
// only, where the light sample is most of a pixel's estimate, and points in media never
// (there is no cosine to fit, and on the Cornell box in fog SPPM rendered 0.66 times the
// passes with it).
struct ReceiverSide {
    Vec3 n;
    bool cosine = true;
    bool fitted = true;
    ReceiverSide(Vec3 normal, bool weighsByCosine = true, bool fit = true)  // NOLINT(google-explicit-constructor)
        : n(normal), cosine(weighsByCosine), fitted(fit) {}
};

class Light {
public:
    virtual ~Light() = default;
    // Total emitted power, W per channel.
    virtual Color power() const = 0;
    // Light arriving at p from above the side's plane (lights may sample only directions
    // above it).
    virtual std::optional<LightSample> sampleIncident(Vec3 p, ReceiverSide side, Vec2 u) const = 0;
    virtual std::optional<PhotonEmission> emitPhoton(Vec2 uPosition, Vec2 uDirection) const = 0;
    // Infinite lights: radiance arriving along a ray from `origin` that leaves the scene in
    // direction d (a light behind a portal shines only along rays through it).
    virtual Color radianceFromDirection(Vec3 origin, Vec3 d) const { return Color(0.0f); }
    // Infinite lights: the solid-angle density with which sampleIncident(p, side, .) returns
    // the direction wi, for weighting it against BSDF sampling (multiple importance
    // sampling, Veach 1997 ch. 9). 0 for lights no ray can find (delta lights).
    virtual float pdfIncident(Vec3 p, ReceiverSide side, Vec3 wi) const { return 0; }
    // Area lights: the same for the direction wi from p (whose light samples are kept from
    // above the side's plane) whose ray first meets the light at `at`. 0 for lights no ray
    // can find.
    virtual float pdfIncidentFrom(Vec3 p, ReceiverSide side, const EmitterPoint& at, Vec3 wi) const { return 0; }
    // For projection maps (projection_map.h): where photons leave from, and how much power
    // leaves which way. emittedDensity, for point kinds: radiant intensity (W/sr) toward
    // world direction w; for parallel kinds: the power per unit area crossing the emission
    // disc (W/m^2), whatever w.
    virtual EmissionGeometry emissionGeometry() const { return {}; }
    virtual Color emittedDensity(Vec3 w) const { return Color(0.0f); }
    // Lights on triangle meshes: the triangles photons leave from, cosine-distributed with
    // the light's whole power each (the photon walk emits eight of those at a time).
    virtual const EmissionTriangles* emissionTriangles() const { return nullptr; }
    // Finite lights: where they are and which way they shine, for choosing among them by
    // what could reach a point (direct_light_sampler.h). None for infinite lights.
    virtual std::optional<LightBounds> bounds() const { return std::nullopt; }
    // False for a light no light sample is taken toward (a medium that emits, whose light
    // a sample from inside it would weigh by an unbounded 1 / r^2): paths count its light in
    // full wherever they cross it, and its photons arrive from their first hit on
    // (PhotonPathSettings::unsampledLightsArriveFirst).
    virtual bool sampledDirectly() const { return true; }
    // Area lights: a point drawn on the light before the point it lights is known (light
    // sampled along a camera ray through a medium, light_along_ray.h), uniformly by area;
    // the density of such points (1 / area; 0 for lights that draw none); and the light
    // arriving at p from such a point y: weight Le |cos| / (d^2 pointDensity), pdf that
    // draw's solid-angle density at p, d^2 pointDensity / |cos|. None where y's emitting
    // side faces away from p.
    virtual std::optional<LightPoint> samplePointByArea(Vec2 u) const { return std::nullopt; }
    virtual float pointDensity() const { return 0; }
    virtual std::optional<LightSample> incidentFromPoint(Vec3 p, const LightPoint& y) const { return std::nullopt; }
};

}  // namespace photon
