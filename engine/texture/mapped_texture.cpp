#include "texture/textures.h"

namespace photon {
namespace {

class MappedTexture final : public Texture {
public:
    MappedTexture(std::shared_ptr<const Texture> texture, TextureMapping mapping)
        : texture_(std::move(texture)), mapping_(mapping),
          // A whole number of repeats keeps the texture's own mean; other scales are
          // measured. Where (s, t) comes from the point, the surface decides which part of
          // the pattern is seen: the pattern's own mean stands for it.
          average_(mapping_.kind == TextureMapping::Kind::Uv ? meanOverUnitSquare(*this) : texture_->average()) {}
    Color lookup(const TexturePoint& at) const override { return texture_->lookup({mapping_.apply(at), at.p, at.n}); }
    Color average() const override { return average_; }

private:
    std::shared_ptr<const Texture> texture_;
    TextureMapping mapping_;
    Color average_;
};

}  // namespace

std::shared_ptr<const Texture> makeMappedTexture(std::shared_ptr<const Texture> texture, TextureMapping mapping) {
    if (mapping.identity()) return texture;
    return std::make_shared<MappedTexture>(std::move(texture), mapping);
}

Color meanOverUnitSquare(const Texture& texture) {
    constexpr int n = 256;
    double sum[3] = {0, 0, 0};
    for (int j = 0; j < n; ++j)
        for (int i = 0; i < n; ++i) {
            Color c = texture.lookup({{(i + 0.5f) / n, (j + 0.5f) / n}, Vec3(0.0f)});
            for (int k = 0; k < 3; ++k) sum[k] += c[k];
        }
    const double cells = double(n) * n;
    return Color(float(sum[0] / cells), float(sum[1] / cells), float(sum[2] / cells));
}

}  // namespace photon
