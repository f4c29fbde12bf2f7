// Reading PLY triangle meshes. The header (ply_header.cpp) says which elements follow, in
// which order, with which properties; the data (ply_data.h) is then read element by element
// in that order (Greg Turk, "The PLY Polygon File Format": "the elements ... in the order
// they were listed in the header"). Only `vertex` and `face` are kept; every other element
// and property is read past. A count is checked against the bytes that remain before
// anything is reserved for it, so a file that lies about its size fails at once.
#include "scene/ply_mesh.h"
#include <algorithm>
#include <array>
#include <cfloat>
#include <cmath>
#include <cstring>
#include <fstream>
#include <limits>
#include <stdexcept>
#include "scene/mesh_loader.h"
#include "scene/ply_data.h"
#include "scene/ply_header.h"

namespace photon {

namespace {

using namespace ply;

// The vertex properties the mesh uses, in the order values[] holds them.
enum Slot { X, Y, Z, NX, NY, NZ, U, V, kSlots };

// Texture coordinate names in use (pbrt-v4 and Blender write u v; others s t or texture_*).
constexpr std::array<std::array<const char*, 2>, 4> kUvNames{
    {{"u", "v"}, {"s", "t"}, {"texture_u", "texture_v"}, {"texture_s", "texture_t"}}};

// A double as a float; values beyond float's range become infinities (which positions
// refuse) rather than an undefined conversion.
float toFloat(double v) {
    if (std::isfinite(v) && std::abs(v) > double(FLT_MAX)) return v > 0 ? INFINITY : -INFINITY;
    return float(v);
}

// "1 byte", "12 bytes".
std::string quantity(uint64_t n, const std::string& unit) {
    return std::to_string(n) + " " + unit + (n == 1 ? "" : "s");
}

std::string plural(const Element& e) {
    if (e.name == "vertex") return "vertices";
    if (e.name == "face") return "faces";
    return "'" + e.name + "' elements";
}

class MeshReader {
public:
    MeshReader(std::string_view bytes, const std::string& name)
        : bytes_(bytes), name_(name), header_(parseHeader(bytes, name)) {}

    TriangleMesh read() {
        findRoles();
        if (header_.format == Format::Ascii) {
            AsciiSource source(bytes_, header_.dataOffset, header_.lines + 1);
            for (const Element& e : header_.elements) readElement(source, e);
        } else {
            BinarySource source(bytes_, header_.dataOffset, header_.format == Format::BinaryBigEndian);
            for (const Element& e : header_.elements) readElement(source, e);
        }
        return std::move(mesh_);
    }

private:
    [[noreturn]] void fail(const std::string& message) const {
        throw std::runtime_error(errorText(name_, message));
    }
    [[noreturn]] void failIn(const Element& e, const std::string& message) const {
        fail("element " + e.name + " (header line " + std::to_string(e.line) + ") " + message);
    }

    // Finds the vertex and face elements and the properties the mesh is made of.
    void findRoles() {
        for (const Element& e : header_.elements) {
            if (e.name == "vertex") vertex_ = &e;
            if (e.name == "face") face_ = &e;
        }
        if (!vertex_) fail("the header declares no vertex element");
        if (!face_) fail("the header declares no face element");
        // Indices are 32-bit: more vertices could not all be named by a face.
        if (vertex_->count > std::numeric_limits<uint32_t>::max())
            failIn(*vertex_, "declares " + std::to_string(vertex_->count) + " vertices, more than 32-bit indices can name");
        slotProperty_.fill(-1);
        const std::array<const char*, 3> position{"x", "y", "z"}, normal{"nx", "ny", "nz"};
        for (int i = 0; i < 3; ++i) {
            slotProperty_[X + i] = vertex_->find(position[i]);
            if (slotProperty_[X + i] < 0) failIn(*vertex_, std::string("has no property ") + position[i]);
        }
        if (vertex_->find("nx") >= 0 && vertex_->find("ny") >= 0 && vertex_->find("nz") >= 0)
            for (int i = 0; i < 3; ++i) slotProperty_[NX + i] = vertex_->find(normal[i]);
        for (const auto& [u, v] : kUvNames)
            if (vertex_->find(u) >= 0 && vertex_->find(v) >= 0) {
                slotProperty_[U] = vertex_->find(u);
                slotProperty_[V] = vertex_->find(v);
                break;
            }
        propertySlot_.assign(vertex_->properties.size(), -1);
        for (int s = 0; s < kSlots; ++s) {
            if (slotProperty_[s] < 0) continue;
            const Property& p = vertex_->properties[size_t(slotProperty_[s])];
            if (p.isList) failIn(*vertex_, "has a list " + p.name + " where a number belongs");
            propertySlot_[size_t(slotProperty_[s])] = s;
        }
        hasNormals_ = slotProperty_[NX] >= 0;
        hasUvs_ = slotProperty_[U] >= 0;

        indexProperty_ = face_->find("vertex_indices");
        if (indexProperty_ < 0) indexProperty_ = face_->find("vertex_index");
        if (indexProperty_ < 0) failIn(*face_, "has no vertex_indices (or vertex_index) list");
        const Property& indices = face_->properties[size_t(indexProperty_)];
        if (!indices.isList) failIn(*face_, "has a single number " + indices.name + " where a list belongs");
        if (!isIntegerType(indices.type))
            failIn(*face_, "has " + indices.name + " of " + typeName(indices.type) + ", not of an integer type");
    }

    // Refuses a count the remaining bytes cannot hold, before anything is reserved for it.
    void checkCount(const AsciiSource& source, const Element& e) const {
        // Every property is at least one number (a list its count), each a character and a
        // separator.
        const uint64_t numbers = e.properties.size();
        if (numbers == 0 || e.count <= (source.remaining() / 2 + 1) / numbers) return;
        fail("the header declares " + std::to_string(e.count) + " " + plural(e) + " of at least " +
             quantity(numbers, "number") + ", but only " + std::to_string(source.remaining()) +
             " bytes of text are left for them at " + source.where());
    }
    void checkCount(const BinarySource& source, const Element& e) const {
        const size_t size = e.binarySize();
        if (size == 0 || e.count <= source.remaining() / size) return;
        std::string message = "the header declares " + std::to_string(e.count) + " " + plural(e) + " of " +
                              (e.hasLists() ? "at least " : "") + quantity(size, "byte") + ", but only " +
                              std::to_string(source.remaining()) + " bytes ";
        if (source.offset() == header_.dataOffset) fail(message + "follow it");
        fail(message + "are left for them at byte offset " + std::to_string(source.offset()));
    }

    // How many instances of `e` the remaining bytes could hold, had every list `listItems`
    // items: what may be reserved.
    size_t affordable(const AsciiSource& source, const Element& e, size_t listItems) const {
        return std::min<uint64_t>(e.count, source.remaining() / (2 * (e.properties.size() + listItems)) + 1);
    }
    size_t affordable(const BinarySource& source, const Element& e, size_t listItems) const {
        size_t size = e.binarySize() + listItems * typeSize(face_->properties[size_t(indexProperty_)].type);
        return std::min<uint64_t>(e.count, source.remaining() / std::max<size_t>(size, 1));
    }

    template <typename Source>
    void readElement(Source& source, const Element& e) {
        checkCount(source, e);
        if (&e == vertex_) {
            mesh_.positions.reserve(e.count + 1);  // room for Embree's 16-byte loads (Scene::newMesh)
            if (hasNormals_) mesh_.normals.reserve(e.count);
            if (hasUvs_) mesh_.uvs.reserve(e.count);
        } else if (&e == face_) {
            mesh_.indices.reserve(3 * std::min(affordable(source, e, 3), kMaxMeshTriangles));
        }
        if (e.properties.empty()) return;  // nothing to read, however many there are
        uint64_t i = 0;
        size_t k = 0;
        try {
            if constexpr (std::is_same_v<Source, BinarySource>) {
                if (!e.hasLists() && &e != face_) return readFixedSize(source, e);
            }
            for (; i < e.count; ++i) {
                std::array<double, kSlots> values{};
                for (k = 0; k < e.properties.size(); ++k) {
                    const Property& p = e.properties[k];
                    if (!p.isList) {
                        int slot = &e == vertex_ ? propertySlot_[k] : -1;
                        if (slot >= 0) values[size_t(slot)] = source.scalar(p.type);
                        else source.skip(p.type, 1);
                        continue;
                    }
                    int64_t n = source.integer(p.countType);
                    if (n < 0 || !source.canHold(uint64_t(n), p.type))
                        fail(std::string(e.name) + " " + std::to_string(i) + " of " + std::to_string(e.count) +
                             ": the list " + p.name + " claims " + std::to_string(n) + " items, but only " +
                             std::to_string(source.remaining()) + " bytes are left at " + source.where());
                    if (&e == face_ && int(k) == indexProperty_) readPolygon(source, p, uint64_t(n), i);
                    else source.skip(p.type, uint64_t(n));
                }
                if (&e == vertex_) addVertex(values, i);
            }
        } catch (const DataProblem& problem) {
            const std::string element = e.name + " " + std::to_string(i) + " of " + std::to_string(e.count);
            const std::string& property = e.properties[k].name;
            if (problem.endOfFile) fail("the file ends in " + element + " (property " + property + ", " + problem.where + ")");
            fail(problem.where + ": '" + problem.token + "' is not a number of type " + typeName(problem.type) + " (" +
                 element + ", property " + property + ")");
        }
    }

    // Binary elements without lists: `checkCount` made sure all of them are there, so they
    // are read (vertices) or passed (anything else) without a check per value.
    void readFixedSize(BinarySource& source, const Element& e) {
        const size_t stride = e.binarySize();
        const uint8_t* data = source.advance(size_t(e.count) * stride);
        if (&e != vertex_) return;
        std::array<size_t, kSlots> offset{};
        std::array<Type, kSlots> type{};
        bool allFloat = !source.swapped();
        for (int s = 0; s < kSlots; ++s) {
            if (slotProperty_[s] < 0) continue;
            for (int k = 0; k < slotProperty_[s]; ++k) offset[s] += typeSize(e.properties[size_t(k)].type);
            type[s] = e.properties[size_t(slotProperty_[s])].type;
            allFloat = allFloat && type[s] == Type::Float32;
        }
        std::array<double, kSlots> values{};
        for (uint64_t i = 0; i < e.count; ++i, data += stride) {
            // The common layout (pbrt-v4, Blender: all float, host order) without a switch per value.
            for (int s = 0; s < kSlots; ++s) {
                if (slotProperty_[s] < 0) continue;
                values[s] = allFloat ? loadValue<float>(data + offset[s], false)
                                     : loadNumber(data + offset[s], type[s], source.swapped());
            }
            addVertex(values, i);
        }
    }

    void addVertex(const std::array<double, kSlots>& v, uint64_t i) {
        Vec3 position{toFloat(v[X]), toFloat(v[Y]), toFloat(v[Z])};
        if (!isFinite(position))
            fail("vertex " + std::to_string(i) + " of " + std::to_string(vertex_->count) +
                 " has a position that is not a finite number");
        mesh_.positions.push_back(position);
        if (hasNormals_) mesh_.normals.push_back({toFloat(v[NX]), toFloat(v[NY]), toFloat(v[NZ])});
        if (hasUvs_) mesh_.uvs.push_back({toFloat(v[U]), toFloat(v[V])});
    }

    // One face's vertex list, `n` items: a polygon becomes a fan of triangles about its first
    // vertex, (a, b, c, d) -> (a, b, c), (a, c, d); fewer than three vertices is no surface.
    template <typename Source>
    void readPolygon(Source& source, const Property& p, uint64_t n, uint64_t face) {
        if (n < 3) return source.skip(p.type, n);
        const size_t triangles = mesh_.indices.size() / 3;
        if (n - 2 > kMaxMeshTriangles - triangles)
            fail("face " + std::to_string(face) + " of " + std::to_string(face_->count) +
                 " takes the mesh past the limit of " + std::to_string(kMaxMeshTriangles) + " triangles");
        if constexpr (std::is_same_v<Source, BinarySource>) {
            // Triangles of 32-bit indices in host order, what nearly every binary file holds:
            // one copy of the three instead of a decode each (the caller checked they are there).
            if (n == 3 && !source.swapped() && (p.type == Type::Int32 || p.type == Type::UInt32)) {
                uint32_t corners[3];
                std::memcpy(corners, source.advance(sizeof corners), sizeof corners);
                for (uint32_t c : corners)
                    if (c >= vertex_->count) failIndex(face, p.type == Type::Int32 ? int64_t(int32_t(c)) : int64_t(c));
                mesh_.indices.insert(mesh_.indices.end(), corners, corners + 3);
                return;
            }
        }
        const uint32_t first = vertexIndex(source, p, face);
        uint32_t previous = vertexIndex(source, p, face);
        for (uint64_t k = 2; k < n; ++k) {
            const uint32_t next = vertexIndex(source, p, face);
            mesh_.indices.insert(mesh_.indices.end(), {first, previous, next});
            previous = next;
        }
    }

    [[noreturn]] void failIndex(uint64_t face, int64_t index) const {
        fail("face " + std::to_string(face) + " refers to vertex " + std::to_string(index) + ", but there are " +
             std::to_string(vertex_->count) + " vertices");
    }

    template <typename Source>
    uint32_t vertexIndex(Source& source, const Property& p, uint64_t face) {
        const int64_t index = source.integer(p.type);
        if (index < 0 || uint64_t(index) >= vertex_->count) failIndex(face, index);
        return uint32_t(index);
    }

    std::string_view bytes_;
    const std::string& name_;
    Header header_;
    const Element* vertex_ = nullptr;
    const Element* face_ = nullptr;
    std::array<int, kSlots> slotProperty_{};  // vertex property index of each slot, or -1
    std::vector<int> propertySlot_;           // slot of each vertex property, or -1
    int indexProperty_ = -1;                  // the face's vertex_indices list
    bool hasNormals_ = false, hasUvs_ = false;
    TriangleMesh mesh_;
};

}  // namespace

TriangleMesh readPlyMesh(std::string_view bytes, const std::string& name) { return MeshReader(bytes, name).read(); }

TriangleMesh readPlyMesh(const std::filesystem::path& file) {
    std::ifstream in(file, std::ios::binary);
    if (!in) throw std::runtime_error(errorText(file.string(), "cannot open the file"));
    in.seekg(0, std::ios::end);
    std::string bytes(size_t(std::max<std::streamoff>(in.tellg(), 0)), '\0');
    in.seekg(0);
    if (!in.read(bytes.data(), std::streamsize(bytes.size())))
        throw std::runtime_error(errorText(file.string(), "cannot read the file"));
    return readPlyMesh(std::string_view(bytes), file.string());
}

}  // namespace photon
