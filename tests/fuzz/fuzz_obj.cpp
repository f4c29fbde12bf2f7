// Fuzzes OBJ mesh input through the engine's OBJ reader (loadMeshFile): the input is
// written to an .obj file in a scratch folder and loaded confined to that folder, as a
// scene's mesh would be. The folder also holds a small .mtl so `mtllib` lines resolve.
//
// Contract checked: loadMeshFile throws std::runtime_error (or a subclass) for bad files and
// otherwise returns a mesh whose indices are in range and whose positions are finite.
#include <cstdint>
#include <cstdlib>
#include <fstream>
#include "fuzz_mesh_check.h"
#include "fuzz_support.h"
#include "scene/mesh_loader.h"

namespace {

namespace fs = std::filesystem;

const fs::path& folder() {
    static const fs::path dir = [] {
        fs::path d = photon::fuzz::scratchDir("photon-fuzz-obj");
        std::ofstream(d / "m.mtl") << "newmtl red\nKd 1 0 0\nmap_Kd t.png\n";
        return d;
    }();
    return dir;
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
    const fs::path file = folder() / "in.obj";
    {
        std::ofstream out(file, std::ios::binary | std::ios::trunc);
        out.write(reinterpret_cast<const char*>(data), std::streamsize(size));
    }
    try {
        photon::fuzz::checkMesh(photon::loadMeshFile(file, folder()));
    } catch (const std::runtime_error&) {
    }
    return 0;
}
