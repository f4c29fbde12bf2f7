#include <cmath>
#include "texture/textures.h"

namespace photon {
namespace {

// Whether cells floor(a) + floor(b) (+ floor(c)) add up to an even number: fmod of the sum,
// not an int cast, so that coordinates far from the origin do not overflow. Non-finite
// coordinates read as the even cell.
bool evenCell(std::initializer_list<float> coordinates) {
    double cell = 0;
    for (float c : coordinates) {
        if (!std::isfinite(c)) return true;
        cell += std::floor(double(c));
    }
    return std::fmod(std::abs(cell), 2.0) < 0.5;
}

class CheckerboardTexture final : public Texture {
public:
    CheckerboardTexture(ColorParam even, ColorParam odd, TextureMapping mapping)
        : even_(std::move(even)), odd_(std::move(odd)), mapping_(mapping),
          average_(mapping_.kind == TextureMapping::Kind::Uv ? meanOverUnitSquare(*this)
                                                             : (even_.average() + odd_.average()) * 0.5f) {}

    Color lookup(const TexturePoint& at) const override {
        const Vec2 m = mapping_.apply(at);
        return evenCell({m.x, m.y}) ? even_.eval(at) : odd_.eval(at);
    }
    Color average() const override { return average_; }

private:
    ColorParam even_, odd_;
    TextureMapping mapping_;
    Color average_;
};

class SolidCheckerboardTexture final : public Texture {
public:
    SolidCheckerboardTexture(ColorParam even, ColorParam odd, const Transform& textureFromWorld)
        : even_(std::move(even)), odd_(std::move(odd)), textureFromWorld_(textureFromWorld) {}

    Color lookup(const TexturePoint& at) const override {
        const Vec3 q = textureFromWorld_.point(at.p);
        return evenCell({q.x, q.y, q.z}) ? even_.eval(at) : odd_.eval(at);
    }
    // Half the cells of any large region are even.
    Color average() const override { return (even_.average() + odd_.average()) * 0.5f; }

private:
    ColorParam even_, odd_;
    Transform textureFromWorld_;
};

}  // namespace

std::shared_ptr<const Texture> makeCheckerboardTexture(ColorParam even, ColorParam odd, TextureMapping mapping) {
    return std::make_shared<CheckerboardTexture>(std::move(even), std::move(odd), mapping);
}

std::shared_ptr<const Texture> makeSolidCheckerboardTexture(ColorParam even, ColorParam odd,
                                                            const Transform& textureFromWorld) {
    return std::make_shared<SolidCheckerboardTexture>(std::move(even), std::move(odd), textureFromWorld);
}

}  // namespace photon
