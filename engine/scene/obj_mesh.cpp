#include "scene/obj_mesh.h"
#include <algorithm>
#include <cstdint>
#include <fstream>
#include <istream>
#include <stdexcept>
#include <string>
#include <tiny_obj_loader.h>
#include "scene/mesh_loader.h"

namespace photon {

namespace {

// A file buffer that knows the line of the last character read: the newlines of the chunks
// already consumed, plus those before the read position in the current one. Counted only
// when an error needs the line, so reading costs what std::filebuf costs.
class LineCountingFileBuf : public std::filebuf {
public:
    size_t lineOfLastRead() const {
        char* end = gptr() > eback() ? gptr() - 1 : gptr();  // the line's own newline excluded
        return linesBefore_ + size_t(std::count(eback(), end, '\n')) + 1;
    }

protected:
    int_type underflow() override {
        linesBefore_ += size_t(std::count(eback(), egptr(), '\n'));
        return std::filebuf::underflow();
    }

private:
    size_t linesBefore_ = 0;
};

// The OBJ file as it streams by, and the mesh it becomes. A corner names a position, and
// optionally a uv and a normal, each by its own index; the renderer needs one index per
// corner. The first triple seen on a position keeps that position's index (a mesh whose
// corners always pair a position with the same uv and normal, as most exporters write it,
// needs nothing more); another triple on it becomes an extra vertex, appended after the
// file's positions when the file has been read.
class ObjReader {
public:
    ObjReader(std::string name, const LineCountingFileBuf& buffer) : name_(std::move(name)), buffer_(buffer) {}

    static void onVertex(void* self, tinyobj::real_t x, tinyobj::real_t y, tinyobj::real_t z, tinyobj::real_t) {
        auto& r = *static_cast<ObjReader*>(self);
        r.positions_.push_back({x, y, z});
        r.firstUse_.push_back({});
    }
    static void onNormal(void* self, tinyobj::real_t x, tinyobj::real_t y, tinyobj::real_t z) {
        static_cast<ObjReader*>(self)->normals_.push_back({x, y, z});
    }
    static void onUv(void* self, tinyobj::real_t u, tinyobj::real_t v, tinyobj::real_t) {
        static_cast<ObjReader*>(self)->uvs_.push_back({u, v});
    }
    static void onFace(void* self, tinyobj::index_t* corners, int count) {
        static_cast<ObjReader*>(self)->addFace(corners, count);
    }

    TriangleMesh finish();

private:
    // A corner's uv and normal indices (kAbsent: none); kUnused: no corner has used the
    // position yet.
    struct Attributes {
        static constexpr int32_t kAbsent = -1, kUnused = -2;
        int32_t uv = kUnused, normal = kUnused;
        bool operator==(const Attributes&) const = default;
    };
    struct ExtraVertex {
        uint32_t position;
        Attributes attributes;
        uint32_t next;  // the next extra vertex on the same position, or kNone
    };
    static constexpr uint32_t kNone = ~0u;
    // An index into extras_ in the corner indices until finish() places the extras.
    static constexpr uint32_t kExtraBit = 1u << 31;

    [[noreturn]] void fail(const std::string& what) const {
        throw std::runtime_error("OBJ: " + name_ + ": line " + std::to_string(buffer_.lineOfLastRead()) + ": " + what);
    }
    // An OBJ index (1-based, or negative: counted back from the last defined) as 0-based;
    // kAbsent for 0 (the corner leaves it out).
    int32_t resolve(int index, size_t defined, const char* what) const {
        if (index == 0) return Attributes::kAbsent;
        const int64_t i = index > 0 ? int64_t(index) - 1 : int64_t(defined) + index;
        if (i < 0 || i >= int64_t(defined))
            fail("a face refers to " + std::string(what) + " " + std::to_string(index) + ", but " +
                 std::to_string(defined) + " are defined before it");
        return int32_t(i);
    }
    uint32_t vertexOf(const tinyobj::index_t& corner) {
        const int32_t position = resolve(corner.vertex_index, positions_.size(), "vertex");
        if (position == Attributes::kAbsent) fail("a face corner has no vertex index");
        const Attributes a{resolve(corner.texcoord_index, uvs_.size(), "texture coordinate"),
                           resolve(corner.normal_index, normals_.size(), "normal")};
        everyCornerHasNormal_ = everyCornerHasNormal_ && a.normal != Attributes::kAbsent;
        anyCornerHasUv_ = anyCornerHasUv_ || a.uv != Attributes::kAbsent;
        Attributes& first = firstUse_[size_t(position)];
        if (first.uv == Attributes::kUnused) first = a;
        if (first == a) return uint32_t(position);
        if (firstExtra_.size() < positions_.size()) firstExtra_.resize(positions_.size(), kNone);
        uint32_t& head = firstExtra_[size_t(position)];
        for (uint32_t e = head; e != kNone; e = extras_[e].next)
            if (extras_[e].attributes == a) return e | kExtraBit;
        if (extras_.size() >= kExtraBit - 1) fail("too many distinct vertices");
        extras_.push_back({uint32_t(position), a, head});
        head = uint32_t(extras_.size() - 1);
        return head | kExtraBit;
    }
    void addFace(const tinyobj::index_t* corners, int count) {
        if (count < 3) return;  // a degenerate face: nothing to intersect
        if (indices_.size() / 3 + size_t(count - 2) > kMaxMeshTriangles)
            fail("the mesh has more than the limit of " + std::to_string(kMaxMeshTriangles) + " triangles");
        // A fan around the first corner, as PLY polygons are triangulated (ply_mesh.h).
        const uint32_t first = vertexOf(corners[0]);
        uint32_t previous = vertexOf(corners[1]);
        for (int k = 2; k < count; ++k) {
            const uint32_t next = vertexOf(corners[k]);
            indices_.insert(indices_.end(), {first, previous, next});
            previous = next;
        }
    }

    std::string name_;
    const LineCountingFileBuf& buffer_;
    std::vector<Vec3> positions_, normals_;
    std::vector<Vec2> uvs_;
    std::vector<Attributes> firstUse_;  // by position
    std::vector<uint32_t> firstExtra_;  // by position, once some position has an extra vertex
    std::vector<ExtraVertex> extras_;
    std::vector<uint32_t> indices_;
    bool everyCornerHasNormal_ = true, anyCornerHasUv_ = false;
};

TriangleMesh ObjReader::finish() {
    const size_t fileVertices = positions_.size(), total = fileVertices + extras_.size();
    TriangleMesh mesh;
    // Exactly the vertices, and one more element's room: Embree reads a vertex with a
    // 16-byte load (Scene::newMesh). The arrays grown line by line hold up to twice that.
    mesh.positions.reserve(total + 1);
    mesh.positions.assign(positions_.begin(), positions_.end());
    for (const ExtraVertex& e : extras_) mesh.positions.push_back(positions_[e.position]);
    positions_ = decltype(positions_)();  // frees its storage (= {} would only clear it)
    for (uint32_t& i : indices_)
        if (i & kExtraBit) i = uint32_t(fileVertices + (i & ~kExtraBit));
    mesh.indices = std::move(indices_);
    mesh.indices.shrink_to_fit();
    // A vertex's uv or normal: that of the corners that use it. A position no corner uses
    // gets a placeholder (no triangle reads it).
    auto attributeOf = [&](size_t vertex) {
        return vertex < fileVertices ? firstUse_[vertex] : extras_[vertex - fileVertices].attributes;
    };
    if (everyCornerHasNormal_ && !mesh.indices.empty()) {
        mesh.normals.resize(total);
        for (size_t v = 0; v < total; ++v) {
            const int32_t n = attributeOf(v).normal;
            mesh.normals[v] = n >= 0 ? normals_[size_t(n)] : Vec3(0, 0, 1);
        }
    }
    normals_ = decltype(normals_)();
    if (anyCornerHasUv_) {
        mesh.uvs.resize(total);
        for (size_t v = 0; v < total; ++v) {
            const int32_t t = attributeOf(v).uv;
            mesh.uvs[v] = t >= 0 ? uvs_[size_t(t)] : Vec2{};
        }
    }
    return mesh;
}

}  // namespace

TriangleMesh readObjMesh(const std::filesystem::path& file) {
    const std::string name = file.filename().string();
    LineCountingFileBuf buffer;
    if (!buffer.open(file, std::ios::in | std::ios::binary)) throw std::runtime_error("OBJ: " + name + ": cannot open the file");
    std::istream in(&buffer);
    ObjReader reader(name, buffer);
    tinyobj::callback_t callbacks;
    callbacks.vertex_cb = ObjReader::onVertex;
    callbacks.normal_cb = ObjReader::onNormal;
    callbacks.texcoord_cb = ObjReader::onUv;
    callbacks.index_cb = ObjReader::onFace;
    std::string error;
    // No material reader: `mtllib` lines open nothing.
    if (!tinyobj::LoadObjWithCallback(in, callbacks, &reader, nullptr, nullptr, &error))
        throw std::runtime_error("OBJ: " + name + ": " + error);
    if (in.bad()) throw std::runtime_error("OBJ: " + name + ": the file could not be read");
    return reader.finish();
}

}  // namespace photon
