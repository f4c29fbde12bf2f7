// Accessors (glTF 2.0 sec. 3.6): typed views of buffer bytes. tinygltf parses the
// document but leaves the bytes to the reader, so every range is checked here before a
// byte is read: a document may claim more data than its buffers hold.
#include <cmath>
#include <cstring>
#include "import/gltf/gltf_parts.h"

namespace photon::gltf {
namespace {

// More elements than any mesh photon accepts (10M triangles) could need.
constexpr size_t kMaxElements = size_t(64) << 20;

double readComponent(const unsigned char* p, int componentType) {
    auto as = [p]<typename T>(T) {
        T v;
        std::memcpy(&v, p, sizeof v);
        return double(v);
    };
    switch (componentType) {
        case TINYGLTF_COMPONENT_TYPE_BYTE: return as(int8_t());
        case TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE: return as(uint8_t());
        case TINYGLTF_COMPONENT_TYPE_SHORT: return as(int16_t());
        case TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT: return as(uint16_t());
        case TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT: return as(uint32_t());
        default: return as(float());
    }
}

// sec. 3.11, "normalized": integers to [0, 1] (unsigned) or [-1, 1] (signed).
double normalise(double v, int componentType) {
    switch (componentType) {
        case TINYGLTF_COMPONENT_TYPE_BYTE: return std::max(v / 127.0, -1.0);
        case TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE: return v / 255.0;
        case TINYGLTF_COMPONENT_TYPE_SHORT: return std::max(v / 32767.0, -1.0);
        case TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT: return v / 65535.0;
        default: return v;
    }
}

struct ViewBytes {
    const unsigned char* base;  // the view's first byte
    size_t stride;              // between elements
};

// The bytes of buffer view `view` from `offset`: `count` elements of `elementSize` bytes,
// the view's byteStride apart (packed without one), checked against the view and its buffer.
ViewBytes viewBytes(Context& ctx, int view, size_t offset, size_t count, size_t elementSize,
                    const std::string& accessorPointer) {
    const auto& views = ctx.model.bufferViews;
    if (view < 0 || size_t(view) >= views.size())
        ctx.fail(accessorPointer, "names bufferView " + std::to_string(view) + ", which does not exist");
    const tinygltf::BufferView& bv = views[view];
    const std::string viewPointer = pointerTo("bufferViews", view);
    if (bv.buffer < 0 || size_t(bv.buffer) >= ctx.model.buffers.size())
        ctx.fail(viewPointer, "names buffer " + std::to_string(bv.buffer) + ", which does not exist");
    const size_t bufferSize = ctx.model.buffers[bv.buffer].data.size();
    if (bv.byteOffset > bufferSize || bv.byteLength > bufferSize - bv.byteOffset)
        ctx.fail(viewPointer, "bytes [" + std::to_string(bv.byteOffset) + ", " + std::to_string(bv.byteOffset + bv.byteLength) +
                                  ") lie beyond buffer " + std::to_string(bv.buffer) + "'s " + std::to_string(bufferSize) +
                                  " bytes");
    const size_t stride = bv.byteStride != 0 ? bv.byteStride : elementSize;
    const size_t need = count == 0 ? 0 : offset + stride * (count - 1) + elementSize;
    if (offset > bv.byteLength || need > bv.byteLength)
        ctx.fail(accessorPointer, "needs " + std::to_string(need) + " bytes of bufferView " + std::to_string(view) +
                                      ", which has " + std::to_string(bv.byteLength));
    return {ctx.model.buffers[bv.buffer].data.data() + bv.byteOffset, stride};
}

void readElements(const ViewBytes& bytes, size_t offset, int componentSize, int componentType, int components,
                  size_t count, double* out) {
    for (size_t e = 0; e < count; ++e)
        for (int c = 0; c < components; ++c)
            out[e * components + c] =
                readComponent(bytes.base + offset + e * bytes.stride + size_t(c) * componentSize, componentType);
}

}  // namespace

AccessorValues readAccessor(Context& ctx, int index, const std::string& referencedFrom) {
    if (index < 0 || size_t(index) >= ctx.model.accessors.size())
        ctx.fail(referencedFrom, "names accessor " + std::to_string(index) + ", which does not exist");
    const tinygltf::Accessor& a = ctx.model.accessors[index];
    const std::string pointer = pointerTo("accessors", index);
    AccessorValues r;
    r.components = tinygltf::GetNumComponentsInType(uint32_t(a.type));
    const int componentSize = tinygltf::GetComponentSizeInBytes(uint32_t(a.componentType));
    if (r.components <= 0 || componentSize <= 0) ctx.fail(pointer, "unknown type or componentType");
    if (a.count > kMaxElements / size_t(r.components))
        ctx.fail(pointer, "count " + std::to_string(a.count) + " is more than photon reads");
    r.count = a.count;
    r.values.assign(r.count * r.components, 0.0);  // sec. 3.6.2.3: without a view, zeros
    const size_t elementSize = size_t(componentSize) * r.components;
    if (a.bufferView >= 0)
        readElements(viewBytes(ctx, a.bufferView, a.byteOffset, r.count, elementSize, pointer), a.byteOffset,
                     componentSize, a.componentType, r.components, r.count, r.values.data());
    if (a.sparse.isSparse) {
        // sec. 3.6.2.3: `count` elements replaced, at the indices given, by the values given.
        const size_t n = size_t(std::max(a.sparse.count, 0));
        if (n > r.count) ctx.fail(pointer + "/sparse/count", "is more than the accessor's count");
        const int indexType = a.sparse.indices.componentType;
        const int indexSize = tinygltf::GetComponentSizeInBytes(uint32_t(indexType));
        if (indexSize <= 0 || indexType == TINYGLTF_COMPONENT_TYPE_FLOAT)
            ctx.fail(pointer + "/sparse/indices/componentType", "must be an unsigned integer type");
        std::vector<double> at(n), values(n * r.components);
        const size_t indexOffset = size_t(std::max(a.sparse.indices.byteOffset, 0));
        const size_t valueOffset = size_t(std::max(a.sparse.values.byteOffset, 0));
        readElements(viewBytes(ctx, a.sparse.indices.bufferView, indexOffset, n, indexSize, pointer + "/sparse/indices"),
                     indexOffset, indexSize, indexType, 1, n, at.data());
        readElements(viewBytes(ctx, a.sparse.values.bufferView, valueOffset, n, elementSize, pointer + "/sparse/values"),
                     valueOffset, componentSize, a.componentType, r.components, n, values.data());
        for (size_t i = 0; i < n; ++i) {
            if (at[i] >= double(r.count))
                ctx.fail(pointer + "/sparse/indices", "index " + std::to_string(size_t(at[i])) + " is beyond the accessor's " +
                                                          std::to_string(r.count) + " elements");
            for (int c = 0; c < r.components; ++c) r.values[size_t(at[i]) * r.components + c] = values[i * r.components + c];
        }
    }
    if (a.normalized)
        for (double& v : r.values) v = normalise(v, a.componentType);
    return r;
}

}  // namespace photon::gltf
