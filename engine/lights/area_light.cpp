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
    AreaLight(Color emission, float area) : emission_(emission), area_(area) {}
    Color power() const override { return emission_ * (kPi * area_); }

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
        Frame frame = Frame::fromNormal(s.n);
        Vec3 d = frame.toWorld(sampleCosineHemisphere(uDirection));
        return PhotonEmission{s.p, d, power(), s.n};
    }

protected:
    virtual SurfacePoint samplePoint(Vec2 u) const = 0;
    Color emission_;
    float area_;
};

class MeshAreaLight final : public AreaLight {
public:
    MeshAreaLight(const ShapeDescription& shape, std::vector<float> cdf, float area)
        : AreaLight(shape.emission, area), mesh_(shape.mesh), cdf_(std::move(cdf)) {
        float sign = shape.flipNormals ? -1.0f : 1.0f;
        for (size_t t = 0; t < mesh_.triangleCount(); ++t) {
            Vec3 a = mesh_.positions[mesh_.indices[3 * t]], b = mesh_.positions[mesh_.indices[3 * t + 1]],
                 c = mesh_.positions[mesh_.indices[3 * t + 2]];
            normals_.push_back(normalize(cross(b - a, c - a)) * sign);
        }
    }

    static std::unique_ptr<Light> make(const ShapeDescription& shape) {
        std::vector<float> cdf;
        double sum = 0;
        for (size_t t = 0; t < shape.mesh.triangleCount(); ++t) {
            sum += triangleArea(shape.mesh, t);
            cdf.push_back(static_cast<float>(sum));
        }
        for (float& c : cdf) c = static_cast<float>(c / sum);
        if (!cdf.empty()) cdf.back() = 1.0f;
        return std::make_unique<MeshAreaLight>(shape, std::move(cdf), static_cast<float>(sum));
    }

private:
    static float triangleArea(const TriangleMesh& m, size_t t) {
        Vec3 a = m.positions[m.indices[3 * t]], b = m.positions[m.indices[3 * t + 1]],
             c = m.positions[m.indices[3 * t + 2]];
        return 0.5f * length(cross(b - a, c - a));
    }

    SurfacePoint samplePoint(Vec2 u) const override {
        // Pick a triangle with u.x, then reuse what is left of u.x within its CDF interval.
        size_t t = static_cast<size_t>(std::upper_bound(cdf_.begin(), cdf_.end(), u.x) - cdf_.begin());
        t = std::min(t, cdf_.size() - 1);
        float lo = t == 0 ? 0.0f : cdf_[t - 1];
        float ux = std::clamp((u.x - lo) / std::max(cdf_[t] - lo, 1e-12f), 0.0f, 0.99999994f);
        Vec2 b = sampleUniformTriangle({ux, u.y});
        Vec3 a = mesh_.positions[mesh_.indices[3 * t]], p1 = mesh_.positions[mesh_.indices[3 * t + 1]],
             p2 = mesh_.positions[mesh_.indices[3 * t + 2]];
        Vec3 p = a * b.x + p1 * b.y + p2 * (1.0f - b.x - b.y);
        return {p, normals_[t]};
    }

    const TriangleMesh& mesh_;
    std::vector<float> cdf_;
    std::vector<Vec3> normals_;  // per triangle, facing the emitting side
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
