// The "tensor_file" format in which Mitsuba and pbrt-v4 read measured BRDFs (RGL's material
// database, Dupuy & Jakob 2018): a 12-byte signature "tensor_file\0", a version (1, 0), a
// field count, then per field its name, rank, element type, the offset of its data in the
// file and its shape; all little-endian. Only what a field's data need is kept.
#pragma once
#include <cstdint>
#include <map>
#include <string>
#include <string_view>
#include <vector>

namespace photon {

// A file's fields, read from its bytes with every count and offset checked against them.
class TensorFile {
public:
    // The element types, numbered as the format numbers them.
    enum class Type : uint8_t { UInt8 = 1, Int8, UInt16, Int16, UInt32, Int32, UInt64, Int64, Float16, Float32, Float64 };
    struct Field {
        Type type;
        std::vector<uint64_t> shape;
        std::string_view bytes;  // into the file's bytes, which the TensorFile keeps
    };
    // Throws std::runtime_error ("<name>: ...") naming the first problem: the signature or
    // version, a field's type, rank or name, or data that would lie past the file's end.
    TensorFile(std::string bytes, std::string name);
    // The file at `path`, named `name` in errors.
    static TensorFile read(const std::string& path, const std::string& name);

    const std::string& name() const { return name_; }
    // The field `key`, which must have `rank` dimensions of type `type`; throws naming the
    // file and the field otherwise.
    const Field& field(const std::string& key, Type type, size_t rank) const;
    bool has(const std::string& key) const { return fields_.count(key) != 0; }
    // A Float32 field's values, converted from the file's byte order.
    std::vector<float> floats(const std::string& key, size_t rank) const;
    [[noreturn]] void fail(const std::string& what) const;

private:
    std::string bytes_, name_;
    std::map<std::string, Field> fields_;
};

// A file's bytes in the format, for writing tables out (tests write measured BRDFs with it).
struct TensorFieldData {
    std::string name;
    TensorFile::Type type;
    std::vector<uint64_t> shape;
    std::string bytes;  // little-endian elements
};
std::string tensorFileBytes(const std::vector<TensorFieldData>& fields);

}  // namespace photon
