// Diffuse area lights on emissive shapes: radiance Le(uv) (a colour, times a texture if any)
// leaves the side the normal faces, or both sides of a two-sided light. Light samples are
// uniform by solid angle on spheres; on meshes they follow what each part above the
// receiver brings to it (warped_light_pieces.h), within a triangle picked by its bounds on
// a mesh of more than a quad's two, or uniform by area over a mesh with the power
// sampler; photons leave
// cosine-distributed from a side picked with probability 1 / sides, so each carries
// Le(uv) pi A sides (Jensen 2001, 5.1.3).
#include <algorithm>
#include <vector>
#include "math/clipped_triangle.h"
#include "math/frame.h"
#include "math/sampling.h"
#include "lights/emission_triangles.h"
#include "lights/light_factories.h"
#include "lights/light_tree.h"
#include "lights/warped_light_pieces.h"

namespace photon {
namespace {

// Shared by every area light: direct-light samples and photons from uniform area samples.
class AreaLight : public Light {
public:
    AreaLight(const ShapeDescription& shape, float area)
        : shape_(shape), sides_(shape.twoSidedEmission ? 2.0f : 1.0f), area_(area),
          power_(shape.meanEmission() * (kPi * area * sides_)) {}
    Color power() const override { return power_; }

    std::optional<LightSample> sampleIncident(Vec3 p, ReceiverSide, Vec2 u) const override {
        return sampleTowards(p, samplePoint(u), 1.0f / area_);
    }

    // sampleIncident's density for the point y: 1/A by area, d^2 / (cos A) in solid angle.
    float pdfIncidentFrom(Vec3 p, ReceiverSide, const EmitterPoint& at, Vec3 wi) const override {
        return solidAngleDensity(p, at, wi, 1.0f / area_);
    }

    std::optional<LightPoint> samplePointByArea(Vec2 u) const override { return samplePoint(u); }
    float pointDensity() const override { return 1.0f / area_; }
    std::optional<LightSample> incidentFromPoint(Vec3 p, const LightPoint& y) const override {
        return sampleTowards(p, y, 1.0f / area_);
    }

    std::optional<PhotonEmission> emitPhoton(Vec2 uPosition, Vec2 uDirection) const override {
        LightPoint s = samplePoint(uPosition);
        Frame frame = Frame::fromNormal(s.n);
        if (sides_ > 1) {  // the back with probability 1/2, u.x reused for the direction
            const bool back = uDirection.x >= 0.5f;
            uDirection.x = std::min(back ? 2.0f * uDirection.x - 1.0f : 2.0f * uDirection.x, 0.99999994f);
            if (back) frame = Frame::fromNormal(-s.n);
        }
        // A photon leaving p cosine-distributed about frame.n carries Le pi A sides: the
        // light's whole power where the emission is uniform.
        Color flux = shape_.emissionTexture ? shape_.emissionAt({s.uv, s.p, s.n}) * (kPi * area_ * sides_) : power_;
        return PhotonEmission{s.p, frame.toWorld(sampleCosineHemisphere(uDirection)), flux, frame.n};
    }

protected:
    // Uniform by area; n faces the (front) emitting side.
    virtual LightPoint samplePoint(Vec2 u) const = 0;

    // The light sample from p toward s, drawn with `density` by area: in solid angle
    // density d^2 / cos.
    std::optional<LightSample> sampleTowards(Vec3 p, const LightPoint& s, float density) const {
        const Vec3 toLight = s.p - p;
        const float dist2 = lengthSquared(toLight);
        if (dist2 <= 0) return std::nullopt;
        const float dist = std::sqrt(dist2);
        const Vec3 wi = toLight / dist;
        float cosLight = -dot(s.n, wi);
        if (sides_ > 1) cosLight = std::abs(cosLight);
        if (cosLight <= 0) return std::nullopt;
        return LightSample{wi, dist, shape_.emissionAt({s.uv, s.p, s.n}) * (cosLight / (dist2 * density)),
                           dist2 / cosLight * density, s.n, s.triangle};
    }
    // The same density for the point a ray from p along wi met.
    static float solidAngleDensity(Vec3 p, const EmitterPoint& at, Vec3 wi, float density) {
        const float cosLight = std::abs(dot(at.ng, wi));
        return cosLight > 0 ? lengthSquared(at.p - p) / cosLight * density : 0.0f;
    }
    // Photons of uniform emission from one side: what the photon walk emits in lanes.
    bool uniformOneSided() const { return !shape_.emissionTexture && sides_ == 1; }

    const ShapeDescription& shape_;
    float sides_, area_;
    Color power_;
};

class MeshAreaLight final : public AreaLight {
public:
    MeshAreaLight(const ShapeDescription& shape, const std::vector<double>& areas, double total, LightSamplerKind kind)
        : AreaLight(shape, static_cast<float>(total)), triangles_(shape, areas, total), triangleArea_(areas.begin(), areas.end()) {
        Vec3 lo(std::numeric_limits<float>::max()), hi(-std::numeric_limits<float>::max());
        for (size_t t = 0; t < triangles_.size(); ++t)
            for (Vec3 v : {triangles_[t].p0, triangles_[t].p0 + triangles_[t].e1, triangles_[t].p0 + triangles_[t].e2})
                lo = vmin(lo, v), hi = vmax(hi, v);
        bounds_ = boundsOf(lo, hi);
        if (kind == LightSamplerKind::Spatial && triangles_.size() > EmissionTriangles::kFewTriangles)
            pickTrianglesByBounds(areas);
    }

    static std::unique_ptr<Light> make(const ShapeDescription& shape, LightSamplerKind kind) {
        std::vector<double> areas;
        double sum = 0;
        for (size_t t = 0; t < shape.mesh.triangleCount(); ++t) {
            areas.push_back(shape.mesh.area(t));
            sum += areas.back();
        }
        return std::make_unique<MeshAreaLight>(shape, areas, sum, kind);
    }

    const EmissionTriangles* emissionTriangles() const override { return uniformOneSided() ? &triangles_ : nullptr; }
    std::optional<LightBounds> bounds() const override { return bounds_; }

    // A mesh of a few triangles (a quad light's two) is sampled by what of it lies above the
    // receiver, each part following what it brings there (warped_light_pieces.h); a mesh of
    // more, with the spatial light sampler, likewise within a triangle picked by its bounds;
    // with the power sampler, uniformly by area over the whole mesh. Where the light (or the
    // triangle picked) lies wholly above the receiver's plane and farther than
    // WarpedLightPieces::kNear times its radius, it is sampled uniformly by area as it was
    // before: what each part brings varies little there, and on the Cornell box the pieces'
    // arithmetic at every vertex made the path tracer 1.3 times as slow.
    std::optional<LightSample> sampleIncident(Vec3 p, ReceiverSide side, Vec2 u) const override {
        if (!byBounds_.empty()) {
            const LightTree::Pick pick = byBounds_.pick(u.x, p, side.n);
            if (!(pick.probability > 0)) return std::nullopt;
            if (uniformFrom(p, side, pick.light, pick.light + 1)) {
                const EmissionTriangles::Triangle& tri = triangles_[pick.light];
                Vec2 barycentric;
                LightPoint y{EmissionTriangles::pointOn(tri, {pick.rest, u.y}, barycentric), tri.frame.n, {}, pick.light};
                if (shape_.emissionTexture) y.uv = shape_.mesh.uvAt(pick.light, barycentric.x, barycentric.y);
                return sampleTowards(p, y, pick.probability / triangleArea_[pick.light]);
            }
            return sampleWarped(p, warpedPieces(p, side, pick.light, pick.light + 1), {pick.rest, u.y}, pick.probability);
        }
        const uint32_t all = uint32_t(triangles_.size());
        if (all > EmissionTriangles::kFewTriangles || uniformFrom(p, side, 0, all))
            return AreaLight::sampleIncident(p, side, u);
        return sampleWarped(p, warpedPieces(p, side, 0, all), u, 1.0f);
    }

    float pdfIncidentFrom(Vec3 p, ReceiverSide side, const EmitterPoint& at, Vec3 wi) const override {
        const uint32_t all = uint32_t(triangles_.size());
        if (byBounds_.empty() && (all > EmissionTriangles::kFewTriangles || uniformFrom(p, side, 0, all)))
            return AreaLight::pdfIncidentFrom(p, side, at, wi);
        if (at.triangle >= all || !(dot(wi, side.n) > 0)) return 0.0f;
        if (byBounds_.empty()) return warpedPieces(p, side, 0, all).density(at.triangle, at.p);
        const float pick = byBounds_.probability(at.triangle, p, side.n);
        if (uniformFrom(p, side, at.triangle, at.triangle + 1))
            return solidAngleDensity(p, at, wi, pick / triangleArea_[at.triangle]);
        return pick * warpedPieces(p, side, at.triangle, at.triangle + 1).density(at.triangle, at.p);
    }

private:
    // A mesh of more triangles than a quad's (a lamp's bulbs and shade, a strip of panels, a
    // neon sign), with the spatial light sampler: the triangle a light sample goes to is
    // picked by a bound on the light it could bring to p, as lights are among themselves
    // (direct_light_sampler.h; pbrt-v4 puts each triangle in its light tree alike), then a
    // point following what its part above brings to p. Picking by area alone
    // sends most samples from a room's worth of ceiling panels to the far ones, and from a
    // lamp to triangles facing away.
    void pickTrianglesByBounds(const std::vector<double>& areas) {
        std::vector<LightBounds> each(triangles_.size());
        const float emission = average(shape_.meanEmission());
        for (size_t t = 0; t < triangles_.size(); ++t) {
            const EmissionTriangles::Triangle& tri = triangles_[t];
            LightBounds& b = each[t];
            b.lo = vmin(tri.p0, vmin(tri.p0 + tri.e1, tri.p0 + tri.e2));
            b.hi = vmax(tri.p0, vmax(tri.p0 + tri.e1, tri.p0 + tri.e2));
            b.intensity = emission * static_cast<float>(areas[t]);
            b.axis = tri.frame.n;
            b.cosThetaO = 1;
            b.twoSided = sides_ > 1;
        }
        byBounds_ = LightTree(each);
    }
    // Light samples are kept from above the plane through p normal to n (the side of the
    // receiving surface they light; Light::sampleIncident), so they are drawn only from what
    // of each triangle lies above it: none falls behind the receiver. Where a quad light
    // stands on a surface's horizon (a lamp beside a wall, the coffee maker's lights beside
    // its body) that was up to half of its samples.
    ClippedTriangle partAbove(size_t i, Vec3 p, Vec3 n) const {
        const EmissionTriangles::Triangle& tri = triangles_[i];
        return clipTriangleAbove(tri.p0, tri.p0 + tri.e1, tri.p0 + tri.e2, p, n);
    }
    // Whether triangles [first, last) lie wholly above the side's plane through p and
    // farther from p than WarpedLightPieces::kNear times the radius of a sphere around them
    // (once that radius where the receiver asks for no fitting).
    bool uniformFrom(Vec3 p, ReceiverSide side, uint32_t first, uint32_t last) const {
        const Vec3 n = side.n;
        const float near = side.fitted ? WarpedLightPieces::kNear : 1.0f;
        Vec3 lo(std::numeric_limits<float>::max()), hi(-std::numeric_limits<float>::max());
        for (uint32_t i = first; i < last; ++i) {
            const EmissionTriangles::Triangle& tri = triangles_[i];
            for (Vec3 v : {tri.p0, tri.p0 + tri.e1, tri.p0 + tri.e2}) {
                if (!(dot(v - p, n) > 0)) return false;
                lo = vmin(lo, v), hi = vmax(hi, v);
            }
        }
        const Vec3 centre = (lo + hi) * 0.5f;
        return lengthSquared(p - centre) > near * near * lengthSquared(hi - centre);
    }
    // Triangles [first, last) by their parts above the receiver (warped_light_pieces.h).
    WarpedLightPieces warpedPieces(Vec3 p, ReceiverSide side, uint32_t first, uint32_t last) const {
        WarpedLightPieces pieces(p, side.n, side.cosine, side.fitted);
        for (uint32_t i = first; i < last; ++i) {
            const EmissionTriangles::Triangle& tri = triangles_[i];
            // A receiver in the triangle's plane (a point on the light itself, to some 50 ulps
            // of its coordinates) gets nothing from it; the solid angle's formula would give
            // it the whole 2 pi.
            const float facing = dot(p - tri.p0, tri.frame.n);
            const float inPlane = 4e-6f * (length(p) + length(tri.p0));
            if (std::abs(facing) <= inPlane || (sides_ == 1 && facing < 0)) continue;
            pieces.add(i, partAbove(i, p, side.n), tri.p0, tri.p0 + tri.e1, tri.p0 + tri.e2, triangleArea_[i], tri.frame.n);
        }
        pieces.weigh();
        return pieces;
    }
    // The light sample the pieces draw from u, the triangle's group picked with `pick`.
    std::optional<LightSample> sampleWarped(Vec3 p, const WarpedLightPieces& pieces, Vec2 u, float pick) const {
        const std::optional<WarpedLightPieces::Sample> s = pieces.sample(u);
        if (!s) return std::nullopt;
        const EmissionTriangles::Triangle& tri = triangles_[s->triangle];
        const float facing = dot(s->wi, tri.frame.n);
        const float dist = facing != 0 ? dot(tri.p0 - p, tri.frame.n) / facing : 0.0f;
        if (!(dist > 0) || !std::isfinite(dist)) return std::nullopt;
        const Vec3 onLight = p + s->wi * dist;
        Vec2 uv;
        if (shape_.emissionTexture) uv = uvOn(s->triangle, onLight);
        const float pdf = pick * s->pdf;
        return LightSample{s->wi, dist, shape_.emissionAt({uv, onLight, tri.frame.n}) / pdf, pdf, tri.frame.n, s->triangle};
    }

    // The texture coordinates at the point q of triangle i.
    Vec2 uvOn(size_t i, Vec3 q) const {
        const EmissionTriangles::Triangle& tri = triangles_[i];
        const Vec2 b = planeCoordinates(q, tri.p0, tri.e1, tri.e2).value_or(Vec2{0.0f, 0.0f});
        return shape_.mesh.uvAt(i, b.x, b.y);
    }

    LightPoint samplePoint(Vec2 u) const override {
        LightPoint s;
        Vec2 barycentric;
        size_t index;
        const EmissionTriangles::Triangle& tri = triangles_.samplePoint(u, s.p, barycentric, index);
        s.n = tri.frame.n;
        s.triangle = uint32_t(index);
        if (shape_.emissionTexture) s.uv = shape_.mesh.uvAt(index, barycentric.x, barycentric.y);
        return s;
    }

    // The box, and a cone about the area-weighted mean normal holding every triangle's
    // emitting normal (all directions when they cancel out, as on a closed mesh).
    LightBounds boundsOf(Vec3 lo, Vec3 hi) const {
        LightBounds b;
        b.lo = lo, b.hi = hi;
        b.intensity = average(shape_.meanEmission()) * area_;  // L A: along the normal of a flat one
        b.twoSided = sides_ > 1;
        Vec3 sum{0, 0, 0};
        for (size_t t = 0; t < triangles_.size(); ++t)
            sum += triangles_[t].frame.n * (0.5f * length(cross(triangles_[t].e1, triangles_[t].e2)));
        if (length(sum) > 1e-3f * area_) {
            b.axis = normalize(sum);
            b.cosThetaO = 1;
            for (size_t t = 0; t < triangles_.size(); ++t)
                b.cosThetaO = std::min(b.cosThetaO, dot(b.axis, triangles_[t].frame.n));
            // Rounding must not leave a triangle's normal outside the cone.
            b.cosThetaO = std::max(-1.0f, b.cosThetaO - 1e-4f);
        }
        return b;
    }

    EmissionTriangles triangles_;
    LightTree byBounds_;               // empty where triangles are picked by area
    std::vector<float> triangleArea_;
    LightBounds bounds_;
};

// Seen from outside, a sphere emitting outward is sampled by the cone of directions it
// subtends, uniformly in solid angle (pbrt-v4's Sphere::Sample with a reference point): every
// sample lands on the visible cap, where sampling by area wastes half its samples on the far
// side and weighs the rest by cos / d^2. Inside, or emitting inward, it is sampled by area.
class SphereAreaLight final : public AreaLight {
public:
    explicit SphereAreaLight(const ShapeDescription& shape)
        : AreaLight(shape, 4.0f * kPi * shape.radius * shape.radius), sign_(shape.flipNormals ? -1.0f : 1.0f) {}

    std::optional<LightSample> sampleIncident(Vec3 p, ReceiverSide side, Vec2 u) const override {
        auto cone = coneFrom(p);
        if (!cone) return AreaLight::sampleIncident(p, side, u);
        // Below sin^2 = 0.00068523 (1.5 degrees) 1 - cos loses its digits in float: sample
        // sin^2 theta linearly there instead (pbrt-v4, sec. 6.2.4).
        float sin2Theta, cosTheta;
        if (cone->small) {
            sin2Theta = cone->sin2Max * u.x;
            cosTheta = std::sqrt(1.0f - sin2Theta);
        } else {
            cosTheta = (1.0f - u.x) + u.x * cone->cosMax;
            sin2Theta = std::max(0.0f, 1.0f - cosTheta * cosTheta);
        }
        const float sinTheta = std::sqrt(sin2Theta), phi = 2.0f * kPi * u.y;
        const Vec3 wi = cone->frame.toWorld(Vec3(sinTheta * std::cos(phi), sinTheta * std::sin(phi), cosTheta));
        // The near intersection of the ray p + t wi with the sphere.
        const float r = shape_.radius;
        const float dist = std::max(0.0f, cone->distance * cosTheta -
                                              std::sqrt(std::max(0.0f, r * r - cone->distance * cone->distance * sin2Theta)));
        const Vec3 onLight = p + wi * dist;
        const Vec3 normal = normalize(onLight - shape_.center);
        const Color Le = shape_.emissionAt({shape_.emissionTexture ? sphereUv(normal) : Vec2{}, onLight, normal});
        return LightSample{wi, dist, Le / cone->pdf, cone->pdf, normal};
    }

    float pdfIncidentFrom(Vec3 p, ReceiverSide side, const EmitterPoint& at, Vec3 wi) const override {
        auto cone = coneFrom(p);
        return cone ? cone->pdf : AreaLight::pdfIncidentFrom(p, side, at, wi);
    }

    // Emits every way; seen from any direction it is a disc of area pi r^2.
    std::optional<LightBounds> bounds() const override {
        LightBounds b;
        const Vec3 r(shape_.radius);
        b.lo = shape_.center - r, b.hi = shape_.center + r;
        b.intensity = average(shape_.meanEmission()) * (kPi * shape_.radius * shape_.radius);
        return b;
    }

private:
    struct Cone {
        Frame frame;  // n toward the centre
        float distance, sin2Max, cosMax, pdf;
        bool small;
    };

    // The cone the sphere subtends from p, if p is outside and the sphere emits outward.
    std::optional<Cone> coneFrom(Vec3 p) const {
        if (sign_ < 0) return std::nullopt;
        const Vec3 toCentre = shape_.center - p;
        const float d2 = lengthSquared(toCentre), r2 = shape_.radius * shape_.radius;
        // Too close to tell inside from outside in float: sample by area.
        if (d2 <= r2 * 1.0001f) return std::nullopt;
        Cone c;
        c.distance = std::sqrt(d2);
        c.frame = Frame::fromNormal(toCentre / c.distance);
        c.sin2Max = r2 / d2;
        c.cosMax = std::sqrt(std::max(0.0f, 1.0f - c.sin2Max));
        c.small = c.sin2Max < 0.00068523f;
        const float oneMinusCosMax = c.small ? 0.5f * c.sin2Max : 1.0f - c.cosMax;
        c.pdf = 1.0f / (2.0f * kPi * oneMinusCosMax);
        return c;
    }

    LightPoint samplePoint(Vec2 u) const override {
        Vec3 n = sampleUniformSphere(u);
        return LightPoint{shape_.center + n * shape_.radius, n * sign_, shape_.emissionTexture ? sphereUv(n) : Vec2{}};
    }
    float sign_;
};

}  // namespace

std::unique_ptr<Light> makeMeshAreaLight(const ShapeDescription& shape, LightSamplerKind kind) {
    return MeshAreaLight::make(shape, kind);
}
std::unique_ptr<Light> makeSphereAreaLight(const ShapeDescription& shape) {
    return std::make_unique<SphereAreaLight>(shape);
}

}  // namespace photon
