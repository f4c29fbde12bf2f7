// Mesh primitives (glTF 2.0 sec. 3.7.2) as photon triangle meshes.
#include <cmath>
#include "import/gltf/gltf_parts.h"

namespace photon::gltf {
namespace {

// The triangles' vertex indices for the primitive's topology (sec. 3.7.2.1): triangle lists
// as they are, strips and fans unrolled with the winding the spec gives each triangle.
// Triangles that repeat a vertex (strip restarts) are dropped.
std::vector<uint32_t> triangleIndices(const std::vector<uint32_t>& v, int mode) {
    std::vector<uint32_t> out;
    auto add = [&out](uint32_t a, uint32_t b, uint32_t c) {
        if (a != b && b != c && a != c) out.insert(out.end(), {a, b, c});
    };
    if (mode == TINYGLTF_MODE_TRIANGLES)
        for (size_t i = 0; i + 2 < v.size(); i += 3) add(v[i], v[i + 1], v[i + 2]);
    if (mode == TINYGLTF_MODE_TRIANGLE_STRIP)
        for (size_t i = 0; i + 2 < v.size(); ++i) add(v[i], v[i + 1 + i % 2], v[i + 2 - i % 2]);
    if (mode == TINYGLTF_MODE_TRIANGLE_FAN)
        for (size_t i = 0; i + 2 < v.size(); ++i) add(v[i + 1], v[i + 2], v[0]);
    return out;
}

int attribute(const tinygltf::Primitive& p, const char* name) {
    auto it = p.attributes.find(name);
    return it == p.attributes.end() ? -1 : it->second;
}

// An attribute's accessor, which must have one element per vertex and `components` each.
AccessorValues readAttribute(Context& ctx, int accessor, int components, size_t vertices, const std::string& pointer) {
    AccessorValues a = readAccessor(ctx, accessor, pointer);
    if (a.components != components)
        ctx.fail(pointerTo("accessors", accessor), "must have " + std::to_string(components) + " components for " + pointer);
    if (a.count != vertices)
        ctx.fail(pointerTo("accessors", accessor), "has " + std::to_string(a.count) + " elements where POSITION has " +
                                                       std::to_string(vertices));
    return a;
}

}  // namespace

std::optional<TriangleMesh> readPrimitive(Context& ctx, int meshIndex, int primitiveIndex) {
    const tinygltf::Primitive& p = ctx.model.meshes[meshIndex].primitives[primitiveIndex];
    const std::string pointer = pointerTo("meshes", meshIndex) + "/primitives/" + std::to_string(primitiveIndex);
    const int mode = p.mode < 0 ? TINYGLTF_MODE_TRIANGLES : p.mode;  // sec. 5.24: default 4
    if (mode != TINYGLTF_MODE_TRIANGLES && mode != TINYGLTF_MODE_TRIANGLE_STRIP && mode != TINYGLTF_MODE_TRIANGLE_FAN) {
        ctx.warn(pointer + "/mode", "points and lines are not rendered; primitive skipped");
        return std::nullopt;
    }
    if (!p.targets.empty()) ctx.warn(pointer + "/targets", "morph targets are ignored (the base shape is used)");
    const int position = attribute(p, "POSITION");
    if (position < 0) ctx.fail(pointer + "/attributes", "has no POSITION");
    const AccessorValues positions = readAccessor(ctx, position, pointer + "/attributes/POSITION");
    if (positions.components != 3) ctx.fail(pointerTo("accessors", position), "POSITION must be a VEC3");
    const size_t n = positions.count;

    TriangleMesh mesh;
    for (size_t i = 0; i < n; ++i) {
        Vec3 v(float(positions.at(i, 0)), float(positions.at(i, 1)), float(positions.at(i, 2)));
        if (!std::isfinite(v.x) || !std::isfinite(v.y) || !std::isfinite(v.z))
            ctx.fail(pointerTo("accessors", position), "position " + std::to_string(i) + " is not finite");
        mesh.positions.push_back(v);
    }
    if (const int normal = attribute(p, "NORMAL"); normal >= 0) {
        const AccessorValues normals = readAttribute(ctx, normal, 3, n, pointer + "/attributes/NORMAL");
        for (size_t i = 0; i < n && mesh.normals.size() == i; ++i) {
            Vec3 v(float(normals.at(i, 0)), float(normals.at(i, 1)), float(normals.at(i, 2)));
            const float len = length(v);
            if (len > 0 && std::isfinite(len)) mesh.normals.push_back(v / len);
        }
        if (mesh.normals.size() != n) {
            ctx.warn(pointer + "/attributes/NORMAL", "has zero or non-finite normals; flat triangle normals used");
            mesh.normals.clear();
        }
    }
    if (const int texcoord = attribute(p, "TEXCOORD_0"); texcoord >= 0) {
        const AccessorValues uvs = readAttribute(ctx, texcoord, 2, n, pointer + "/attributes/TEXCOORD_0");
        // glTF's uv origin is the image's top-left corner (sec. 3.7.2.1), photon's the
        // bottom-left: v is flipped here, once, so that every texture reads as glTF means.
        for (size_t i = 0; i < n; ++i) mesh.uvs.push_back({float(uvs.at(i, 0)), float(1.0 - uvs.at(i, 1))});
    }

    std::vector<uint32_t> vertices;
    if (p.indices >= 0) {
        const AccessorValues indices = readAccessor(ctx, p.indices, pointer + "/indices");
        if (indices.components != 1) ctx.fail(pointerTo("accessors", p.indices), "indices must be SCALAR");
        for (size_t i = 0; i < indices.count; ++i) {
            const double v = indices.values[i];
            if (!(v >= 0 && v < double(n)))
                ctx.fail(pointerTo("accessors", p.indices), "index " + std::to_string(i) + " (" + std::to_string(int64_t(v)) +
                                                                 ") is not below POSITION's " + std::to_string(n) + " vertices");
            vertices.push_back(uint32_t(v));
        }
    } else {
        for (size_t i = 0; i < n; ++i) vertices.push_back(uint32_t(i));
    }
    mesh.indices = triangleIndices(vertices, mode);
    if (mesh.indices.empty()) {
        ctx.warn(pointer, "has no triangles; skipped");
        return std::nullopt;
    }
    return mesh;
}

}  // namespace photon::gltf
