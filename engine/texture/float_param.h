// A scalar material parameter (roughness, alpha, mix amount, eta scale) that is either
// constant or read from a texture: the mean of the texture's three channels, so a grey
// image reads as its value and a single-channel or alpha texture (replicated) exactly.
#pragma once
#include <memory>
#include "texture/texture.h"

namespace photon {

struct FloatParam {
    float value = 0;
    std::shared_ptr<const Texture> texture;

    FloatParam() = default;
    FloatParam(float v) : value(v) {}  // NOLINT: a constant converts implicitly
    explicit FloatParam(std::shared_ptr<const Texture> t) : texture(std::move(t)) {}

    bool textured() const { return texture != nullptr; }
    float eval(const TexturePoint& at) const { return texture ? channelMean(texture->lookup(at)) : value; }
    float average() const { return texture ? channelMean(texture->average()) : value; }

private:
    static float channelMean(Color c) { return (c.x + c.y + c.z) * (1.0f / 3.0f); }
};

}  // namespace photon
