#include "texture/textures.h"

namespace photon {
namespace {

class UvMappedTexture final : public Texture {
public:
    UvMappedTexture(std::shared_ptr<const Texture> texture, UvMapping mapping)
        : texture_(std::move(texture)), mapping_(mapping), average_(meanOverUnitSquare(*this)) {}
    Color lookup(Vec2 uv) const override { return texture_->lookup(mapping_.apply(uv)); }
    // A whole number of repeats keeps the texture's own mean; other scales are measured.
    Color average() const override { return average_; }

private:
    std::shared_ptr<const Texture> texture_;
    UvMapping mapping_;
    Color average_;
};

}  // namespace

std::shared_ptr<const Texture> makeUvMappedTexture(std::shared_ptr<const Texture> texture, UvMapping mapping) {
    if (mapping.identity()) return texture;
    return std::make_shared<UvMappedTexture>(std::move(texture), mapping);
}

Color meanOverUnitSquare(const Texture& texture) {
    constexpr int n = 256;
    double sum[3] = {0, 0, 0};
    for (int j = 0; j < n; ++j)
        for (int i = 0; i < n; ++i) {
            Color c = texture.lookup({(i + 0.5f) / n, (j + 0.5f) / n});
            for (int k = 0; k < 3; ++k) sum[k] += c[k];
        }
    const double cells = double(n) * n;
    return Color(float(sum[0] / cells), float(sum[1] / cells), float(sum[2] / cells));
}

}  // namespace photon
