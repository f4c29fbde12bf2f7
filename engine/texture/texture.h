// A colour that varies over a surface: an image or pattern read at the surface's texture
// coordinates or at its point in space, or an expression of other textures. Float
// parameters read a texture's channel mean (see float_param.h).
#pragma once
#include <photon/vec.h>

namespace photon {

// Where a texture is read: the surface's texture coordinates, its point in world space
// (solid textures and the spherical, cylindrical and planar mappings read the point) and its
// normal there, of either sign (directionmix reads it; zero where no surface is meant: a
// texture's mean, a material's albedo table).
struct TexturePoint {
    Vec2 uv;
    Vec3 p{0.0f};
    Vec3 n{0.0f};
};

class Texture {
public:
    virtual ~Texture() = default;
    // The colour at `at` (any finite or non-finite value; images wrap).
    virtual Color lookup(const TexturePoint& at) const = 0;
    // What light power and lobe choices use for the mean over a surface: the mean of
    // lookup() over the unit square of uv (a solid texture's over a cube of its space).
    virtual Color average() const = 0;
};

}  // namespace photon
