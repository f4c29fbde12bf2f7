// Alpha cutouts (leaves, fences, grilles): Embree filter functions on a shape whose
// coverage (ShapeDescription::alpha) is below 1 somewhere. A hit where the coverage is a is
// kept with probability a, decided by a hash of the ray and the primitive (stochastic
// transparency, as pbrt-v4's alpha test), so every kind of ray sees the same surface —
// camera, shadow and photon rays, one by one or in packets — and a render stays identical
// for a seed. With ShapeDescription::alphaCutoff the coverage is a mask instead (glTF's
// alphaMode MASK): a hit is kept exactly where the coverage reaches the cutoff.
#pragma once
#include <embree3/rtcore.h>
#include "description/scene_description.h"

namespace photon {

// True if the shape lets rays through anywhere (a texture, or a constant under 1 or under
// the cutoff).
bool hasCutout(const ShapeDescription& shape);
// Sets the filters on the geometry (before it is committed); `shape` must outlive it.
void attachAlphaCutout(RTCGeometry geometry, const ShapeDescription& shape);

}  // namespace photon
