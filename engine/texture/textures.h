// The texture kinds besides images (image_texture.h), one file each: a mapping over
// another texture, checkerboards, a bilinear blend, noise patterns, a product and a mix. Each takes constants or textures
// as its inputs (ColorParam, FloatParam), so they nest.
#pragma once
#include <cmath>
#include <memory>
#include "texture/color_param.h"
#include "texture/float_param.h"
#include "texture/image_texture.h"
#include "texture/texture_mapping.h"

namespace photon {

// `image` read with `wrap` outside its unit square, and with `invert` as max(0, 1 - value)
// (pbrt-v4's imagemap "wrap" and "invert"); the image itself for a plain repeat.
std::shared_ptr<const Texture> makeImageLookupTexture(std::shared_ptr<const ImageTexture> image, ImageWrap wrap,
                                                      bool invert);
// `texture` looked up at mapping.apply(at): an image tiled, shifted or wrapped around a
// sphere without a copy of it. Its average is the texture's own where the mapping is not
// uv (the mean over the unit square of (s, t), not weighted by the surface's area).
std::shared_ptr<const Texture> makeMappedTexture(std::shared_ptr<const Texture> texture, TextureMapping mapping);
// `even` where floor(s) + floor(t) is even, `odd` elsewhere, for (s, t) = mapping(at);
// the two inputs are read where the surface is.
std::shared_ptr<const Texture> makeCheckerboardTexture(ColorParam even, ColorParam odd, TextureMapping mapping);
// A solid checkerboard (pbrt-v4's 3D checkerboard): `even` where floor(x) + floor(y) +
// floor(z) is even for (x, y, z) = textureFromWorld(p), `odd` elsewhere.
std::shared_ptr<const Texture> makeSolidCheckerboardTexture(ColorParam even, ColorParam odd,
                                                            const Transform& textureFromWorld);
// (1 - s)(1 - t) v00 + (1 - s) t v01 + s (1 - t) v10 + s t v11 for (s, t) = mapping(at)
// (pbrt-v4's bilerp; not clamped to the unit square, as there).
std::shared_ptr<const Texture> makeBilerpTexture(ColorParam v00, ColorParam v01, ColorParam v10, ColorParam v11,
                                                 TextureMapping mapping);
// pbrt-v4's noise textures (noise_textures.cpp, perlin_noise.h), grey: fbm, the fractal sum
// of `octaves` octaves of noise at q = textureFromWorld(p), each `roughness` times the one
// before; wrinkled, the same of |noise|; windy, waves under a slow wind.
std::shared_ptr<const Texture> makeFbmTexture(const Transform& textureFromWorld, int octaves, float roughness);
std::shared_ptr<const Texture> makeWrinkledTexture(const Transform& textureFromWorld, int octaves, float roughness);
std::shared_ptr<const Texture> makeWindyTexture(const Transform& textureFromWorld);
// pbrt-v4's marble: veins of grey and slate blue along y, bent by fbm(q) times `variation`,
// q the point in the texture's space times `scale`; marbleSpline(t) is its colour ramp.
std::shared_ptr<const Texture> makeMarbleTexture(const Transform& textureFromWorld, int octaves, float roughness,
                                                 float scale, float variation);
Color marbleSpline(float t);
// `inside` within polka dots on the (s, t) plane of the mapping (pbrt-v4's dots), `outside`
// elsewhere.
std::shared_ptr<const Texture> makeDotsTexture(ColorParam inside, ColorParam outside, TextureMapping mapping);
// a * b, channel by channel (pbrt-v4's "scale" texture).
std::shared_ptr<const Texture> makeProductTexture(ColorParam a, ColorParam b);
// (1 - amount) a + amount b.
std::shared_ptr<const Texture> makeMixTexture(ColorParam a, ColorParam b, FloatParam amount);
// t along + (1 - t) across, t = |n . direction| for the surface's normal n where it is read
// (pbrt-v4's directionmix); `direction` need not be of unit length, not zero.
std::shared_ptr<const Texture> makeDirectionMixTexture(ColorParam along, ColorParam across, Vec3 direction);

// The mean of lookup() over the unit square by a fixed 256 x 256 midpoint grid: the
// average of textures whose mean has no closed form (products and mixes of textures).
Color meanOverUnitSquare(const Texture& texture);

}  // namespace photon
