// The header of a PLY file, as described in Greg Turk, "The PLY Polygon File Format": the
// format line, then elements (a name and a count), each with its properties (a scalar type
// or a list of a count type and an item type), closed by `end_header`. Only the structure
// is read here; the data after it is decoded by ply_mesh.cpp.
#pragma once
#include <cstddef>
#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

namespace photon::ply {

enum class Format { Ascii, BinaryLittleEndian, BinaryBigEndian };

// The eight scalar types of the format description, under either of their names
// (char/int8, uchar/uint8, ..., float/float32, double/float64).
enum class Type : uint8_t { Int8, UInt8, Int16, UInt16, Int32, UInt32, Float32, Float64 };

size_t typeSize(Type type);
bool isIntegerType(Type type);
const char* typeName(Type type);

struct Property {
    std::string name;
    Type type = Type::Float32;  // the scalar's type, or a list's item type
    bool isList = false;
    Type countType = Type::UInt8;  // lists only
};

struct Element {
    std::string name;
    uint64_t count = 0;
    std::vector<Property> properties;
    int line = 0;  // header line of the `element` keyword, for messages

    // The index of the property named `name`, or -1.
    int find(std::string_view propertyName) const;
    bool hasLists() const;
    // Bytes one instance takes in a binary file: exact without lists, the least possible
    // (every list empty) with them.
    size_t binarySize() const;
};

struct Header {
    Format format = Format::Ascii;
    std::vector<Element> elements;
    size_t dataOffset = 0;  // where the data starts: just past the `end_header` line
    int lines = 0;          // lines in the header, `end_header` included (ascii data counts on)
};

// Parses the header at the start of `bytes`. Throws std::runtime_error("PLY: <where>: ...")
// naming the header line of the first problem; `where` is `name` followed by the line.
Header parseHeader(std::string_view bytes, const std::string& name);

// "PLY: " + name + ": " + message (without the name if it is empty): every error says
// which file it is about, even when a caller loses track of it.
std::string errorText(const std::string& name, const std::string& message);

}  // namespace photon::ply
