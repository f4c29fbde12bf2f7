// A colour that is either constant or looked up in a texture where the surface is hit.
#pragma once
#include <memory>
#include "texture/texture.h"

namespace photon {

struct ColorParam {
    Color value{0.0f};
    std::shared_ptr<const Texture> texture;

    ColorParam() = default;
    ColorParam(Color c) : value(c) {}  // NOLINT: a constant converts implicitly
    explicit ColorParam(std::shared_ptr<const Texture> t) : texture(std::move(t)) {}

    bool textured() const { return texture != nullptr; }
    Color eval(const TexturePoint& at) const { return texture ? texture->lookup(at) : value; }
    // Mean over the surface: what light power and lobe choices use.
    Color average() const { return texture ? texture->average() : value; }
};

}  // namespace photon
