#include "texture/textures.h"

namespace photon {
namespace {

class MixTexture final : public Texture {
public:
    MixTexture(ColorParam a, ColorParam b, FloatParam amount)
        : a_(std::move(a)), b_(std::move(b)), amount_(std::move(amount)),
          average_(amount_.textured() ? meanOverUnitSquare(*this) : mix(a_.average(), b_.average(), amount_.value)) {}
    Color lookup(const TexturePoint& at) const override { return mix(a_.eval(at), b_.eval(at), amount_.eval(at)); }
    Color average() const override { return average_; }

private:
    static Color mix(Color a, Color b, float t) { return a * (1.0f - t) + b * t; }
    ColorParam a_, b_;
    FloatParam amount_;
    Color average_;
};

}  // namespace

std::shared_ptr<const Texture> makeMixTexture(ColorParam a, ColorParam b, FloatParam amount) {
    return std::make_shared<MixTexture>(std::move(a), std::move(b), std::move(amount));
}

}  // namespace photon
