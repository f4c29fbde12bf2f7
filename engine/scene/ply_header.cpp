#include "scene/ply_header.h"
#include <array>
#include <charconv>
#include <stdexcept>
#include <utility>

namespace photon::ply {

namespace {

struct TypeName {
    std::string_view name;
    Type type;
};
// The format description's names and the sized names later writers use (both are common:
// pbrt-v4's files say "float", numpy-based exporters "float32").
constexpr std::array<TypeName, 16> kTypeNames{{
    {"char", Type::Int8},     {"uchar", Type::UInt8},   {"short", Type::Int16},     {"ushort", Type::UInt16},
    {"int", Type::Int32},     {"uint", Type::UInt32},   {"float", Type::Float32},   {"double", Type::Float64},
    {"int8", Type::Int8},     {"uint8", Type::UInt8},   {"int16", Type::Int16},     {"uint16", Type::UInt16},
    {"int32", Type::Int32},   {"uint32", Type::UInt32}, {"float32", Type::Float32}, {"float64", Type::Float64},
}};

// Splits a header line at spaces and tabs.
std::vector<std::string_view> words(std::string_view line) {
    std::vector<std::string_view> out;
    size_t i = 0;
    while (i < line.size()) {
        while (i < line.size() && (line[i] == ' ' || line[i] == '\t')) ++i;
        size_t start = i;
        while (i < line.size() && line[i] != ' ' && line[i] != '\t') ++i;
        if (i > start) out.push_back(line.substr(start, i - start));
    }
    return out;
}

// Reads the header line by line, keeping the line number for messages.
class HeaderParser {
public:
    HeaderParser(std::string_view bytes, const std::string& name) : bytes_(bytes), name_(name) {}

    Header parse() {
        std::string_view first;
        if (!nextLine(first) || first != "ply")
            throw std::runtime_error(errorText(name_, "the file does not start with a 'ply' line"));
        bool haveFormat = false;
        for (std::string_view line; nextLine(line);) {
            std::vector<std::string_view> w = words(line);
            if (w.empty() || w[0] == "comment" || w[0] == "obj_info") continue;
            if (w[0] == "end_header" && w.size() == 1) {
                if (!haveFormat) fail("the header has no 'format' line");
                header_.dataOffset = pos_;
                header_.lines = lineNumber_;
                return std::move(header_);
            }
            if (w[0] == "format") {
                readFormat(w);
                haveFormat = true;
            } else if (w[0] == "element") {
                if (!haveFormat) fail("'element' before the 'format' line");
                readElement(w);
            } else if (w[0] == "property") {
                readProperty(w);
            } else {
                fail("unknown keyword '" + std::string(w[0]) + "'");
            }
        }
        throw std::runtime_error(errorText(name_, "the header has no 'end_header' line"));
    }

private:
    // The next line without its line ending ("\n" or "\r\n"); false at the end of the bytes.
    bool nextLine(std::string_view& line) {
        if (pos_ >= bytes_.size()) return false;
        size_t end = bytes_.find('\n', pos_);
        size_t next = end == std::string_view::npos ? bytes_.size() : end + 1;
        line = bytes_.substr(pos_, (end == std::string_view::npos ? bytes_.size() : end) - pos_);
        while (!line.empty() && (line.back() == '\r' || line.back() == ' ' || line.back() == '\t'))
            line.remove_suffix(1);
        pos_ = next;
        ++lineNumber_;
        return true;
    }

    [[noreturn]] void fail(const std::string& message) const {
        throw std::runtime_error(errorText(name_, "header line " + std::to_string(lineNumber_) + ": " + message));
    }

    void readFormat(const std::vector<std::string_view>& w) {
        if (w.size() != 3) fail("expected 'format ascii|binary_little_endian|binary_big_endian 1.0'");
        if (w[1] == "ascii") header_.format = Format::Ascii;
        else if (w[1] == "binary_little_endian") header_.format = Format::BinaryLittleEndian;
        else if (w[1] == "binary_big_endian") header_.format = Format::BinaryBigEndian;
        else
            fail("unknown format '" + std::string(w[1]) +
                 "' (expected ascii, binary_little_endian or binary_big_endian)");
        // 1.0 is the only version the format description defines.
        if (w[2] != "1.0") fail("unsupported format version '" + std::string(w[2]) + "' (expected 1.0)");
    }

    void readElement(const std::vector<std::string_view>& w) {
        if (w.size() != 3) fail("expected 'element NAME COUNT'");
        Element e;
        e.name = w[1];
        e.line = lineNumber_;
        auto [end, ec] = std::from_chars(w[2].data(), w[2].data() + w[2].size(), e.count);
        if (ec != std::errc() || end != w[2].data() + w[2].size())
            fail("the count of element " + e.name + " is not a whole number: '" + std::string(w[2]) + "'");
        for (const Element& other : header_.elements)
            if (other.name == e.name) fail("a second element named " + e.name);
        header_.elements.push_back(std::move(e));
    }

    Type type(std::string_view word) const {
        for (const TypeName& t : kTypeNames)
            if (t.name == word) return t.type;
        fail("unknown property type '" + std::string(word) + "'");
    }

    void readProperty(const std::vector<std::string_view>& w) {
        if (header_.elements.empty()) fail("'property' before any 'element'");
        Element& element = header_.elements.back();
        Property p;
        if (w.size() == 3 && w[1] != "list") {
            p.type = type(w[1]);
            p.name = w[2];
        } else if (w.size() == 5 && w[1] == "list") {
            p.isList = true;
            p.countType = type(w[2]);
            p.type = type(w[3]);
            p.name = w[4];
            if (!isIntegerType(p.countType))
                fail("the count type of list " + p.name + " must be an integer type, not " + std::string(w[2]));
        } else {
            fail("expected 'property TYPE NAME' or 'property list COUNTTYPE ITEMTYPE NAME'");
        }
        if (element.find(p.name) >= 0) fail("element " + element.name + " has two properties named " + p.name);
        element.properties.push_back(std::move(p));
    }

    std::string_view bytes_;
    const std::string& name_;
    size_t pos_ = 0;
    int lineNumber_ = 0;
    Header header_;
};

}  // namespace

size_t typeSize(Type type) {
    switch (type) {
    case Type::Int8:
    case Type::UInt8: return 1;
    case Type::Int16:
    case Type::UInt16: return 2;
    case Type::Int32:
    case Type::UInt32:
    case Type::Float32: return 4;
    case Type::Float64: return 8;
    }
    return 0;
}

bool isIntegerType(Type type) { return type != Type::Float32 && type != Type::Float64; }

const char* typeName(Type type) {
    for (const TypeName& t : kTypeNames)
        if (t.type == type) return t.name.data();  // the format description's name comes first
    return "?";
}

int Element::find(std::string_view propertyName) const {
    for (size_t i = 0; i < properties.size(); ++i)
        if (properties[i].name == propertyName) return int(i);
    return -1;
}

bool Element::hasLists() const {
    for (const Property& p : properties)
        if (p.isList) return true;
    return false;
}

size_t Element::binarySize() const {
    size_t size = 0;
    for (const Property& p : properties) size += typeSize(p.isList ? p.countType : p.type);
    return size;
}

Header parseHeader(std::string_view bytes, const std::string& name) { return HeaderParser(bytes, name).parse(); }

std::string errorText(const std::string& name, const std::string& message) {
    return name.empty() ? "PLY: " + message : "PLY: " + name + ": " + message;
}

}  // namespace photon::ply
