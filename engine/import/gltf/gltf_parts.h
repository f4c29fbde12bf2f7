// Internal to the glTF importer: one reader per concept, each in its own file.
#pragma once
#include <optional>
#include <string>
#include <vector>
#include "import/gltf/gltf_context.h"

namespace photon::gltf {

// An accessor's elements as doubles, `components` per element, normalised integers
// already scaled (glTF 2.0 sec. 3.6.2), sparse substitutions applied (gltf_accessors.cpp).
struct AccessorValues {
    int components = 0;
    size_t count = 0;
    std::vector<double> values;
    double at(size_t element, int component) const { return values[element * components + component]; }
};
// Every byte it reads is checked to lie inside its buffer view and buffer: a document
// whose counts or offsets overrun its buffers is an error at the accessor or view.
AccessorValues readAccessor(Context& ctx, int accessor, const std::string& referencedFrom);

// A primitive's triangles in its mesh's frame, uvs flipped to photon's v-up convention;
// nothing (with a warning) for points and lines (gltf_meshes.cpp).
std::optional<TriangleMesh> readPrimitive(Context& ctx, int mesh, int primitive);

// What a glTF material becomes (gltf_materials.cpp): a photon material, and the fields
// photon keeps on the shape (emission, two_sided, alpha, alpha_cutoff).
struct MaterialMapping {
    Json material;
    Json shapeFields = Json::object();
    // KHR_materials_volume's attenuation: the medium inside the shapes of this material
    // ({"absorption"}; null: none).
    Json medium;
};
// -1: the default material of glTF 2.0 sec. 3.9.6.
MaterialMapping mapMaterial(Context& ctx, int material);

// Where a glTF texture is read (gltf_textures.cpp).
struct TextureSlot {
    int index = -1;
    int texCoord = 0;
    const tinygltf::ExtensionMap* extensions = nullptr;
    std::string pointer;  // the texture info's, e.g. /materials/0/emissiveTexture
};
// {"texture": file, "uv_scale", "uv_offset", "channel"}; warns about what it cannot honour.
Json textureReference(Context& ctx, const TextureSlot& slot, const char* channel = nullptr);
// The file photon reads the texture's image from, relative to the glTF's folder.
std::string textureFile(Context& ctx, const TextureSlot& slot);

// A camera node's photon camera (gltf_lights_cameras.cpp).
Json cameraJson(Context& ctx, int node, const Matrix4& toWorld);
// A KHR_lights_punctual light placed by a node, in world space.
Json lightJson(Context& ctx, int light, int node, const Matrix4& toWorld);

}  // namespace photon::gltf
