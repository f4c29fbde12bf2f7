#include "texture/textures.h"

namespace photon {
namespace {

class BilerpTexture final : public Texture {
public:
    BilerpTexture(ColorParam v00, ColorParam v01, ColorParam v10, ColorParam v11, TextureMapping mapping)
        : v00_(std::move(v00)), v01_(std::move(v01)), v10_(std::move(v10)), v11_(std::move(v11)), mapping_(mapping),
          // Over the unit square of (s, t) the blend's mean is the corners' mean.
          average_(mapping_.kind == TextureMapping::Kind::Uv
                       ? meanOverUnitSquare(*this)
                       : (v00_.average() + v01_.average() + v10_.average() + v11_.average()) * 0.25f) {}

    Color lookup(const TexturePoint& at) const override {
        const Vec2 st = mapping_.apply(at);
        const float s = st.x, t = st.y;
        return v00_.eval(at) * ((1 - s) * (1 - t)) + v01_.eval(at) * ((1 - s) * t) + v10_.eval(at) * (s * (1 - t)) +
               v11_.eval(at) * (s * t);
    }
    Color average() const override { return average_; }

private:
    ColorParam v00_, v01_, v10_, v11_;
    TextureMapping mapping_;
    Color average_;
};

}  // namespace

std::shared_ptr<const Texture> makeBilerpTexture(ColorParam v00, ColorParam v01, ColorParam v10, ColorParam v11,
                                                 TextureMapping mapping) {
    return std::make_shared<BilerpTexture>(std::move(v00), std::move(v01), std::move(v10), std::move(v11), mapping);
}

}  // namespace photon
