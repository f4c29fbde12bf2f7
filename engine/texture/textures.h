// The texture kinds besides images (image_texture.h), one file each: a uv mapping over
// another texture, a checkerboard, a product and a mix. Each takes constants or textures
// as its inputs (ColorParam, FloatParam), so they nest.
#pragma once
#include <memory>
#include "texture/color_param.h"
#include "texture/float_param.h"

namespace photon {

// uv -> uv * scale + offset, then the texture (pbrt-v4's UVMapping: su, sv, du, dv).
struct UvMapping {
    Vec2 scale{1, 1}, offset{0, 0};
    Vec2 apply(Vec2 uv) const { return {uv.x * scale.x + offset.x, uv.y * scale.y + offset.y}; }
    bool identity() const { return scale.x == 1 && scale.y == 1 && offset.x == 0 && offset.y == 0; }
};

// `texture` looked up at mapping.apply(uv): an image tiled or shifted without a copy of it.
std::shared_ptr<const Texture> makeUvMappedTexture(std::shared_ptr<const Texture> texture, UvMapping mapping);
// `even` where floor(u') + floor(v') is even, `odd` elsewhere, for (u', v') = mapping(uv);
// the two inputs are read at the surface's own uv.
std::shared_ptr<const Texture> makeCheckerboardTexture(ColorParam even, ColorParam odd, UvMapping mapping);
// a * b, channel by channel (pbrt-v4's "scale" texture).
std::shared_ptr<const Texture> makeProductTexture(ColorParam a, ColorParam b);
// (1 - amount) a + amount b.
std::shared_ptr<const Texture> makeMixTexture(ColorParam a, ColorParam b, FloatParam amount);

// The mean of lookup() over the unit square by a fixed 256 x 256 midpoint grid: the
// average of textures whose mean has no closed form (products and mixes of textures).
Color meanOverUnitSquare(const Texture& texture);

}  // namespace photon
