// A point light that projects an image as a slide projector does (pbrt-v4's
// ProjectionLight): in the light's frame the image fills the rectangle of the plane z = 1
// that a field of view `fov` spans across its shorter side, its top toward +y; the intensity
// toward a direction through a texel is that texel times `intensity` W/sr, and nothing
// leaves outside the rectangle. Photons pick a texel by luminance x the solid angle it
// subtends (exact, math/plane_solid_angle.h), then a point of it uniformly on the plane:
// the solid-angle density is then P(texel) / area(texel) x (1 + x^2 + y^2)^(3/2), and each
// photon carries I(w) / density; the power is the sum of texel x solid angle x intensity.
#include <cmath>
#include "lights/light_factories.h"
#include "lights/point_emitter.h"
#include "math/piecewise_constant.h"
#include "math/plane_solid_angle.h"
#include "texture/image_texture.h"

namespace photon {
namespace {

class ProjectionLight final : public Light {
public:
    explicit ProjectionLight(const LightDescription& d)
        : position_(d.position),
          intensity_(d.intensity * d.environment.scale),
          image_(d.environment.image),
          toWorld_(d.environment.toWorld) {
        const int w = image_->width(), h = image_->height();
        const float t = std::tan(0.5f * d.projectionFovDegrees * kPi / 180.0f), aspect = float(w) / float(h);
        halfX_ = aspect > 1 ? aspect * t : t;
        halfY_ = aspect > 1 ? t : t / aspect;
        std::vector<float> weights(size_t(w) * size_t(h));
        for (int y = 0; y < h; ++y)
            for (int x = 0; x < w; ++x) {
                const double omega = texelSolidAngle(x, y);
                const Color texel = image_->texel(x, y);
                weights[size_t(y) * w + x] = float(luminance(texel) * omega);
                power_ += texel * float(omega);
            }
        power_ *= intensity_;
        distribution_ = PiecewiseConstant2D(weights, w, h);
        axis_ = normalize(toWorld_.vector({0, 0, 1}));
        cosEdge_ = 1.0f / std::sqrt(1 + halfX_ * halfX_ + halfY_ * halfY_);
    }

    Color power() const override { return power_; }

    std::optional<LightSample> sampleIncident(Vec3 p, ReceiverSide, Vec2) const override {
        return samplePointEmitter(position_, p, [this](Vec3 w) { return emittedDensity(w); });
    }

    std::optional<PhotonEmission> emitPhoton(Vec2, Vec2 uDirection) const override {
        if (distribution_.integral() <= 0) return std::nullopt;
        const PiecewiseConstant2D::Sample s = distribution_.sample(uDirection);
        const float x = (2 * s.point.x - 1) * halfX_, y = (1 - 2 * s.point.y) * halfY_;
        const float planePdf = s.pdf / (4 * halfX_ * halfY_);
        const float r2 = 1 + x * x + y * y;
        const float pdf = planePdf * r2 * std::sqrt(r2);
        if (!(pdf > 0)) return std::nullopt;
        const Color flux = intensity_ * image_->texel(s.x, s.y) / pdf;
        return PhotonEmission{position_, normalize(toWorld_.vector({x, y, 1})), flux, Vec3{}};
    }

    EmissionGeometry emissionGeometry() const override {
        return {EmissionGeometry::Kind::Point, position_, Frame::fromNormal(axis_), cosEdge_, {}};
    }
    Color emittedDensity(Vec3 w) const override {
        const Vec3 local = toWorld_.inverseRotation(w);
        if (!(local.z > 1e-3f * length(local))) return Color(0.0f);
        const float x = local.x / local.z, y = local.y / local.z;
        if (std::abs(x) >= halfX_ || std::abs(y) >= halfY_) return Color(0.0f);
        const int column = std::min(image_->width() - 1, int((x + halfX_) / (2 * halfX_) * image_->width()));
        const int row = std::min(image_->height() - 1, int((halfY_ - y) / (2 * halfY_) * image_->height()));
        return intensity_ * image_->texel(column, row);
    }
    std::optional<LightBounds> bounds() const override {
        // Toward the axis, out to the image's corners.
        LightBounds b;
        b.lo = b.hi = position_;
        b.intensity = average(power_) / (2 * kPi * (1 - cosEdge_));
        b.axis = axis_;
        b.cosThetaO = cosEdge_;
        b.cosThetaE = 1;
        return b;
    }

private:
    // The solid angle of texel (x, y), row 0 at the top (+y).
    double texelSolidAngle(int x, int y) const {
        const double w = image_->width(), h = image_->height();
        const double x0 = (2 * x / w - 1) * halfX_, x1 = (2 * (x + 1) / w - 1) * halfX_;
        const double y0 = (1 - 2 * (y + 1) / h) * halfY_, y1 = (1 - 2 * y / h) * halfY_;
        return rectangleSolidAngle(x0, x1, y0, y1);
    }

    Vec3 position_;
    Color intensity_;
    std::shared_ptr<const ImageTexture> image_;
    Transform toWorld_;
    float halfX_ = 1, halfY_ = 1;  // the image's half extent on the plane z = 1
    PiecewiseConstant2D distribution_;
    Color power_{0.0f};
    Vec3 axis_;
    float cosEdge_ = 0;  // the cosine of the angle out to the image's corners
};

}  // namespace

std::unique_ptr<Light> makeProjectionLight(const LightDescription& d) { return std::make_unique<ProjectionLight>(d); }

}  // namespace photon
