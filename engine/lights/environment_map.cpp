#include "lights/environment_map.h"
#include <cmath>
#include <stdexcept>

namespace photon {

EnvironmentMap::EnvironmentMap(std::shared_ptr<const ImageTexture> image, EnvironmentLayout layout)
    : image_(std::move(image)), layout_(layout), width_(image_->width()), height_(image_->height()) {
    if (layout_ == EnvironmentLayout::EqualArea && width_ != height_)
        throw std::invalid_argument("an equal-area environment image must be square, not " + std::to_string(width_) +
                                    "x" + std::to_string(height_));
    texelSolidAngle_.resize(size_t(height_));
    if (layout_ == EnvironmentLayout::LatLong) {
        // Row y spans theta in [pi y / h, pi (y+1) / h]: a band of solid angle
        // 2 pi (cos theta_top - cos theta_bottom), shared by its w texels. This is the
        // sin(theta) Jacobian of the longitude-latitude map, integrated over the row.
        cosThetaEdge_.resize(size_t(height_) + 1);
        for (int y = 0; y <= height_; ++y) cosThetaEdge_[size_t(y)] = float(std::cos(M_PI * y / height_));
        for (int y = 0; y < height_; ++y) {
            double band = 2 * M_PI * (std::cos(M_PI * y / height_) - std::cos(M_PI * (y + 1) / height_));
            texelSolidAngle_[size_t(y)] = float(band / width_);
        }
    } else {
        std::fill(texelSolidAngle_.begin(), texelSolidAngle_.end(), float(4 * M_PI / (double(width_) * height_)));
    }
    // Luminance x solid angle: the share of the map's light each texel holds.
    std::vector<float> weights(size_t(width_) * size_t(height_));
    double sum[3] = {0, 0, 0};
    for (int y = 0; y < height_; ++y)
        for (int x = 0; x < width_; ++x) {
            const Color c = image_->texel(x, y);
            const float omega = texelSolidAngle_[size_t(y)];
            weights[size_t(y) * size_t(width_) + size_t(x)] = luminance(c) * omega;
            for (int k = 0; k < 3; ++k) sum[k] += double(c[k]) * omega;
        }
    distribution_ = PiecewiseConstant2D(weights, width_, height_);
    integral_ = Color(float(sum[0]), float(sum[1]), float(sum[2]));
}

TexelIndex EnvironmentMap::texelOf(Vec3 d) const {
    if (layout_ == EnvironmentLayout::LatLong) {
        float u = std::atan2(-d.x, d.z) * (0.5f * kInvPi);
        if (u < 0) u += 1;
        const float theta = std::acos(std::clamp(d.y, -1.0f, 1.0f));
        const int x = std::min(int(u * float(width_)), width_ - 1);
        const int y = std::min(int(theta * kInvPi * float(height_)), height_ - 1);
        return {std::max(x, 0), std::max(y, 0)};
    }
    const Vec2 p = equalAreaSphereToSquare(d);
    // p can reach 1 (or, rounded, pass 0 or 1): the fold gives the texel across the edge.
    return wrapEqualAreaTexel({int(std::floor(p.x * float(width_))), int(std::floor(p.y * float(height_)))}, width_,
                              height_);
}

Vec3 EnvironmentMap::directionAt(Vec2 p, int row) const {
    if (layout_ == EnvironmentLayout::EqualArea) return equalAreaSquareToSphere(p);
    // Uniform in phi and in cos theta across the row: uniform in solid angle over the texel.
    const float phi = 2 * kPi * p.x;
    const float t = std::clamp(p.y * float(height_) - float(row), 0.0f, 1.0f);
    const float top = cosThetaEdge_[size_t(row)], bottom = cosThetaEdge_[size_t(row) + 1];
    const float cosTheta = top + t * (bottom - top);
    const float sinTheta = std::sqrt(std::max(0.0f, 1 - cosTheta * cosTheta));
    return {-sinTheta * std::sin(phi), cosTheta, sinTheta * std::cos(phi)};
}

float EnvironmentMap::poleIrradiance() const {
    const Vec3 pole = layout_ == EnvironmentLayout::LatLong ? Vec3{0, 1, 0} : Vec3{0, 0, 1};
    double sum = 0;
    for (int y = 0; y < height_; ++y)
        for (int x = 0; x < width_; ++x) {
            const Vec3 d = directionAt({(float(x) + 0.5f) / float(width_), (float(y) + 0.5f) / float(height_)}, y);
            const float cosine = dot(d, pole);
            if (cosine > 0) sum += double(luminance(image_->texel(x, y))) * cosine * texelSolidAngle(y);
        }
    return float(sum);
}

float environmentScale(const LightDescription::EnvironmentImage& e, const EnvironmentMap& map) {
    if (!(e.illuminance > 0)) return e.scale;
    const float pole = map.poleIrradiance();
    return pole > 0 ? e.scale * e.illuminance / pole : e.scale;
}

std::optional<EnvironmentMap::DirectionSample> EnvironmentMap::sample(Vec2 u) const {
    if (isBlack(integral_)) return std::nullopt;
    const PiecewiseConstant2D::Sample s = distribution_.sample(u);
    const Vec3 d = directionAt(s.point, s.y);
    // Radiance and density from the texel d falls in, so that they are exactly what
    // radiance(d) and pdf(d) report (they differ from the sampled texel's only when
    // rounding puts d on the far side of a texel edge).
    const TexelIndex t = texelOf(d);
    const float density = texelProbability(t) / texelSolidAngle(t.y);
    if (!(density > 0)) return std::nullopt;
    return DirectionSample{d, image_->texel(t.x, t.y), density};
}

}  // namespace photon
