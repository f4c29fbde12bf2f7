// How a camera turns a film position into a ray's direction (camera/camera.cpp).
#pragma once
#include <cstdint>

namespace photon {

// Perspective (with an optional thin lens); orthographic: parallel rays along the view;
// spherical: the whole sphere of directions around the camera (pbrt-v4's SphericalCamera);
// a lens system traced ray by ray (pbrt-v4's RealisticCamera, camera/lens_system.h).
enum class CameraProjection : uint8_t { Perspective, Orthographic, Spherical, LensSystem };
// How a spherical camera lays the sphere out on the image: Clarberg's equal-area square
// (pbrt-v4's default, "equalarea") or latitude and longitude ("equirectangular").
enum class CameraSphericalMapping : uint8_t { EqualArea, Equirectangular };

}  // namespace photon
