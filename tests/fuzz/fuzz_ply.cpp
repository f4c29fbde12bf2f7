// Fuzzes photon's PLY reader (readPlyMesh on bytes in memory, as loadMeshFile reads a
// scene's .ply), and the writer on whatever it accepts.
//
// Contract checked: readPlyMesh throws std::runtime_error for bad input and otherwise
// returns a mesh whose indices are in range, whose positions are finite, whose normals and
// uvs are empty or one per position, and within kMaxMeshTriangles; writing that mesh and
// reading it back gives it again bit for bit. A count the input cannot hold must fail
// before it is allocated (libFuzzer's -rss_limit_mb and -malloc_limit_mb catch one that
// does not).
#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <cstring>
#include <string_view>
#include "fuzz_mesh_check.h"
#include "fuzz_support.h"
#include "scene/mesh_loader.h"
#include "scene/ply_mesh.h"

namespace {

namespace fs = std::filesystem;

// Bit for bit, except that a NaN may come back as another NaN: values pass through double
// on the way in, which quiets a signalling NaN.
template <typename T>
bool sameBits(const std::vector<T>& a, const std::vector<T>& b) {
    if (a.size() != b.size()) return false;
    const auto* x = reinterpret_cast<const float*>(a.data());
    const auto* y = reinterpret_cast<const float*>(b.data());
    for (size_t i = 0; i < a.size() * sizeof(T) / sizeof(float); ++i)
        if (std::memcmp(&x[i], &y[i], sizeof(float)) != 0 && !(std::isnan(x[i]) && std::isnan(y[i]))) return false;
    return true;
}

void checkRoundTrip(const photon::TriangleMesh& mesh) {
    static const fs::path file = photon::fuzz::scratchDir("photon-fuzz-ply") / "round-trip.ply";
    photon::writePlyMesh(mesh, file);
    photon::TriangleMesh again = photon::readPlyMesh(file);
    if (!sameBits(again.positions, mesh.positions) || !sameBits(again.normals, mesh.normals) ||
        !sameBits(again.uvs, mesh.uvs) || again.indices != mesh.indices)
        std::abort();
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
    photon::TriangleMesh mesh;
    try {
        mesh = photon::readPlyMesh(std::string_view(reinterpret_cast<const char*>(data), size), "in.ply");
    } catch (const std::runtime_error&) {
        return 0;
    }
    photon::fuzz::checkMesh(mesh);
    checkRoundTrip(mesh);
    return 0;
}
