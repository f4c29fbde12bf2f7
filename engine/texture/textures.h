// The texture kinds besides images (image_texture.h), one file each: a uv mapping over
// another texture, a checkerboard, a product and a mix. Each takes constants or textures
// as its inputs (ColorParam, FloatParam), so they nest.
#pragma once
#include <cmath>
#include <memory>
#include "texture/color_param.h"
#include "texture/float_param.h"

namespace photon {

// uv -> uv * scale, turned counter-clockwise by `rotation` (radians; v up), + offset, then
// the texture (pbrt-v4's UVMapping: su, sv, du, dv; glTF's KHR_texture_transform: T R S).
struct UvMapping {
    Vec2 scale{1, 1}, offset{0, 0};
    float rotation = 0;
    Vec2 apply(Vec2 uv) const {
        const Vec2 s{uv.x * scale.x, uv.y * scale.y};
        if (rotation == 0) return {s.x + offset.x, s.y + offset.y};
        const float c = std::cos(rotation), n = std::sin(rotation);
        return {c * s.x - n * s.y + offset.x, n * s.x + c * s.y + offset.y};
    }
    bool identity() const { return scale.x == 1 && scale.y == 1 && offset.x == 0 && offset.y == 0 && rotation == 0; }
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
