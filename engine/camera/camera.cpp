#include "camera/camera.h"
#include "description/scene_description.h"

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
    orthographic_ = d.orthographic;
    halfHeight_ = 0.5f * d.viewHeight;
    pixelSize_ = d.viewHeight / static_cast<float>(height_);
}

Ray Camera::generateRay(float x, float y, Vec2 uLens) const {
    // Film point on the plane at distance 1: [-aspect, aspect] x [-1, 1] scaled by tan(fov/2).
    const float nx = 2.0f * x / static_cast<float>(width_) - 1.0f, ny = 1.0f - 2.0f * y / static_cast<float>(height_);
    // Orthographic: every ray along the view, from the film point on the camera's plane.
    if (orthographic_) return {position_ + right_ * (nx * halfHeight_ * aspect_) + up_ * (ny * halfHeight_), forward_};
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
