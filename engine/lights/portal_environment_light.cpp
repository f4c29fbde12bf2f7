// An environment light (constant or an image) that reaches the scene only through a
// rectangle, its portal: a window of an interior. Rays that leave the scene see the
// environment only if they pass through the portal (pbrt-v4's PortalImageInfiniteLight;
// scenes written for it rely on this, since their rooms are open elsewhere), and both light
// samples and photons go only where the portal lets light in:
//
// - Light samples: the directions leaving the portal's outer side are parameterised by
//   uv = ((atan(x / z) + pi/2) / pi, (atan(y / z) + pi/2) / pi) in the portal's frame (x, y
//   along its edges, z out of the scene). From any point inside, the directions through the
//   rectangle are then an axis-aligned window of uv (x / z and y / z each vary along one
//   edge alone), which a summed-area table samples in proportion to radiance (Bitterli,
//   Novák, Jarosz 2015, "Portal-Masked Environment Map Sampling"; the rectified
//   parameterisation as in pbrt-v4). With w the unit direction, the solid angle per unit uv
//   is dw/duv = pi^2 (1 - w_x^2)(1 - w_y^2) / w_z (from w = (tan a, tan b, 1) / |.|).
// - Photons start on the portal (uniform in area A) heading in, in directions drawn in
//   proportion to radiance x cos, each carrying L cos A / pdf(w): every photon enters the
//   room, where an unportaled environment sends almost all of them onto its outer walls.
//   They are traced from where their line leaves the scene's bounding sphere, so what
//   stands outside the portal shadows them as it shadows the rays that look out.
//
// Radiance along a ray is looked up in the environment itself (texel for texel as without
// the portal); the rectified grid only shapes the sampling densities. Every cell of it keeps
// a small floor of the mean, so no direction that brings light has density 0.
#include <algorithm>
#include <cmath>
#include "lights/environment_map.h"
#include "lights/light_factories.h"
#include "math/windowed_piecewise_constant.h"
#include "math/piecewise_constant.h"

namespace photon {
namespace {

constexpr float kFloor = 1e-4f;  // of the mean cell weight

class PortalEnvironmentLight final : public Light {
public:
    PortalEnvironmentLight(const LightDescription& d, SceneSphere bounds) : bounds_(bounds) {
        const std::array<Vec3, 4>& q = *d.portal;
        origin_ = q[0];
        width_ = length(q[3] - q[0]);
        height_ = length(q[1] - q[0]);
        frame_.s = normalize(q[3] - q[0]);
        frame_.t = normalize(q[1] - q[0]);
        frame_.n = normalize(cross(frame_.s, frame_.t));
        if (d.environment.image) {
            map_.emplace(d.environment.image, d.environment.layout);
            scale_ = environmentScale(d.environment, *map_);
            toWorld_ = d.environment.toWorld;
        } else {
            radiance_ = d.radiance;
        }
        buildDistributions(d.environment.image ? 256 : 64, d.environment.image ? 4 : 2);
    }

    Color power() const override { return power_; }

    std::optional<LightSample> sampleIncident(Vec3 p, ReceiverSide, Vec2 u) const override {
        const std::optional<UvWindow> window = windowFrom(p);
        if (!window) return std::nullopt;
        const std::optional<WindowedPiecewiseConstant2D::Sample> s = lightDistribution_.sample(u, *window);
        if (!s) return std::nullopt;
        const Vec3 local = directionAt(s->uv);
        const float pdf = s->pdf / solidAnglePerUv(local);
        if (!(pdf > 0) || !std::isfinite(pdf)) return std::nullopt;
        const Vec3 wi = frame_.toWorld(local);
        const Color L = radiance(wi);
        if (isBlack(L)) return std::nullopt;
        return LightSample{wi, std::numeric_limits<float>::infinity(), L / pdf, pdf};
    }

    float pdfIncident(Vec3 p, ReceiverSide, Vec3 wi) const override {
        const std::optional<UvWindow> window = windowFrom(p);
        const Vec3 local = frame_.toLocal(wi);
        if (!window || !(local.z > 0)) return 0;
        return lightDistribution_.pdf(uvOf(local), *window) / solidAnglePerUv(local);
    }

    Color radianceFromDirection(Vec3 o, Vec3 d) const override {
        return throughPortal(o, d) ? radiance(d) : Color(0.0f);
    }

    // The flux L cos A / pdf(w), with pdf(w) = pdf(uv) / (dw/duv): the cosine cancels
    // against dw/duv's 1 / w_z, which keeps photons at grazing directions finite.
    std::optional<PhotonEmission> emitPhoton(Vec2 uPosition, Vec2 uDirection) const override {
        const PiecewiseConstant2D::Sample s = emissionDistribution_.sample(uDirection);
        const Vec3 local = directionAt(s.point);
        if (!(local.z > 0) || !(s.pdf > 0)) return std::nullopt;
        const Vec3 out = frame_.toWorld(local);
        const Color L = radiance(out);
        if (isBlack(L)) return std::nullopt;
        const float cosTimesJacobian = kPi * kPi * (1 - local.x * local.x) * (1 - local.y * local.y);
        const Vec3 onPortal = origin_ + frame_.s * (uPosition.x * width_) + frame_.t * (uPosition.y * height_);
        return PhotonEmission{onPortal + out * outside(onPortal, out), -out,
                              L * (cosTimesJacobian * width_ * height_ / s.pdf), Vec3{}};
    }

private:
    Color radiance(Vec3 world) const {
        if (!map_) return radiance_;
        return map_->radiance(normalize(toWorld_.inverseRotation(world))) * scale_;
    }

    // (tan a, tan b, 1) normalised, written without the tangents' poles.
    static Vec3 directionAt(Vec2 uv) {
        const float a = kPi * (uv.x - 0.5f), b = kPi * (uv.y - 0.5f);
        const float ca = std::cos(a), cb = std::cos(b);
        return normalize(Vec3{std::sin(a) * cb, std::sin(b) * ca, ca * cb});
    }
    static Vec2 uvOf(Vec3 local) {
        return {std::atan2(local.x, local.z) / kPi + 0.5f, std::atan2(local.y, local.z) / kPi + 0.5f};
    }
    static float solidAnglePerUv(Vec3 local) {
        return kPi * kPi * (1 - local.x * local.x) * (1 - local.y * local.y) / local.z;
    }

    // The directions from p through the portal, or none if p is not inside (behind its
    // plane, as seen from the light).
    std::optional<UvWindow> windowFrom(Vec3 p) const {
        const Vec3 q = frame_.toLocal(p - origin_);
        const float depth = -q.z;
        if (!(depth > 1e-6f * (width_ + height_))) return std::nullopt;
        auto u = [&](float edge, float at) { return std::atan2(edge - at, depth) / kPi + 0.5f; };
        return UvWindow{{u(0, q.x), u(0, q.y)}, {u(width_, q.x), u(height_, q.y)}};
    }

    // Whether the ray from o along d leaves through the portal's rectangle (with a margin of
    // a millionth of its size, so that light samples drawn at its very edge still pass).
    bool throughPortal(Vec3 o, Vec3 d) const {
        const Vec3 q = frame_.toLocal(o - origin_), dl = frame_.toLocal(d);
        if (!(q.z < 0) || !(dl.z > 0)) return false;
        const float t = -q.z / dl.z;
        const float x = q.x + t * dl.x, y = q.y + t * dl.y;
        const float margin = 1e-6f * (width_ + height_);
        return x >= -margin && x <= width_ + margin && y >= -margin && y <= height_ + margin;
    }

    // How far along `out` from p the line leaves the bounding sphere (0 if p is outside).
    float outside(Vec3 p, Vec3 out) const {
        const Vec3 c = p - bounds_.center;
        const float b = dot(c, out), disc = b * b - (dot(c, c) - bounds_.radius * bounds_.radius);
        return disc > 0 ? std::max(0.0f, -b + std::sqrt(disc)) * 1.0001f : 0.0f;
    }

    // Cell weights from samples x samples radiances each: luminance x dw/duv for light
    // samples, times cos for photons, and the power through the portal, A x the integral of
    // L cos over the outer hemisphere.
    void buildDistributions(int n, int samples) {
        std::vector<float> light(size_t(n) * size_t(n)), emission(light.size());
        Color integral(0.0f);
        const float cellArea = 1.0f / (float(n) * float(n)), share = 1.0f / float(samples * samples);
        for (int y = 0; y < n; ++y)
            for (int x = 0; x < n; ++x) {
                double l = 0, e = 0;
                for (int j = 0; j < samples; ++j)
                    for (int i = 0; i < samples; ++i) {
                        const Vec2 uv{(float(x) + (float(i) + 0.5f) / float(samples)) / float(n),
                                      (float(y) + (float(j) + 0.5f) / float(samples)) / float(n)};
                        const Vec3 local = directionAt(uv);
                        const float jacobian = solidAnglePerUv(local);
                        const Color L = radiance(frame_.toWorld(local));
                        l += double(luminance(L) * jacobian);
                        e += double(luminance(L) * jacobian * local.z);
                        integral += L * (jacobian * local.z * cellArea * share);
                    }
                light[size_t(y) * size_t(n) + size_t(x)] = float(l * share);
                emission[size_t(y) * size_t(n) + size_t(x)] = float(e * share);
            }
        for (std::vector<float>* w : {&light, &emission}) {
            double mean = 0;
            for (float v : *w) mean += v;
            const float floor = kFloor * float(mean / double(w->size()));
            for (float& v : *w) v = std::max(v, floor);
        }
        lightDistribution_ = WindowedPiecewiseConstant2D(light, n);
        emissionDistribution_ = PiecewiseConstant2D(emission, n, n);
        power_ = integral * (width_ * height_);
    }

    SceneSphere bounds_;
    Vec3 origin_;
    float width_ = 0, height_ = 0;
    Frame frame_;  // s along p0 -> p3, t along p0 -> p1, n out of the scene
    std::optional<EnvironmentMap> map_;
    float scale_ = 1;
    Transform toWorld_;
    Color radiance_{0.0f};
    WindowedPiecewiseConstant2D lightDistribution_;
    PiecewiseConstant2D emissionDistribution_;
    Color power_{0.0f};
};

}  // namespace

std::unique_ptr<Light> makePortalEnvironmentLight(const LightDescription& d, SceneSphere bounds) {
    return std::make_unique<PortalEnvironmentLight>(d, bounds);
}

}  // namespace photon
