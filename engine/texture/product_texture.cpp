#include "texture/textures.h"

namespace photon {
namespace {

class ProductTexture final : public Texture {
public:
    ProductTexture(ColorParam a, ColorParam b)
        : a_(std::move(a)), b_(std::move(b)),
          // The mean of a product is the product of means only if one factor is constant.
          average_(a_.textured() && b_.textured() ? meanOverUnitSquare(*this) : a_.average() * b_.average()) {}
    Color lookup(const TexturePoint& at) const override { return a_.eval(at) * b_.eval(at); }
    Color average() const override { return average_; }

private:
    ColorParam a_, b_;
    Color average_;
};

}  // namespace

std::shared_ptr<const Texture> makeProductTexture(ColorParam a, ColorParam b) {
    return std::make_shared<ProductTexture>(std::move(a), std::move(b));
}

}  // namespace photon
