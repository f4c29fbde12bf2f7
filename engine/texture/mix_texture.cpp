// Mixes of two textures: by an amount (a number or texture), or by the surface's facing
// (pbrt-v4's directionmix).
#include <algorithm>
#include <cmath>
#include "texture/textures.h"

namespace photon {
namespace {

Color mix(Color a, Color b, float t) { return a * (1.0f - t) + b * t; }

class MixTexture final : public Texture {
public:
    MixTexture(ColorParam a, ColorParam b, FloatParam amount)
        : a_(std::move(a)), b_(std::move(b)), amount_(std::move(amount)),
          average_(amount_.textured() ? meanOverUnitSquare(*this) : mix(a_.average(), b_.average(), amount_.value)) {}
    Color lookup(const TexturePoint& at) const override { return mix(a_.eval(at), b_.eval(at), amount_.eval(at)); }
    Color average() const override { return average_; }

private:
    ColorParam a_, b_;
    FloatParam amount_;
    Color average_;
};

// `along` weighted by |n . direction|, `across` by the rest, n the surface's normal where the
// texture is read (pbrt-v4's DirectionMixTexture: its tex1 and tex2).
class DirectionMixTexture final : public Texture {
public:
    DirectionMixTexture(ColorParam along, ColorParam across, Vec3 direction)
        : along_(std::move(along)), across_(std::move(across)), direction_(normalize(direction)),
          // |cos| of a direction uniform on the sphere has mean 1/2: the mean over a surface
          // that faces every way alike.
          average_(mix(across_.average(), along_.average(), 0.5f)) {}
    Color lookup(const TexturePoint& at) const override {
        const float t = std::min(std::abs(dot(at.n, direction_)), 1.0f);
        // Each side read only where it has weight, as pbrt-v4 does.
        const Color a = t > 0 ? along_.eval(at) : Color(0.0f);
        const Color b = t < 1 ? across_.eval(at) : Color(0.0f);
        return a * t + b * (1.0f - t);
    }
    Color average() const override { return average_; }

private:
    ColorParam along_, across_;
    Vec3 direction_;
    Color average_;
};

}  // namespace

std::shared_ptr<const Texture> makeMixTexture(ColorParam a, ColorParam b, FloatParam amount) {
    return std::make_shared<MixTexture>(std::move(a), std::move(b), std::move(amount));
}

std::shared_ptr<const Texture> makeDirectionMixTexture(ColorParam along, ColorParam across, Vec3 direction) {
    return std::make_shared<DirectionMixTexture>(std::move(along), std::move(across), direction);
}

}  // namespace photon
