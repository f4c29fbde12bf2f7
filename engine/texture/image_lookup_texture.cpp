#include <algorithm>
#include "texture/textures.h"

namespace photon {
namespace {

// An image read with a wrap other than repeat, or inverted (pbrt-v4's imagemap "wrap" and
// "invert": max(0, 1 - value) per channel).
class ImageLookupTexture final : public Texture {
public:
    ImageLookupTexture(std::shared_ptr<const ImageTexture> image, ImageWrap wrap, bool invert)
        : image_(std::move(image)), wrap_(wrap), invert_(invert), average_(meanOverUnitSquare(*this)) {}
    Color lookup(const TexturePoint& at) const override {
        const Color c = image_->lookup(at.uv, wrap_);
        if (!invert_) return c;
        return Color(std::max(0.0f, 1 - c.x), std::max(0.0f, 1 - c.y), std::max(0.0f, 1 - c.z));
    }
    Color average() const override { return average_; }

private:
    std::shared_ptr<const ImageTexture> image_;
    ImageWrap wrap_;
    bool invert_;
    Color average_;
};

}  // namespace

std::shared_ptr<const Texture> makeImageLookupTexture(std::shared_ptr<const ImageTexture> image, ImageWrap wrap,
                                                      bool invert) {
    if (wrap == ImageWrap::Repeat && !invert) return image;
    return std::make_shared<ImageLookupTexture>(std::move(image), wrap, invert);
}

}  // namespace photon
