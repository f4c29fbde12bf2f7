// A scattering medium given by how it looks rather than by its coefficients: the diffuse
// reflectance of a deep slab of it, which may vary over its surface (skin's albedo map), and
// the mean free path of light in it, as renderers' "subsurface colour" and "radius" and
// pbrt-v4's "subsurface" material (reflectance, mfp) give it. Its coefficients follow from
// the classical dipole (media/diffusion_dipole.h); docs/scene-format.md#subsurface-media.
#pragma once
#include "texture/color_param.h"

namespace photon {

struct MediumReflectance {
    // In [0, 1] per channel. A texture is read where a path enters the medium through a shape
    // that has it inside, at that shape's point and texture coordinates: the path then walks
    // in the medium of that reflectance (scene/medium_palette.h), as random-walk subsurface
    // scattering takes the albedo at the entry point.
    ColorParam reflectance;
    Color meanFreePath{1.0f};  // 1 / sigma_t, in scene units, > 0
    float boundaryIor = 1.33f; // the index of the surface the reflectance is reckoned under
};

}  // namespace photon
