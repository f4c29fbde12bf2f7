#include <cmath>
#include "texture/textures.h"

namespace photon {
namespace {

class CheckerboardTexture final : public Texture {
public:
    CheckerboardTexture(ColorParam even, ColorParam odd, UvMapping mapping)
        : even_(std::move(even)), odd_(std::move(odd)), mapping_(mapping), average_(meanOverUnitSquare(*this)) {}

    Color lookup(Vec2 uv) const override {
        Vec2 m = mapping_.apply(uv);
        if (!std::isfinite(m.x) || !std::isfinite(m.y)) return even_.eval(uv);
        // fmod of the sum, not an int cast: uv far from the origin must not overflow.
        double cell = std::floor(double(m.x)) + std::floor(double(m.y));
        return std::fmod(std::abs(cell), 2.0) < 0.5 ? even_.eval(uv) : odd_.eval(uv);
    }
    Color average() const override { return average_; }

private:
    ColorParam even_, odd_;
    UvMapping mapping_;
    Color average_;
};

}  // namespace

std::shared_ptr<const Texture> makeCheckerboardTexture(ColorParam even, ColorParam odd, UvMapping mapping) {
    return std::make_shared<CheckerboardTexture>(std::move(even), std::move(odd), mapping);
}

}  // namespace photon
