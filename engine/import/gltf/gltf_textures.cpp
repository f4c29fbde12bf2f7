// Textures and images (glTF 2.0 sec. 3.8) as photon image textures. An image with a uri
// is a file next to the glTF; an embedded one (data: uri, or a .glb's buffer view) is kept
// as its encoded bytes in ImportedScene::files, which photon's image reader decodes from
// memory, so photon-convert can write it out unchanged.
#include <cmath>
#include <filesystem>
#include "import/gltf/gltf_parts.h"

namespace photon::gltf {
namespace {

// "%20" and the like (RFC 3986 sec. 2.1): uris are percent-encoded, file names are not.
std::string percentDecoded(const std::string& uri) {
    std::string out;
    for (size_t i = 0; i < uri.size(); ++i) {
        if (uri[i] == '%' && i + 2 < uri.size() && std::isxdigit(uint8_t(uri[i + 1])) && std::isxdigit(uint8_t(uri[i + 2]))) {
            out += char(std::stoi(uri.substr(i + 1, 2), nullptr, 16));
            i += 2;
        } else {
            out += uri[i];
        }
    }
    return out;
}

// The file extension of an embedded image: from its mimeType (sec. 5.17: PNG or JPEG),
// else from its first bytes.
std::string embeddedExtension(Context& ctx, const tinygltf::Image& image, const std::string& pointer) {
    if (image.mimeType == "image/png") return "png";
    if (image.mimeType == "image/jpeg") return "jpg";
    const auto& b = image.image;
    if (b.size() >= 4 && b[0] == 0x89 && b[1] == 'P' && b[2] == 'N' && b[3] == 'G') return "png";
    if (b.size() >= 2 && b[0] == 0xFF && b[1] == 0xD8) return "jpg";
    ctx.fail(pointer, "an embedded image must be a PNG or a JPEG (mimeType \"" + image.mimeType + "\")");
}

std::string imageFile(Context& ctx, int index, const std::string& referencedFrom) {
    if (index < 0 || size_t(index) >= ctx.model.images.size())
        ctx.fail(referencedFrom, "names image " + std::to_string(index) + ", which does not exist");
    const tinygltf::Image& image = ctx.model.images[index];
    const std::string pointer = pointerTo("images", index);
    if (!image.uri.empty()) {
        // A file next to the glTF, which must stay in its folder (the scene format's rule).
        const std::filesystem::path file(percentDecoded(image.uri));
        bool inside = !file.empty() && file.is_relative() && !file.has_root_name();
        for (const auto& part : file) inside = inside && part != "..";
        if (!inside) ctx.fail(pointer + "/uri", "must be a relative path inside the glTF's folder");
        return file.generic_string();
    }
    if (image.image.empty()) ctx.fail(pointer, "has no image data");
    const std::string name = "textures/" + std::to_string(index) + "." + embeddedExtension(ctx, image, pointer);
    ctx.out.files.try_emplace(name, image.image.begin(), image.image.end());
    return name;
}

const tinygltf::Texture& textureOf(Context& ctx, const TextureSlot& slot) {
    if (slot.index < 0 || size_t(slot.index) >= ctx.model.textures.size())
        ctx.fail(slot.pointer + "/index", "names texture " + std::to_string(slot.index) + ", which does not exist");
    return ctx.model.textures[slot.index];
}

// Sampler settings photon has no equivalent for (it filters bilinearly and repeats).
void checkSampler(Context& ctx, const tinygltf::Texture& texture, int textureIndex) {
    if (texture.sampler < 0 || size_t(texture.sampler) >= ctx.model.samplers.size()) return;
    const tinygltf::Sampler& s = ctx.model.samplers[texture.sampler];
    if (s.wrapS != TINYGLTF_TEXTURE_WRAP_REPEAT || s.wrapT != TINYGLTF_TEXTURE_WRAP_REPEAT)
        ctx.warn(pointerTo("samplers", texture.sampler), "clamped and mirrored wrapping are read as repeat (texture " +
                                                             std::to_string(textureIndex) + ")");
}

}  // namespace

std::string textureFile(Context& ctx, const TextureSlot& slot) {
    const tinygltf::Texture& texture = textureOf(ctx, slot);
    if (slot.texCoord != 0) ctx.warn(slot.pointer + "/texCoord", "photon reads TEXCOORD_0 only; TEXCOORD_0 used");
    checkSampler(ctx, texture, slot.index);
    if (!texture.extensions.empty())
        ctx.warn(pointerTo("textures", slot.index) + "/extensions/" + texture.extensions.begin()->first,
                 "texture extensions are ignored; the texture's source used");
    return imageFile(ctx, texture.source, pointerTo("textures", slot.index) + "/source");
}

Json textureReference(Context& ctx, const TextureSlot& slot, const char* channel) {
    Json t = {{"texture", textureFile(ctx, slot)}};
    if (channel) t["channel"] = channel;
    if (slot.extensions)
        for (const auto& [name, value] : *slot.extensions) {
            const std::string pointer = slot.pointer + "/extensions/" + name;
            if (name != "KHR_texture_transform") {
                ctx.warn(pointer, "unknown texture extension ignored");
                continue;
            }
            // uv' = T R S uv in glTF's top-down v, R turning u toward -v by `rotation` (the
            // matrix the sample model and Blender use, KhronosGroup/glTF issue 1563). In
            // photon's v, which runs up (v_photon = 1 - v_glTF), that is the same scale, the
            // same angle counter-clockwise, and the offset (o_u + sin s_v, 1 - cos s_v - o_v).
            const double su = value.Has("scale") ? value.Get("scale").Get(0).GetNumberAsDouble() : 1.0;
            const double sv = value.Has("scale") ? value.Get("scale").Get(1).GetNumberAsDouble() : 1.0;
            const double ou = value.Has("offset") ? value.Get("offset").Get(0).GetNumberAsDouble() : 0.0;
            const double ov = value.Has("offset") ? value.Get("offset").Get(1).GetNumberAsDouble() : 0.0;
            const double rotation = numberIn(value, "rotation", 0.0);
            if (value.Has("texCoord")) ctx.warn(pointer + "/texCoord", "photon reads TEXCOORD_0 only; TEXCOORD_0 used");
            t["uv_scale"] = {su, sv};
            t["uv_offset"] = {ou + std::sin(rotation) * sv, 1.0 - std::cos(rotation) * sv - ov};
            if (rotation != 0) t["uv_rotation"] = rotation * 180 / 3.14159265358979323846;
        }
    return t;
}

}  // namespace photon::gltf
