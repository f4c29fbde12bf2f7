// The two ways a PLY file's data is stored after its header (Greg Turk, "The PLY Polygon File
// Format"): ascii, numbers separated by white space (one element a line by convention, but
// only the order counts), and binary, the values packed back to back in the header's order
// with no padding, in little- or big-endian byte order. Both give the element loop in
// ply_mesh.cpp the same calls; neither trusts a count it has not checked against the bytes
// that remain.
#pragma once
#include <bit>
#include <charconv>
#include <cstdint>
#include <cstring>
#include <limits>
#include <string>
#include <string_view>
#include "scene/ply_header.h"

namespace photon::ply {

// What went wrong while reading a value; the element loop adds which element and property.
struct DataProblem {
    bool endOfFile = false;  // otherwise a token that is not a number of the type
    std::string token;
    std::string where;  // "line 14" or "byte offset 1234"
    Type type = Type::Float32;  // the type the token should have been
};

// The value range of an integer type, to refuse ascii numbers that do not fit it.
inline bool fitsType(int64_t v, Type type) {
    switch (type) {
    case Type::Int8: return v >= INT8_MIN && v <= INT8_MAX;
    case Type::UInt8: return v >= 0 && v <= UINT8_MAX;
    case Type::Int16: return v >= INT16_MIN && v <= INT16_MAX;
    case Type::UInt16: return v >= 0 && v <= UINT16_MAX;
    case Type::Int32: return v >= INT32_MIN && v <= INT32_MAX;
    case Type::UInt32: return v >= 0 && v <= UINT32_MAX;
    default: return true;
    }
}

class AsciiSource {
public:
    AsciiSource(std::string_view bytes, size_t start, int firstLine)
        : bytes_(bytes), pos_(start), line_(firstLine), tokenLine_(firstLine) {}

    size_t remaining() const { return bytes_.size() - pos_; }
    // Whether `n` more numbers could follow: each takes a character and a separator.
    bool canHold(uint64_t n, Type) const { return n <= remaining() / 2 + 1; }
    std::string where() const { return "line " + std::to_string(line_); }

    double scalar(Type type) {
        if (isIntegerType(type)) return double(integer(type));
        std::string_view t = token();
        double v = 0;
        auto [end, ec] = std::from_chars(t.data(), t.data() + t.size(), v);
        // Out of range (1e999) is an error from from_chars; the caller refuses what is not finite.
        if (end != t.data() + t.size() || (ec != std::errc() && ec != std::errc::result_out_of_range))
            throw DataProblem{false, std::string(t), where(), type};
        return v;
    }
    int64_t integer(Type type) {
        std::string_view t = token();
        int64_t v = 0;
        auto [end, ec] = std::from_chars(t.data(), t.data() + t.size(), v);
        if (ec != std::errc() || end != t.data() + t.size() || !fitsType(v, type))
            throw DataProblem{false, std::string(t), where(), type};
        return v;
    }
    // Skipped values are still checked to be numbers: a file with text where a number
    // belongs is broken, whichever property it is.
    void skip(Type type, uint64_t n) {
        for (uint64_t i = 0; i < n; ++i) scalar(type);
    }

private:
    std::string_view token() {
        while (pos_ < bytes_.size() && isSpace(bytes_[pos_])) {
            if (bytes_[pos_] == '\n') ++line_;
            ++pos_;
        }
        // At the end, the line of the last number read: the one that is short.
        if (pos_ == bytes_.size()) throw DataProblem{true, {}, "line " + std::to_string(tokenLine_)};
        tokenLine_ = line_;
        size_t start = pos_;
        while (pos_ < bytes_.size() && !isSpace(bytes_[pos_])) ++pos_;
        return bytes_.substr(start, pos_ - start);
    }
    static bool isSpace(char c) { return c == ' ' || c == '\n' || c == '\r' || c == '\t'; }

    std::string_view bytes_;
    size_t pos_;
    int line_;
    int tokenLine_;
};

// Loads a value of `type` stored at `p` in the file's byte order (`swap`: not the host's).
template <typename T>
T loadValue(const uint8_t* p, bool swap) {
    using Bits = std::conditional_t<sizeof(T) == 1, uint8_t,
                                    std::conditional_t<sizeof(T) == 2, uint16_t,
                                                       std::conditional_t<sizeof(T) == 4, uint32_t, uint64_t>>>;
    Bits bits;
    std::memcpy(&bits, p, sizeof bits);
    if constexpr (sizeof(T) == 2) bits = swap ? __builtin_bswap16(bits) : bits;
    if constexpr (sizeof(T) == 4) bits = swap ? __builtin_bswap32(bits) : bits;
    if constexpr (sizeof(T) == 8) bits = swap ? __builtin_bswap64(bits) : bits;
    return std::bit_cast<T>(bits);
}

inline double loadNumber(const uint8_t* p, Type type, bool swap) {
    switch (type) {
    case Type::Int8: return loadValue<int8_t>(p, swap);
    case Type::UInt8: return loadValue<uint8_t>(p, swap);
    case Type::Int16: return loadValue<int16_t>(p, swap);
    case Type::UInt16: return loadValue<uint16_t>(p, swap);
    case Type::Int32: return loadValue<int32_t>(p, swap);
    case Type::UInt32: return loadValue<uint32_t>(p, swap);
    case Type::Float32: return loadValue<float>(p, swap);
    case Type::Float64: return loadValue<double>(p, swap);
    }
    return 0;
}

inline int64_t loadInteger(const uint8_t* p, Type type, bool swap) {
    switch (type) {
    case Type::Int8: return loadValue<int8_t>(p, swap);
    case Type::UInt8: return loadValue<uint8_t>(p, swap);
    case Type::Int16: return loadValue<int16_t>(p, swap);
    case Type::UInt16: return loadValue<uint16_t>(p, swap);
    case Type::Int32: return loadValue<int32_t>(p, swap);
    case Type::UInt32: return loadValue<uint32_t>(p, swap);
    default: return 0;  // the header parser and the element roles allow only integer types here
    }
}

class BinarySource {
public:
    BinarySource(std::string_view bytes, size_t start, bool bigEndian)
        : data_(reinterpret_cast<const uint8_t*>(bytes.data())), size_(bytes.size()), pos_(start),
          swap_(bigEndian != (std::endian::native == std::endian::big)) {}

    size_t remaining() const { return size_ - pos_; }
    size_t offset() const { return pos_; }
    bool swapped() const { return swap_; }
    bool canHold(uint64_t n, Type type) const { return n <= remaining() / typeSize(type); }
    std::string where() const { return "byte offset " + std::to_string(pos_); }

    double scalar(Type type) { return loadNumber(take(typeSize(type)), type, swap_); }
    int64_t integer(Type type) { return loadInteger(take(typeSize(type)), type, swap_); }
    void skip(Type type, uint64_t n) {
        if (!canHold(n, type)) throw DataProblem{true, {}, where()};
        pos_ += size_t(n) * typeSize(type);
    }
    // The next `n` bytes, which the caller has checked are there (fixed-size elements).
    const uint8_t* advance(size_t n) {
        const uint8_t* p = data_ + pos_;
        pos_ += n;
        return p;
    }

private:
    const uint8_t* take(size_t n) {
        if (n > remaining()) throw DataProblem{true, {}, where()};
        return advance(n);
    }

    const uint8_t* data_;
    size_t size_;
    size_t pos_;
    bool swap_;
};

}  // namespace photon::ply
