// photon's PLY reader and writer (engine/scene/ply_mesh.h): a hand-written mesh decodes to the
// same triangles from ascii and both binary byte orders, with whatever else the file holds
// skipped; a written mesh reads back bit for bit; and every way a file can be wrong or lie
// about its size is an exact error, never a crash or a huge allocation.
#include <gtest/gtest.h>
#include <bit>
#include <chrono>
#include <cmath>
#include <cstring>
#include <fstream>
#include <iterator>
#include <limits>
#include <unistd.h>
#include "scene/mesh_loader.h"
#include "scene/ply_mesh.h"
#include "test_support.h"

namespace photon {
namespace {

namespace fs = std::filesystem;

// ---- building PLY bytes: the same rows as text or packed binary ----

enum class T { i8, u8, i16, u16, i32, u32, f32, f64 };
struct Value {
    T type;
    double v;
};
using Row = std::vector<Value>;

template <typename U>
void appendBytes(std::string& out, U value, bool bigEndian) {
    char bytes[sizeof(U)];
    std::memcpy(bytes, &value, sizeof(U));
    if (bigEndian != (std::endian::native == std::endian::big)) std::reverse(bytes, bytes + sizeof(U));
    out.append(bytes, sizeof(U));
}

void appendValue(std::string& out, Value x, bool bigEndian) {
    switch (x.type) {
    case T::i8: return appendBytes(out, int8_t(x.v), bigEndian);
    case T::u8: return appendBytes(out, uint8_t(x.v), bigEndian);
    case T::i16: return appendBytes(out, int16_t(x.v), bigEndian);
    case T::u16: return appendBytes(out, uint16_t(x.v), bigEndian);
    case T::i32: return appendBytes(out, int32_t(x.v), bigEndian);
    case T::u32: return appendBytes(out, uint32_t(x.v), bigEndian);
    case T::f32: return appendBytes(out, float(x.v), bigEndian);
    case T::f64: return appendBytes(out, x.v, bigEndian);
    }
}

// "ply", the format line, `headerBody` (elements and properties), end_header, then the rows.
std::string plyBytes(const std::string& format, const std::string& headerBody, const std::vector<Row>& rows) {
    std::string out = "ply\nformat " + format + " 1.0\n" + headerBody + "end_header\n";
    for (const Row& row : rows) {
        for (size_t i = 0; i < row.size(); ++i) {
            if (format != "ascii") {
                appendValue(out, row[i], format == "binary_big_endian");
                continue;
            }
            char text[64];
            std::snprintf(text, sizeof text, "%.17g", row[i].v);
            out += (i ? " " : "") + std::string(text);
        }
        if (format == "ascii") out += "\n";
    }
    return out;
}

const std::vector<std::string> kFormats{"ascii", "binary_little_endian", "binary_big_endian"};

// A quad, a triangle and a two-vertex face, among elements and properties the mesh does not
// use: a `tag` element with a list before the vertices, a uchar and a double among the
// vertex properties, pbrt's face_indices, and edges after the faces.
const std::string kMixedHeader =
    "comment made by hand\nobj_info for the reader's tests\n"
    "element tag 2\nproperty list uchar int ids\nproperty double weight\n"
    "element vertex 5\nproperty float x\nproperty float y\nproperty float z\nproperty uchar red\n"
    "property float nx\nproperty float ny\nproperty float nz\nproperty double confidence\n"
    "property float u\nproperty float v\n"
    "element face 3\nproperty list uchar int vertex_indices\nproperty int face_indices\n"
    "element edge 1\nproperty int vertex1\nproperty list uint16 int16 path\n";

std::vector<Row> mixedRows() {
    auto vertex = [](double x, double y, double z, double nz, double u, double v) {
        return Row{{T::f32, x}, {T::f32, y}, {T::f32, z},  {T::u8, 200},  {T::f32, 0},
                   {T::f32, 0}, {T::f32, nz}, {T::f64, 0.5}, {T::f32, u}, {T::f32, v}};
    };
    return {
        {{T::u8, 2}, {T::i32, 7}, {T::i32, -8}, {T::f64, 1.5}},
        {{T::u8, 0}, {T::f64, 2.5}},
        vertex(0, 0, 0, 1, 0, 0),
        vertex(1, 0, 0, 1, 1, 0),
        vertex(1, 1, 0, 1, 1, 1),
        vertex(0, 1, 0, 1, 0, 1),
        vertex(0.5, 0.5, 2, 0, 0.5, 0.25),  // a zero normal, kept as the file has it
        {{T::u8, 4}, {T::i32, 0}, {T::i32, 1}, {T::i32, 2}, {T::i32, 3}, {T::i32, 0}},
        {{T::u8, 3}, {T::i32, 1}, {T::i32, 4}, {T::i32, 2}, {T::i32, 1}},
        {{T::u8, 2}, {T::i32, 0}, {T::i32, 4}, {T::i32, 1}},
        {{T::i32, 0}, {T::i32, 1}, {T::u16, 2}, {T::i16, 3}, {T::i16, -4}},
    };
}

TriangleMesh read(const std::string& bytes) { return readPlyMesh(std::string_view(bytes), "m.ply"); }

std::string errorOf(const std::string& bytes) {
    try {
        read(bytes);
    } catch (const std::runtime_error& e) {
        return e.what();
    }
    return "no error";
}

// Same size and the same bytes (memcmp: -0.0 and 0.0 differ, as they should here).
template <typename V>
bool sameBytes(const std::vector<V>& a, const std::vector<V>& b) {
    return a.size() == b.size() && (a.empty() || std::memcmp(a.data(), b.data(), a.size() * sizeof(V)) == 0);
}

void expectSameBits(const TriangleMesh& a, const TriangleMesh& b) {
    EXPECT_EQ(a.indices, b.indices);
    EXPECT_TRUE(sameBytes(a.positions, b.positions));
    EXPECT_TRUE(sameBytes(a.normals, b.normals));
    EXPECT_TRUE(sameBytes(a.uvs, b.uvs));
}

fs::path tempFolder() {
    fs::path dir = fs::temp_directory_path() / ("photon-test-ply-" + std::to_string(::getpid()));
    fs::create_directories(dir);
    return dir;
}

// ---- decoding ----

TEST(PlyMesh, AsciiAndBothBinaryOrdersGiveTheSameMesh) {
    TriangleMesh expected;
    expected.positions = {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}, {0.5f, 0.5f, 2}};
    expected.normals = {{0, 0, 1}, {0, 0, 1}, {0, 0, 1}, {0, 0, 1}, {0, 0, 0}};
    expected.uvs = {{0, 0}, {1, 0}, {1, 1}, {0, 1}, {0.5f, 0.25f}};
    // The quad fans about its first vertex; the two-vertex face is dropped.
    expected.indices = {0, 1, 2, 0, 2, 3, 1, 4, 2};
    for (const std::string& format : kFormats) {
        SCOPED_TRACE(format);
        expectSameBits(read(plyBytes(format, kMixedHeader, mixedRows())), expected);
    }
}

TEST(PlyMesh, DoublePositionsAndListsAmongTheVertexProperties) {
    const std::string header =
        "element vertex 3\nproperty list uchar float weights\nproperty double x\nproperty double y\n"
        "property double z\nproperty int16 id\n"
        "element face 1\nproperty list uint32 uint16 vertex_index\n";
    const std::vector<Row> rows{
        {{T::u8, 2}, {T::f32, 0.25}, {T::f32, 0.5}, {T::f64, 0.1}, {T::f64, -2}, {T::f64, 3}, {T::i16, -1}},
        {{T::u8, 0}, {T::f64, 1}, {T::f64, 0}, {T::f64, 0}, {T::i16, 7}},
        {{T::u8, 1}, {T::f32, 1}, {T::f64, 0}, {T::f64, 1e30}, {T::f64, 0}, {T::i16, 8}},
        {{T::u32, 3}, {T::u16, 2}, {T::u16, 1}, {T::u16, 0}},
    };
    for (const std::string& format : kFormats) {
        SCOPED_TRACE(format);
        TriangleMesh m = read(plyBytes(format, header, rows));
        ASSERT_EQ(m.positions.size(), 3u);
        EXPECT_EQ(m.positions[0].x, 0.1f);
        EXPECT_EQ(m.positions[0].y, -2.0f);
        EXPECT_EQ(m.positions[2].y, 1e30f);
        EXPECT_TRUE(m.normals.empty());
        EXPECT_TRUE(m.uvs.empty());
        EXPECT_EQ(m.indices, (std::vector<uint32_t>{2, 1, 0}));
    }
}

TEST(PlyMesh, EveryTextureCoordinateNaming) {
    for (auto [u, v] : std::vector<std::pair<std::string, std::string>>{
             {"u", "v"}, {"s", "t"}, {"texture_u", "texture_v"}, {"texture_s", "texture_t"}}) {
        SCOPED_TRACE(u);
        const std::string header = "element vertex 3\nproperty float x\nproperty float y\nproperty float z\n"
                                   "property float " + u + "\nproperty float " + v + "\n"
                                   "element face 1\nproperty list uchar int vertex_indices\n";
        auto vertex = [](double x, double uu, double vv) {
            return Row{{T::f32, x}, {T::f32, 0}, {T::f32, 0}, {T::f32, uu}, {T::f32, vv}};
        };
        TriangleMesh m = read(plyBytes("binary_little_endian", header,
                                       {vertex(0, 0.25, 0.5), vertex(1, 0.75, 1), vertex(2, 1, 0),
                                        {{T::u8, 3}, {T::i32, 0}, {T::i32, 1}, {T::i32, 2}}}));
        ASSERT_EQ(m.uvs.size(), 3u);
        EXPECT_EQ(m.uvs[0].x, 0.25f);
        EXPECT_EQ(m.uvs[0].y, 0.5f);
        EXPECT_EQ(m.uvs[1].x, 0.75f);
    }
    // Half a pair, or half a normal, is not one.
    TriangleMesh m = read("ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\nproperty float y\n"
                          "property float z\nproperty float u\nproperty float nx\nelement face 1\n"
                          "property list uchar int vertex_indices\nend_header\n0 0 0 1 1\n1 0 0 1 1\n0 1 0 1 1\n3 0 1 2\n");
    EXPECT_TRUE(m.uvs.empty());
    EXPECT_TRUE(m.normals.empty());
}

TEST(PlyMesh, CrlfHeaderSizedTypeNamesAndTrailingBytes) {
    std::string bytes = "ply\r\nformat binary_big_endian 1.0\r\ncomment CRLF\r\nelement vertex 3\r\n"
                        "property float32 x\r\nproperty float32 y\r\nproperty float32 z\r\nelement face 1\r\n"
                        "property list uint8 int32 vertex_indices\r\nend_header\r\n";
    for (double x : {0.0, 1.0, 0.0, 0.0, 0.0, 1.0, 0.0, 0.0, 0.0}) appendBytes(bytes, float(x), true);
    appendBytes(bytes, uint8_t(3), true);
    for (int32_t i : {0, 1, 2}) appendBytes(bytes, i, true);
    bytes += "whatever follows the last element";
    TriangleMesh m = read(bytes);
    ASSERT_EQ(m.positions.size(), 3u);
    EXPECT_EQ(m.positions[0].y, 1.0f);
    EXPECT_EQ(m.positions[1].z, 1.0f);
    EXPECT_EQ(m.indices, (std::vector<uint32_t>{0, 1, 2}));
}

// ---- writing ----

TEST(PlyMesh, WriteThenReadIsBitExact) {
    TriangleMesh mesh;
    mesh.positions = {{0.1f, -0.0f, 1e-40f}, {3.14159265f, 1e30f, -7}, {-1, 2, 3}, {5, 6, 7}};
    mesh.normals = {{0, 0, 1}, {0.6f, 0.8f, 0}, {0, 0, 0}, {1, 0, 0}};
    mesh.uvs = {{0, 0}, {1.0f / 3, 2}, {-0.5f, 1e-7f}, {1, 1}};
    mesh.indices = {0, 1, 2, 2, 1, 3};
    const fs::path file = tempFolder() / "round-trip.ply";
    writePlyMesh(mesh, file);
    expectSameBits(readPlyMesh(file), mesh);

    mesh.normals.clear();
    mesh.uvs.clear();
    writePlyMesh(mesh, file);
    expectSameBits(readPlyMesh(file), mesh);
    fs::remove_all(file.parent_path());
}

// ---- loadMeshFile ----

// pbrt-v4 scenes ship meshes as "geometry/ganesha.ply.gz".
TEST(PlyMesh, LoadMeshFileReadsGzippedPly) {
    const fs::path folder = tempFolder();
    TriangleMesh mesh;
    mesh.positions = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {1, 1, 0}};
    mesh.uvs = {{0, 0}, {1, 0}, {0, 1}, {1, 1}};
    mesh.indices = {0, 1, 2, 2, 1, 3};
    writePlyMesh(mesh, folder / "plain.ply");
    std::ifstream in(folder / "plain.ply", std::ios::binary);
    const std::string bytes{std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
    std::ofstream(folder / "zipped.ply.gz", std::ios::binary) << test::gzipped(bytes);
    expectSameBits(loadMeshFile(folder / "zipped.ply.gz", folder), mesh);
    // Not gzip inside, or cut short: the reason, with the file.
    std::ofstream(folder / "plain.ply.gz", std::ios::binary) << bytes;
    const std::string gz = test::gzipped(bytes);
    std::ofstream(folder / "cut.ply.gz", std::ios::binary) << gz.substr(0, gz.size() - 9);
    for (const auto& [file, why] : {std::pair{"plain.ply.gz", "not a gzip file"}, {"cut.ply.gz", "the gzip file is cut short"}}) {
        try {
            loadMeshFile(folder / file, folder);
            ADD_FAILURE() << file << " was read";
        } catch (const std::runtime_error& e) {
            EXPECT_EQ(std::string(e.what()), "PLY: " + (folder / file).string() + ": " + why);
        }
    }
}

TEST(PlyMesh, LoadMeshFileReadsPlyWhateverTheExtensionsCase) {
    const fs::path folder = tempFolder();
    TriangleMesh mesh;
    mesh.positions = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}};
    mesh.normals = {{0, 0, 2}, {0, 0, 2}, {0, 0, 2}};
    mesh.uvs = {{0, 0}, {1, 0}, {0, 1}};
    mesh.indices = {0, 1, 2};
    writePlyMesh(mesh, folder / "upper.PLY");
    TriangleMesh loaded = loadMeshFile(folder / "upper.PLY", folder);
    EXPECT_EQ(loaded.indices, mesh.indices);
    EXPECT_EQ(loaded.normals[1].z, 1.0f);  // normalized, as for every other format
    EXPECT_EQ(loaded.uvs[2].y, 1.0f);
    // A zero normal makes the whole mesh use geometric normals (loadMeshFile's contract).
    mesh.normals[1] = {0, 0, 0};
    writePlyMesh(mesh, folder / "zero-normal.ply");
    EXPECT_TRUE(loadMeshFile(folder / "zero-normal.ply").normals.empty());
    // Outside the folder it is confined to.
    const fs::path inner = folder / "inner";
    fs::create_directories(inner);
    try {
        loadMeshFile(folder / "upper.PLY", inner);
        FAIL() << "read a file outside the folder";
    } catch (const std::runtime_error& e) {
        EXPECT_EQ(std::string(e.what()),
                  "PLY: " + (folder / "upper.PLY").string() + ": the file is outside the folder it must be in");
    }
    mesh.indices.clear();
    writePlyMesh(mesh, folder / "empty.ply");
    try {
        loadMeshFile(folder / "empty.ply");
        FAIL() << "loaded a mesh without triangles";
    } catch (const std::runtime_error& e) {
        EXPECT_EQ(std::string(e.what()), "the file contains no triangles");
    }
    fs::remove_all(folder);
}


// ---- errors: exact messages ----

// A triangle's header: lines 3 to 8, end_header on line 9, data from line 10.
const std::string kTriangleHeader =
    "element vertex 3\nproperty float x\nproperty float y\nproperty float z\n"
    "element face 1\nproperty list uchar int vertex_indices\n";

Row xyz(double x, double y, double z) { return {{T::f32, x}, {T::f32, y}, {T::f32, z}}; }
Row triangle(double a, double b, double c) { return {{T::u8, 3}, {T::i32, a}, {T::i32, b}, {T::i32, c}}; }

// Where the data starts in plyBytes(format, header, ...).
size_t dataOffset(const std::string& format, const std::string& header) {
    return plyBytes(format, header, {}).size();
}

TEST(PlyMeshErrors, Header) {
    EXPECT_EQ(errorOf("solid cube\n"), "PLY: m.ply: the file does not start with a 'ply' line");
    EXPECT_EQ(errorOf("ply\nformat binary_middle_endian 1.0\nend_header\n"),
              "PLY: m.ply: header line 2: unknown format 'binary_middle_endian' (expected ascii, "
              "binary_little_endian or binary_big_endian)");
    EXPECT_EQ(errorOf("ply\nformat ascii 2.0\nend_header\n"),
              "PLY: m.ply: header line 2: unsupported format version '2.0' (expected 1.0)");
    EXPECT_EQ(errorOf("ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\n"),
              "PLY: m.ply: the header has no 'end_header' line");
    EXPECT_EQ(errorOf("ply\nelement vertex 3\nend_header\n"),
              "PLY: m.ply: header line 2: 'element' before the 'format' line");
    EXPECT_EQ(errorOf("ply\nend_header\n"), "PLY: m.ply: header line 2: the header has no 'format' line");
    EXPECT_EQ(errorOf("ply\nformat ascii 1.0\nelement face 1\nproperty list float int vertex_indices\nend_header\n"),
              "PLY: m.ply: header line 4: the count type of list vertex_indices must be an integer type, not float");
    EXPECT_EQ(errorOf("ply\nformat ascii 1.0\nelement vertex 1\nproperty half x\nend_header\n"),
              "PLY: m.ply: header line 4: unknown property type 'half'");
    EXPECT_EQ(errorOf("ply\nformat ascii 1.0\nelements vertex 3\nend_header\n"),
              "PLY: m.ply: header line 3: unknown keyword 'elements'");
    EXPECT_EQ(errorOf("ply\nformat ascii 1.0\nproperty float x\nend_header\n"),
              "PLY: m.ply: header line 3: 'property' before any 'element'");
    EXPECT_EQ(errorOf("ply\nformat ascii 1.0\nelement vertex -1\nend_header\n"),
              "PLY: m.ply: header line 3: the count of element vertex is not a whole number: '-1'");
    EXPECT_EQ(errorOf("ply\nformat ascii 1.0\nelement vertex 1\nproperty float x\nproperty double x\nend_header\n"),
              "PLY: m.ply: header line 5: element vertex has two properties named x");
    EXPECT_EQ(errorOf("ply\nformat ascii 1.0\nelement vertex 1 2\nend_header\n"),
              "PLY: m.ply: header line 3: expected 'element NAME COUNT'");
}

TEST(PlyMeshErrors, WhatTheMeshNeeds) {
    const std::string start = "ply\nformat ascii 1.0\n";
    EXPECT_EQ(errorOf(start + "element face 0\nproperty list uchar int vertex_indices\nend_header\n"),
              "PLY: m.ply: the header declares no vertex element");
    EXPECT_EQ(errorOf(start + "element vertex 0\nproperty float x\nend_header\n"),
              "PLY: m.ply: the header declares no face element");
    EXPECT_EQ(errorOf(start + "element vertex 0\nproperty float x\nproperty float y\nelement face 0\n"
                              "property list uchar int vertex_indices\nend_header\n"),
              "PLY: m.ply: element vertex (header line 3) has no property z");
    EXPECT_EQ(errorOf(start + "element vertex 0\nproperty list uchar float x\nproperty float y\nproperty float z\n"
                              "element face 0\nproperty list uchar int vertex_indices\nend_header\n"),
              "PLY: m.ply: element vertex (header line 3) has a list x where a number belongs");
    const std::string vertices = "element vertex 0\nproperty float x\nproperty float y\nproperty float z\n";
    EXPECT_EQ(errorOf(start + vertices + "element face 0\nproperty list uchar float vertex_indices\nend_header\n"),
              "PLY: m.ply: element face (header line 7) has vertex_indices of float, not of an integer type");
    EXPECT_EQ(errorOf(start + vertices + "element face 0\nproperty int vertex_indices\nend_header\n"),
              "PLY: m.ply: element face (header line 7) has a single number vertex_indices where a list belongs");
    EXPECT_EQ(errorOf(start + vertices + "element face 0\nproperty list uchar int corners\nend_header\n"),
              "PLY: m.ply: element face (header line 7) has no vertex_indices (or vertex_index) list");
    EXPECT_EQ(errorOf(start + "element vertex 5000000000\nproperty float x\nproperty float y\nproperty float z\n"
                              "element face 0\nproperty list uchar int vertex_indices\nend_header\n"),
              "PLY: m.ply: element vertex (header line 3) declares 5000000000 vertices, more than 32-bit indices "
              "can name");
}

TEST(PlyMeshErrors, CountsTheBytesCannotHoldFailBeforeAnyAllocation) {
    const std::string binary = "binary_little_endian";
    const size_t at = dataOffset(binary, kTriangleHeader);
    // Two of three vertices.
    EXPECT_EQ(errorOf(plyBytes(binary, kTriangleHeader, {xyz(0, 0, 0), xyz(1, 0, 0)})),
              "PLY: m.ply: the header declares 3 vertices of 12 bytes, but only 24 bytes follow it");
    // Four billion vertices in a file of a few hundred bytes: refused at once (48 GB were
    // it believed).
    std::string huge = kTriangleHeader;
    huge.replace(huge.find("vertex 3"), 8, "vertex 4000000000");
    std::vector<Row> rows(16, xyz(0, 0, 0));
    rows.push_back(triangle(0, 1, 2));
    auto start = std::chrono::steady_clock::now();
    EXPECT_EQ(errorOf(plyBytes(binary, huge, rows)),
              "PLY: m.ply: the header declares 4000000000 vertices of 12 bytes, but only 205 bytes follow it");
    EXPECT_EQ(errorOf(plyBytes("ascii", huge, rows)),
              "PLY: m.ply: the header declares 4000000000 vertices of at least 3 numbers, but only 104 bytes of "
              "text are left for them at line 10");
    EXPECT_LT(std::chrono::steady_clock::now() - start, std::chrono::seconds(1));
    // A later element: the faces after the vertices.
    std::string faces = kTriangleHeader;
    faces.replace(faces.find("face 1"), 6, "face 1000");
    EXPECT_EQ(errorOf(plyBytes(binary, faces, {xyz(0, 0, 0), xyz(1, 0, 0), xyz(0, 1, 0), triangle(0, 1, 2)})),
              "PLY: m.ply: the header declares 1000 faces of at least 1 byte, but only 13 bytes are left for them "
              "at byte offset " + std::to_string(dataOffset(binary, faces) + 36));
    // A list longer than what is left.
    EXPECT_EQ(errorOf(plyBytes(binary, kTriangleHeader,
                               {xyz(0, 0, 0), xyz(1, 0, 0), xyz(0, 1, 0), {{T::u8, 200}, {T::i32, 0}, {T::i32, 1},
                                                                            {T::i32, 2}}})),
              "PLY: m.ply: face 0 of 1: the list vertex_indices claims 200 items, but only 12 bytes are left at "
              "byte offset " + std::to_string(at + 37));
    std::string signedCount = kTriangleHeader;
    signedCount.replace(signedCount.find("uchar"), 5, "char");
    EXPECT_EQ(errorOf(plyBytes(binary, signedCount, {xyz(0, 0, 0), xyz(1, 0, 0), xyz(0, 1, 0),
                                                     {{T::i8, -3}, {T::i32, 0}, {T::i32, 1}, {T::i32, 2}}})),
              "PLY: m.ply: face 0 of 1: the list vertex_indices claims -3 items, but only 12 bytes are left at "
              "byte offset " + std::to_string(dataOffset(binary, signedCount) + 37));
    // Two faces declared, one there.
    std::string twoFaces = kTriangleHeader;
    twoFaces.replace(twoFaces.find("face 1"), 6, "face 2");
    EXPECT_EQ(errorOf(plyBytes(binary, twoFaces, {xyz(0, 0, 0), xyz(1, 0, 0), xyz(0, 1, 0), triangle(0, 1, 2)})),
              "PLY: m.ply: the file ends in face 1 of 2 (property vertex_indices, byte offset " +
                  std::to_string(dataOffset(binary, twoFaces) + 49) + ")");
}

TEST(PlyMeshErrors, BadValues) {
    const std::string binary = "binary_little_endian";
    EXPECT_EQ(errorOf(plyBytes(binary, kTriangleHeader, {xyz(0, 0, 0), xyz(1, 0, 0), xyz(0, 1, 0), triangle(0, 1, 12)})),
              "PLY: m.ply: face 0 refers to vertex 12, but there are 3 vertices");
    EXPECT_EQ(errorOf(plyBytes(binary, kTriangleHeader, {xyz(0, 0, 0), xyz(1, 0, 0), xyz(0, 1, 0), triangle(0, -1, 2)})),
              "PLY: m.ply: face 0 refers to vertex -1, but there are 3 vertices");
    const double inf = std::numeric_limits<double>::infinity();
    EXPECT_EQ(errorOf(plyBytes(binary, kTriangleHeader, {xyz(0, 0, 0), xyz(1, inf, 0), xyz(0, 1, 0), triangle(0, 1, 2)})),
              "PLY: m.ply: vertex 1 of 3 has a position that is not a finite number");
    const std::string ascii = plyBytes("ascii", kTriangleHeader, {});
    EXPECT_EQ(errorOf(ascii + "0 0 0\n1 0 nan\n0 1 0\n3 0 1 2\n"),
              "PLY: m.ply: vertex 1 of 3 has a position that is not a finite number");
    EXPECT_EQ(errorOf(ascii + "0 0 0\n1 abc 0\n0 1 0\n3 0 1 2\n"),
              "PLY: m.ply: line 11: 'abc' is not a number of type float (vertex 1 of 3, property y)");
    EXPECT_EQ(errorOf(ascii + "0 0 0\n1 0 0\n0 1 0\n300 0 1 2\n"),
              "PLY: m.ply: line 13: '300' is not a number of type uchar (face 0 of 1, property vertex_indices)");
    EXPECT_EQ(errorOf(ascii + "0 0 0\n1 0 0\n0 1 0\n3 0 1.5 2\n"),
              "PLY: m.ply: line 13: '1.5' is not a number of type int (face 0 of 1, property vertex_indices)");
    EXPECT_EQ(errorOf(ascii + "0 0 0\n1 0 0\n0 1 0\n3 0 1\n"),
              "PLY: m.ply: the file ends in face 0 of 1 (property vertex_indices, line 13)");
}

TEST(PlyMeshErrors, TriangleLimit) {
    // One polygon of ten million and three vertices: ten million and one triangles.
    const std::string header = "element vertex 3\nproperty float x\nproperty float y\nproperty float z\n"
                               "element face 1\nproperty list uint uchar vertex_indices\n";
    std::string bytes = plyBytes("binary_little_endian", header, {xyz(0, 0, 0), xyz(1, 0, 0), xyz(0, 1, 0),
                                                                  {{T::u32, double(kMaxMeshTriangles + 3)}}});
    bytes.append(kMaxMeshTriangles + 3, '\0');
    EXPECT_EQ(errorOf(bytes), "PLY: m.ply: face 0 of 1 takes the mesh past the limit of 10000000 triangles");
}

TEST(PlyMeshErrors, Files) {
    const fs::path missing = tempFolder() / "missing.ply";
    try {
        readPlyMesh(missing);
        FAIL() << "read a missing file";
    } catch (const std::runtime_error& e) {
        EXPECT_EQ(std::string(e.what()), "PLY: " + missing.string() + ": cannot open the file");
    }
    TriangleMesh mesh;
    mesh.positions = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}};
    mesh.normals = {{0, 0, 1}};
    mesh.indices = {0, 1, 2};
    try {
        writePlyMesh(mesh, tempFolder() / "bad.ply");
        FAIL() << "wrote a mesh with one normal for three positions";
    } catch (const std::runtime_error& e) {
        EXPECT_EQ(std::string(e.what()), "PLY: " + (tempFolder() / "bad.ply").string() +
                                             ": cannot write a mesh whose normals or uvs are not one per position");
    }
    fs::remove_all(tempFolder());
}

}  // namespace
}  // namespace photon
