// Diffuse area lights on emissive shapes: radiance Le leaves the side the normal faces.
// Points are sampled uniformly by area (a triangle picked in proportion to its area),
// photons leave cosine-distributed, so each carries Le pi A (Jensen 2001, 5.1.3).
#include <algorithm>
#include <vector>
#include "../math/frame.h"
#include "../math/sampling.h"
#include "light_factories.h"

namespace photon {
namespace {

struct SurfacePoint {
    Vec3 p, n;
};

// Shared by every area light: direct-light samples and photons from uniform area samples.
class AreaLight : public Light {
public:
    AreaLight(Color emission, float area) : emission_(emission), area_(area), power_(emission * (kPi * area)) {}
    Color power() const override { return power_; }

    std::optional<LightSample> sampleIncident(Vec3 p, Vec3, Vec2 u) const override {
        SurfacePoint s = samplePoint(u);
        Vec3 toLight = s.p - p;
        float dist2 = lengthSquared(toLight);
        if (dist2 <= 0) return std::nullopt;
        float dist = std::sqrt(dist2);
        Vec3 wi = toLight / dist;
        float cosLight = -dot(s.n, wi);
        if (cosLight <= 0) return std::nullopt;
        // Area density 1/A converted to solid angle: pdf = d^2 / (cos A).
        return LightSample{wi, dist, emission_ * (cosLight * area_ / dist2)};
    }

    std::optional<PhotonEmission> emitPhoton(Vec2 uPosition, Vec2 uDirection) const override {
        SurfacePoint s = samplePoint(uPosition);
        return emitFrom(s.p, Frame::fromNormal(s.n), uDirection);
    }

protected:
    virtual SurfacePoint samplePoint(Vec2 u) const = 0;
    // A photon leaving p cosine-distributed about frame.n carries the light's whole power.
    PhotonEmission emitFrom(Vec3 p, const Frame& frame, Vec2 uDirection) const {
        return PhotonEmission{p, frame.toWorld(sampleCosineHemisphere(uDirection)), power_, frame.n};
    }
    Color emission_;
    float area_;
    Color power_;
};

class MeshAreaLight final : public AreaLight {
public:
    MeshAreaLight(const ShapeDescription& shape, const std::vector<double>& areas, double total)
        : AreaLight(shape.emission, static_cast<float>(total)) {
        // Everything a sample needs, per triangle and in one place: photons are emitted
        // millions of times a pass.
        const TriangleMesh& m = shape.mesh;
        float sign = shape.flipNormals ? -1.0f : 1.0f;
        double sum = 0;
        for (size_t t = 0; t < m.triangleCount(); ++t) {
            TriangleMesh::Corners k = m.corners(t);
            // (A mesh without area has no power and is never picked; its shares stay finite.)
            float lo = total > 0 ? static_cast<float>(sum / total) : 0.0f;
            sum += areas[t];
            float hi = t + 1 == m.triangleCount() || !(total > 0) ? 1.0f : static_cast<float>(sum / total);
            triangles_.push_back({k.a, k.b - k.a, k.c - k.a, Frame::fromNormal(m.faceNormal(t) * sign), lo,
                                  1.0f / std::max(hi - lo, 1e-12f)});
            cdf_.push_back(hi);
        }
    }

    static std::unique_ptr<Light> make(const ShapeDescription& shape) {
        std::vector<double> areas;
        double sum = 0;
        for (size_t t = 0; t < shape.mesh.triangleCount(); ++t) {
            areas.push_back(shape.mesh.area(t));
            sum += areas.back();
        }
        return std::make_unique<MeshAreaLight>(shape, areas, sum);
    }

    std::optional<PhotonEmission> emitPhoton(Vec2 uPosition, Vec2 uDirection) const override {
        Vec3 p;
        const Triangle& tri = sampleTriangle(uPosition, p);
        return emitFrom(p, tri.frame, uDirection);
    }

private:
    struct Triangle {
        Vec3 p0, e1, e2;  // p = p0 + b1 e1 + b2 e2
        Frame frame;      // n faces the emitting side
        float cdfLow, inverseWidth;  // where the triangle's share of [0, 1) starts, 1 / its size
    };

    // Picks a triangle in proportion to its area with u.x, then reuses what is left of u.x
    // within its share for a uniform point on it.
    const Triangle& sampleTriangle(Vec2 u, Vec3& p) const {
        const Triangle& tri = triangles_[std::min(triangleAt(u.x), triangles_.size() - 1)];
        float ux = std::clamp((u.x - tri.cdfLow) * tri.inverseWidth, 0.0f, 0.99999994f);
        Vec2 b = sampleUniformTriangle({ux, u.y});
        // Barycentric b.x on the first vertex, b.y on the second.
        p = tri.p0 + tri.e1 * b.y + tri.e2 * (1.0f - b.x - b.y);
        return tri;
    }

    SurfacePoint samplePoint(Vec2 u) const override {
        Vec3 p;
        const Triangle& tri = sampleTriangle(u, p);
        return {p, tri.frame.n};
    }

    // The triangle whose share of [0, 1) holds u. A few triangles (a quad's two) are counted
    // without branches: the binary search's branch is a coin toss there, mispredicted half
    // the time.
    size_t triangleAt(float u) const {
        if (cdf_.size() > 16) return static_cast<size_t>(std::upper_bound(cdf_.begin(), cdf_.end(), u) - cdf_.begin());
        size_t below = 0;
        for (float c : cdf_) below += c <= u;
        return below;
    }

    std::vector<Triangle> triangles_;
    std::vector<float> cdf_;  // upper ends of the triangles' shares
};

class SphereAreaLight final : public AreaLight {
public:
    explicit SphereAreaLight(const ShapeDescription& shape)
        : AreaLight(shape.emission, 4.0f * kPi * shape.radius * shape.radius), center_(shape.center),
          radius_(shape.radius), sign_(shape.flipNormals ? -1.0f : 1.0f) {}

private:
    SurfacePoint samplePoint(Vec2 u) const override {
        Vec3 n = sampleUniformSphere(u);
        return {center_ + n * radius_, n * sign_};
    }
    Vec3 center_;
    float radius_, sign_;
};

}  // namespace

std::unique_ptr<Light> makeMeshAreaLight(const ShapeDescription& shape) { return MeshAreaLight::make(shape); }
std::unique_ptr<Light> makeSphereAreaLight(const ShapeDescription& shape) {
    return std::make_unique<SphereAreaLight>(shape);
}

}  // namespace photon
