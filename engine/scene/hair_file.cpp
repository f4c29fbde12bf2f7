#include "scene/hair_file.h"
#include <cmath>
#include <cstring>
#include <fstream>
#include <stdexcept>

namespace photon {
namespace {

// The header's fields, in order (cyHairFile.h): 4 + 5 * 4 + 3 * 4 + 88 = 128 bytes.
constexpr size_t kHeaderBytes = 128;
constexpr uint32_t kSegmentsBit = 1, kPointsBit = 2, kThicknessBit = 4, kTransparencyBit = 8, kColorsBit = 16;

[[noreturn]] void fail(const std::string& name, const std::string& message) {
    throw std::runtime_error("HAIR: " + name + ": " + message);
}

// Little-endian reads at an offset the caller has checked.
uint32_t u32(std::string_view b, size_t at) {
    const auto* p = reinterpret_cast<const unsigned char*>(b.data() + at);
    return uint32_t(p[0]) | uint32_t(p[1]) << 8 | uint32_t(p[2]) << 16 | uint32_t(p[3]) << 24;
}
uint16_t u16(std::string_view b, size_t at) {
    const auto* p = reinterpret_cast<const unsigned char*>(b.data() + at);
    return uint16_t(p[0] | p[1] << 8);
}
float f32(std::string_view b, size_t at) {
    const uint32_t bits = u32(b, at);
    float f;
    std::memcpy(&f, &bits, 4);
    return f;
}

void put32(std::string& out, uint32_t v) {
    for (int i = 0; i < 4; ++i) out.push_back(char((v >> (8 * i)) & 0xff));
}
void putFloat(std::string& out, float f) {
    uint32_t bits;
    std::memcpy(&bits, &f, 4);
    put32(out, bits);
}

}  // namespace

CurveSet readHairFile(std::string_view bytes, const std::string& name, float defaultWidth) {
    if (bytes.size() < kHeaderBytes) fail(name, "shorter than the 128-byte header");
    if (bytes.substr(0, 4) != "HAIR") fail(name, "does not start with the signature HAIR");
    const uint32_t strands = u32(bytes, 4), points = u32(bytes, 8), arrays = u32(bytes, 12);
    const uint32_t defaultSegments = u32(bytes, 16);
    const float defaultThickness = f32(bytes, 20);
    if (!(arrays & kPointsBit)) fail(name, "has no point array");
    if (points > kMaxCurvePoints)
        fail(name, std::to_string(points) + " points, more than the limit of " + std::to_string(kMaxCurvePoints));
    // Every array's size from the counts, checked against the bytes there before reading.
    const uint64_t segmentBytes = arrays & kSegmentsBit ? 2ull * strands : 0;
    const uint64_t pointBytes = 12ull * points, thicknessBytes = arrays & kThicknessBit ? 4ull * points : 0;
    const uint64_t transparencyBytes = arrays & kTransparencyBit ? 4ull * points : 0;
    const uint64_t colorBytes = arrays & kColorsBit ? 12ull * points : 0;
    const uint64_t need = kHeaderBytes + segmentBytes + pointBytes + thicknessBytes + transparencyBytes + colorBytes;
    if (bytes.size() < need)
        fail(name, "is " + std::to_string(bytes.size()) + " bytes, its header's counts need " + std::to_string(need));
    CurveSet c;
    c.strandStarts.reserve(strands);
    uint64_t total = 0;
    for (uint32_t k = 0; k < strands; ++k) {
        const uint64_t segments = arrays & kSegmentsBit ? u16(bytes, kHeaderBytes + 2ull * k) : defaultSegments;
        c.strandStarts.push_back(uint32_t(std::min<uint64_t>(total, points)));
        total += segments + 1;
        if (total > points)
            fail(name, "strand " + std::to_string(k) + " runs past the header's " + std::to_string(points) + " points");
    }
    if (total != points)
        fail(name, "its strands hold " + std::to_string(total) + " points, the header says " + std::to_string(points));
    const size_t pointAt = kHeaderBytes + segmentBytes, thicknessAt = pointAt + pointBytes;
    const float width = arrays & kThicknessBit ? 0.0f : (defaultThickness > 0 ? defaultThickness : defaultWidth);
    c.points.resize(points);
    for (uint32_t i = 0; i < points; ++i) {
        CurvePoint& p = c.points[i];
        p.p = {f32(bytes, pointAt + 12ull * i), f32(bytes, pointAt + 12ull * i + 4), f32(bytes, pointAt + 12ull * i + 8)};
        const float w = arrays & kThicknessBit ? f32(bytes, thicknessAt + 4ull * i) : width;
        if (!isFinite(p.p)) fail(name, "point " + std::to_string(i) + " is not finite");
        if (!(w >= 0) || !std::isfinite(w)) fail(name, "point " + std::to_string(i) + " has a thickness below 0 or not finite");
        p.radius = 0.5f * w;
    }
    return c;
}

CurveSet readHairFile(const std::filesystem::path& file, float defaultWidth) {
    std::ifstream in(file, std::ios::binary);
    if (!in) fail(file.string(), "cannot open the file");
    in.seekg(0, std::ios::end);
    std::string bytes(size_t(std::max<std::streamoff>(in.tellg(), 0)), '\0');
    in.seekg(0);
    if (!in.read(bytes.data(), std::streamsize(bytes.size()))) fail(file.string(), "cannot read the file");
    return readHairFile(std::string_view(bytes), file.string(), defaultWidth);
}

std::string hairFileBytes(const CurveSet& curves) {
    std::string out = "HAIR";
    put32(out, uint32_t(curves.strandCount()));
    put32(out, uint32_t(curves.points.size()));
    put32(out, kSegmentsBit | kPointsBit | kThicknessBit);
    put32(out, 0);       // default segments: every strand has its own
    putFloat(out, 0);    // default thickness, transparency, colour: unused
    putFloat(out, 0);
    for (int i = 0; i < 3; ++i) putFloat(out, 0);
    std::string info = "photon";
    info.resize(88, '\0');
    out += info;
    for (size_t k = 0; k < curves.strandCount(); ++k) {
        const size_t n = curves.strandSize(k);
        if (n < 1 || n > 65536) throw std::runtime_error("HAIR: a strand of " + std::to_string(n) + " points cannot be written (1 to 65536)");
        out.push_back(char((n - 1) & 0xff));
        out.push_back(char((n - 1) >> 8));
    }
    for (const CurvePoint& p : curves.points)
        for (int i = 0; i < 3; ++i) putFloat(out, p.p[i]);
    for (const CurvePoint& p : curves.points) putFloat(out, 2.0f * p.radius);
    return out;
}

void writeHairFile(const CurveSet& curves, const std::filesystem::path& file) {
    const std::string bytes = hairFileBytes(curves);
    std::ofstream out(file, std::ios::binary);
    out.write(bytes.data(), std::streamsize(bytes.size()));
    if (!out) throw std::runtime_error("HAIR: cannot write " + file.string());
}

}  // namespace photon
