#include "camera/camera.h"
#include "description/scene_description.h"
#include "math/equal_area.h"

namespace photon {

Camera::Camera(const CameraDescription& d)
    : position_(d.position), apertureRadius_(d.apertureRadius), focusDistance_(d.focusDistance),
      width_(d.width), height_(d.height), filter_(d.filter) {
    forward_ = normalize(d.lookAt - d.position);
    const Vec3 rightHanded = normalize(cross(forward_, d.up));
    up_ = cross(rightHanded, forward_);
    // A left-handed camera (pbrt's) sees the same view mirrored left to right.
    right_ = d.leftHanded ? -rightHanded : rightHanded;
    tanHalfFov_ = std::tan(d.fovDegrees * kPi / 360.0f);
    aspect_ = static_cast<float>(width_) / static_cast<float>(height_);
    pixelAngle_ = 2.0f * tanHalfFov_ / static_cast<float>(height_);
    projection_ = d.projection;
    mapping_ = d.mapping;
    halfHeight_ = 0.5f * d.viewHeight;
    pixelSize_ = d.viewHeight / static_cast<float>(height_);
    // A spherical pixel's angular side: 4 pi / pixels steradians each on the equal-area
    // square, pi / height radians of latitude on the equirectangular map.
    // A lens system's pixel: its side on the film over the effective focal length.
    if (projection_ == Projection::LensSystem) {
        lens_ = std::make_shared<const LensSystem>(d.lens, d.lensApertureDiameter, d.focusDistance, d.filmDiagonal,
                                                   width_, height_, true);
        pixelAngle_ = static_cast<float>(lens_->filmHeight() / lens_->focalLength()) / static_cast<float>(height_);
    }
    if (projection_ == Projection::Spherical)
        pixelAngle_ = mapping_ == SphericalMapping::EqualArea
                          ? std::sqrt(4.0f * kPi / (static_cast<float>(width_) * static_cast<float>(height_)))
                          : kPi / static_cast<float>(height_);
}

// The direction through film position (x, y) of a spherical camera, (u, v) = (x / width,
// y / height). The layouts are pbrt-v4's (SphericalCamera::GenerateRay), whose image is
// centred on its camera space's -x: a pbrt camera comes in with forward its -x and right
// its -z (import/pbrt/pbrt_camera.cpp).
// - Equirectangular: latitude theta = pi v from up, longitude phi = 2 pi (u - 1/2) from
//   forward toward right: the image's centre looks forward, its top row up.
// - Equal-area: Clarberg's square (math/equal_area.h) with its centre up, its corners down,
//   the middles of its left, right, top and bottom edges forward, back, right and left.
Vec3 Camera::sphericalDirection(float x, float y) const {
    const float u = x / static_cast<float>(width_), v = y / static_cast<float>(height_);
    if (mapping_ == SphericalMapping::Equirectangular) {
        const float theta = kPi * v, phi = 2.0f * kPi * (u - 0.5f);
        const float sinTheta = std::sin(theta);
        return up_ * std::cos(theta) + (forward_ * std::cos(phi) + right_ * std::sin(phi)) * sinTheta;
    }
    // pbrt: d on the sphere with the square's centre at +z, then y and z swapped (up = +z
    // of d); its +x is the camera's -forward and its +y the camera's -right. A filter's
    // sample past an edge folds back across it, as the square folds onto the sphere.
    const Vec3 d = equalAreaSquareToSphere(wrapEqualAreaSquare({u, v}));
    return normalize(up_ * d.z - forward_ * d.x - right_ * d.y);
}

Camera::PixelSample Camera::throughLens(const FilmSample& f, Vec2 uLens) const {
    const std::optional<LensSystem::Sample> s = lens_->sample(f.x, f.y, uLens);
    if (!s) return {Ray{position_, forward_}, 0.0f};
    const Vec3 origin = position_ + right_ * s->origin.x + up_ * s->origin.y + forward_ * s->origin.z;
    const Vec3 direction = right_ * s->direction.x + up_ * s->direction.y + forward_ * s->direction.z;
    return {Ray{origin, normalize(direction)}, f.weight * s->weight};
}

Ray Camera::generateRay(float x, float y, Vec2 uLens) const {
    if (projection_ == Projection::Spherical) return {position_, sphericalDirection(x, y)};
    if (lens_) return throughLens({x, y, 1.0f}, uLens).ray;
    // Film point on the plane at distance 1: [-aspect, aspect] x [-1, 1] scaled by tan(fov/2).
    const float nx = 2.0f * x / static_cast<float>(width_) - 1.0f, ny = 1.0f - 2.0f * y / static_cast<float>(height_);
    // Orthographic: every ray along the view, from the film point on the camera's plane.
    if (projection_ == Projection::Orthographic)
        return {position_ + right_ * (nx * halfHeight_ * aspect_) + up_ * (ny * halfHeight_), forward_};
    float sx = nx * tanHalfFov_ * aspect_;
    float sy = ny * tanHalfFov_;
    Vec3 dir = forward_ + right_ * sx + up_ * sy;
    if (apertureRadius_ <= 0) return {position_, normalize(dir)};
    // Thin lens (pbrt-v4 5.2.3): rays through the lens converge on the plane of focus.
    Vec3 focus = position_ + dir * focusDistance_;
    Vec2 lens = sampleUniformDiskConcentric(uLens);
    Vec3 origin = position_ + right_ * (lens.x * apertureRadius_) + up_ * (lens.y * apertureRadius_);
    return {origin, normalize(focus - origin)};
}

}  // namespace photon
