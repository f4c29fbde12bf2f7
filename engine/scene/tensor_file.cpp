#include "scene/tensor_file.h"
#include <bit>
#include <cstring>
#include <fstream>
#include <limits>
#include <stdexcept>

namespace photon {

namespace {

static_assert(std::endian::native == std::endian::little, "tensor files are little-endian, as is this machine");

constexpr char kSignature[12] = "tensor_file";
// The file may hold more fields than a BRDF needs, but not more than this: a count read from
// a damaged header must not make the reader loop for long.
constexpr uint32_t kMaxFields = 4096;
constexpr uint16_t kMaxRank = 8;

size_t elementSize(TensorFile::Type t) {
    switch (t) {
        case TensorFile::Type::UInt8:
        case TensorFile::Type::Int8: return 1;
        case TensorFile::Type::UInt16:
        case TensorFile::Type::Int16:
        case TensorFile::Type::Float16: return 2;
        case TensorFile::Type::UInt32:
        case TensorFile::Type::Int32:
        case TensorFile::Type::Float32: return 4;
        default: return 8;
    }
}

// Reads the header's fixed-size values one after another, failing past the end.
struct HeaderReader {
    const TensorFile& file;
    std::string_view bytes;
    size_t at = 0;
    template <class T>
    T next(const char* what) {
        if (bytes.size() - at < sizeof(T)) file.fail(std::string("the header ends inside ") + what);
        T v;
        std::memcpy(&v, bytes.data() + at, sizeof(T));
        at += sizeof(T);
        return v;
    }
};

}  // namespace

TensorFile::TensorFile(std::string bytes, std::string name) : bytes_(std::move(bytes)), name_(std::move(name)) {
    const std::string_view all(bytes_);
    if (all.size() < 18 || std::memcmp(all.data(), kSignature, sizeof(kSignature)) != 0)
        fail("not a tensor file (no \"tensor_file\" signature)");
    HeaderReader header{*this, all, sizeof(kSignature)};
    const auto major = header.next<uint8_t>("the version"), minor = header.next<uint8_t>("the version");
    if (major != 1 || minor != 0)
        fail("version " + std::to_string(major) + "." + std::to_string(minor) + " (expected 1.0)");
    const auto count = header.next<uint32_t>("the field count");
    if (count > kMaxFields) fail(std::to_string(count) + " fields (at most " + std::to_string(kMaxFields) + ")");
    for (uint32_t f = 0; f < count; ++f) {
        const auto nameLength = header.next<uint16_t>("a field's name");
        if (all.size() - header.at < nameLength) fail("the header ends inside a field's name");
        std::string key(all.substr(header.at, nameLength));
        header.at += nameLength;
        const auto rank = header.next<uint16_t>("a field's rank");
        const auto type = header.next<uint8_t>("a field's type");
        const auto offset = header.next<uint64_t>("a field's offset");
        if (type < uint8_t(Type::UInt8) || type > uint8_t(Type::Float64))
            fail("field \"" + key + "\" has an unknown element type " + std::to_string(type));
        if (rank > kMaxRank) fail("field \"" + key + "\" has rank " + std::to_string(rank));
        Field field{Type(type), {}, {}};
        // The data's size, checked against the file's as it grows, so no product overflows.
        uint64_t size = elementSize(field.type);
        for (uint16_t d = 0; d < rank; ++d) {
            const auto extent = header.next<uint64_t>("a field's shape");
            if (extent != 0 && size > all.size() / extent) fail("field \"" + key + "\" is larger than the file");
            size *= extent;
            field.shape.push_back(extent);
        }
        if (offset > all.size() || size > all.size() - offset)
            fail("field \"" + key + "\" lies past the end of the file (" + std::to_string(all.size()) + " bytes)");
        field.bytes = all.substr(size_t(offset), size_t(size));
        if (!fields_.emplace(key, std::move(field)).second) fail("field \"" + key + "\" is given twice");
    }
}

TensorFile TensorFile::read(const std::string& path, const std::string& name) {
    std::ifstream in(path, std::ios::binary);
    if (!in) throw std::runtime_error(name + ": cannot open the file");
    in.seekg(0, std::ios::end);
    std::string bytes(size_t(std::max<std::streamoff>(in.tellg(), 0)), '\0');
    in.seekg(0);
    if (!in.read(bytes.data(), std::streamsize(bytes.size()))) throw std::runtime_error(name + ": cannot read the file");
    return TensorFile(std::move(bytes), name);
}

void TensorFile::fail(const std::string& what) const { throw std::runtime_error(name_ + ": " + what); }

const TensorFile::Field& TensorFile::field(const std::string& key, Type type, size_t rank) const {
    auto found = fields_.find(key);
    if (found == fields_.end()) fail("has no field \"" + key + "\"");
    const Field& f = found->second;
    if (f.type != type || f.shape.size() != rank)
        fail("field \"" + key + "\" must have " + std::to_string(rank) + " dimension(s) of " +
             (type == Type::Float32 ? "32-bit floats" : "bytes"));
    return f;
}

std::vector<float> TensorFile::floats(const std::string& key, size_t rank) const {
    const Field& f = field(key, Type::Float32, rank);
    std::vector<float> values(f.bytes.size() / sizeof(float));
    if (!values.empty()) std::memcpy(values.data(), f.bytes.data(), values.size() * sizeof(float));
    return values;
}

std::string tensorFileBytes(const std::vector<TensorFieldData>& fields) {
    auto put = [](std::string& out, const auto& v) { out.append(reinterpret_cast<const char*>(&v), sizeof(v)); };
    std::string header(kSignature, sizeof(kSignature));
    header += char(1);
    header += char(0);
    put(header, uint32_t(fields.size()));
    size_t headerSize = header.size();
    for (const auto& f : fields) headerSize += 2 + f.name.size() + 2 + 1 + 8 + 8 * f.shape.size();
    uint64_t offset = headerSize;
    std::string data;
    for (const auto& f : fields) {
        put(header, uint16_t(f.name.size()));
        header += f.name;
        put(header, uint16_t(f.shape.size()));
        put(header, uint8_t(f.type));
        put(header, offset + data.size());
        for (uint64_t extent : f.shape) put(header, extent);
        data += f.bytes;
    }
    return header + data;
}

}  // namespace photon
