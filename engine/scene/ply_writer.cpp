// Writing PLY triangle meshes: binary little-endian (what pbrt-v4 and most tools read
// fastest), float positions, normals and uvs only when the mesh has them, and faces as
// lists of uchar count and uint indices, the layout of Greg Turk's "The PLY Polygon File
// Format" examples.
#include <bit>
#include <cstring>
#include <fstream>
#include <stdexcept>
#include "scene/ply_header.h"
#include "scene/ply_mesh.h"

namespace photon {

namespace {

// Appends `value` in little-endian byte order, whatever the host's.
template <typename T>
void appendLittleEndian(std::string& out, T value) {
    auto bits = std::bit_cast<std::conditional_t<sizeof(T) == 1, uint8_t, uint32_t>>(value);
    if constexpr (std::endian::native == std::endian::big && sizeof(T) == 4) bits = __builtin_bswap32(bits);
    char bytes[sizeof(T)];
    std::memcpy(bytes, &bits, sizeof(T));
    out.append(bytes, sizeof(T));
}

std::string header(const TriangleMesh& mesh) {
    std::string h = "ply\nformat binary_little_endian 1.0\n";
    h += "element vertex " + std::to_string(mesh.positions.size()) + "\n";
    h += "property float x\nproperty float y\nproperty float z\n";
    if (!mesh.normals.empty()) h += "property float nx\nproperty float ny\nproperty float nz\n";
    if (!mesh.uvs.empty()) h += "property float u\nproperty float v\n";
    h += "element face " + std::to_string(mesh.triangleCount()) + "\n";
    h += "property list uchar uint vertex_indices\nend_header\n";
    return h;
}

}  // namespace

void writePlyMesh(const TriangleMesh& mesh, const std::filesystem::path& file) {
    const std::string name = file.string();
    const size_t n = mesh.positions.size();
    if ((!mesh.normals.empty() && mesh.normals.size() != n) || (!mesh.uvs.empty() && mesh.uvs.size() != n))
        throw std::runtime_error(ply::errorText(name, "cannot write a mesh whose normals or uvs are not one per position"));
    if (mesh.indices.size() % 3 != 0)
        throw std::runtime_error(ply::errorText(name, "cannot write a mesh whose index count is not a multiple of 3"));
    std::string out = header(mesh);
    const size_t vertexBytes = 4 * (3 + (mesh.normals.empty() ? 0 : 3) + (mesh.uvs.empty() ? 0 : 2));
    out.reserve(out.size() + n * vertexBytes + mesh.triangleCount() * 13);
    for (size_t i = 0; i < n; ++i) {
        for (float c : {mesh.positions[i].x, mesh.positions[i].y, mesh.positions[i].z}) appendLittleEndian(out, c);
        if (!mesh.normals.empty())
            for (float c : {mesh.normals[i].x, mesh.normals[i].y, mesh.normals[i].z}) appendLittleEndian(out, c);
        if (!mesh.uvs.empty())
            for (float c : {mesh.uvs[i].x, mesh.uvs[i].y}) appendLittleEndian(out, c);
    }
    for (size_t t = 0; t < mesh.triangleCount(); ++t) {
        appendLittleEndian(out, uint8_t(3));
        for (int k = 0; k < 3; ++k) appendLittleEndian(out, mesh.indices[3 * t + size_t(k)]);
    }
    std::ofstream stream(file, std::ios::binary | std::ios::trunc);
    if (!stream.write(out.data(), std::streamsize(out.size())) || !stream.flush())
        throw std::runtime_error(ply::errorText(name, "cannot write the file"));
}

}  // namespace photon
