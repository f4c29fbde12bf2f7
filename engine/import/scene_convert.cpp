#include <photon/scene_convert.h>
#include <unistd.h>
#include <fstream>
#include <sstream>
#include <stdexcept>
#include "import/scene_import.h"
#include "scene/ply_mesh.h"
#include "scene/scene_loader.h"

namespace photon {

namespace {

namespace fs = std::filesystem;

fs::path folderOf(const fs::path& file) { return file.parent_path().empty() ? fs::path(".") : file.parent_path(); }

std::string readAll(const fs::path& file) {
    std::ifstream in(file, std::ios::binary);
    std::ostringstream s;
    s << in.rdbuf();
    return s.str();
}

// Writes `bytes` to `file` unless it holds them already; refuses to replace other contents.
void writeFile(const fs::path& file, const std::string& bytes, bool overwrite) {
    std::error_code ec;
    if (fs::exists(file, ec)) {
        if (readAll(file) == bytes) return;
        if (!overwrite) throw std::runtime_error("would overwrite " + file.string() + " (a different file is there)");
    }
    fs::create_directories(folderOf(file));
    const fs::path temporary = file.string() + ".tmp";
    {
        std::ofstream out(temporary, std::ios::binary);
        out.write(bytes.data(), std::streamsize(bytes.size()));
        if (!out) throw std::runtime_error("cannot write " + temporary.string());
    }
    fs::rename(temporary, file);
}

std::string plyBytes(const TriangleMesh& mesh) {
    const fs::path scratch = fs::temp_directory_path() / ("photon-convert-" + std::to_string(::getpid()) + ".ply");
    writePlyMesh(mesh, scratch);
    std::string bytes = readAll(scratch);
    fs::remove(scratch);
    return bytes;
}

}  // namespace

ConversionReport convertScene(const fs::path& input, const fs::path& output, const ImportOptions& options,
                              bool overwrite) {
    ImportedScene imported = importSceneFile(input, options);
    const fs::path inDir = folderOf(input), outDir = folderOf(output);
    // Loading checks the document as photon's loader will read it, and lists the files on
    // disk it names.
    const SceneDescription loaded = loadImportedScene(imported, inDir);
    std::error_code ec;
    const bool sameFolder = fs::equivalent(inDir, outDir, ec) || fs::weakly_canonical(inDir) == fs::weakly_canonical(outDir);
    ConversionReport report;
    report.warnings = imported.warnings;
    for (const auto& [name, mesh] : imported.meshes) {
        // A mesh that is a file as it stands is that file (copied, gzipped or not), not the
        // mesh written again.
        const bool onDisk = imported.meshesOnDisk.count(name) > 0;
        if (sameFolder && onDisk) continue;
        writeFile(outDir / name, onDisk ? readAll(inDir / name) : plyBytes(mesh), overwrite);
        report.written.push_back(name);
    }
    for (const auto& [name, bytes] : imported.files) {
        writeFile(outDir / name, bytes, overwrite);
        report.written.push_back(name);
    }
    if (!sameFolder)
        for (const std::string& name : loaded.files) {
            if (imported.meshes.count(name) || imported.files.count(name)) continue;
            writeFile(outDir / name, readAll(inDir / name), overwrite);
            report.written.push_back(name);
        }
    writeFile(output, imported.document.dump(2) + "\n", overwrite);
    return report;
}

}  // namespace photon
