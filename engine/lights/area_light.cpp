// Diffuse area lights on emissive shapes: radiance Le leaves the side the normal faces.
// Points are sampled uniformly by area (a triangle picked in proportion to its area),
// photons leave cosine-distributed, so each carries Le pi A (Jensen 2001, 5.1.3).
#include <algorithm>
#include <vector>
#include "math/frame.h"
#include "math/sampling.h"
#include "lights/emission_triangles.h"
#include "lights/light_factories.h"

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
        : AreaLight(shape.emission, static_cast<float>(total)), triangles_(shape, areas, total) {}

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
        const EmissionTriangles::Triangle& tri = triangles_.samplePoint(uPosition, p);
        return emitFrom(p, tri.frame, uDirection);
    }
    const EmissionTriangles* emissionTriangles() const override { return &triangles_; }

private:
    SurfacePoint samplePoint(Vec2 u) const override {
        Vec3 p;
        const EmissionTriangles::Triangle& tri = triangles_.samplePoint(u, p);
        return {p, tri.frame.n};
    }

    EmissionTriangles triangles_;
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
