// A colour that varies over a surface with its texture coordinates: an image, a pattern,
// or an expression of other textures. Float parameters read a texture's channel mean
// (see float_param.h).
#pragma once
#include <photon/vec.h>

namespace photon {

class Texture {
public:
    virtual ~Texture() = default;
    // The colour at texture coordinates uv (any finite or non-finite value; images wrap).
    virtual Color lookup(Vec2 uv) const = 0;
    // The mean of lookup() over the unit square: what light power and lobe choices use.
    virtual Color average() const = 0;
};

}  // namespace photon
