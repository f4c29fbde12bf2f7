// The on-disk layout under the data directory:
//   DIR/lock                  held (flock) by the server using DIR
//   DIR/jobs.db               job records (JobStore)
//   DIR/jobs/<id>/scene.json  the scene as submitted (scene.pbrt, scene.gltf or scene.glb
//                             when it was one of those: see sceneFileNameFor), plus its assets
//   DIR/jobs/<id>/image.png   final images (and image.exr), written when the job finishes
//   DIR/jobs/<id>/checkpoint.bin  the running render's state, while there is one
//   DIR/jobs/<id>/job.log     what happened to the job, one timestamped line an event
//   DIR/tmp/                  uploads being staged; renamed into jobs/ once accepted
#pragma once
#include <filesystem>
#include <optional>
#include <string>
#include <vector>
#include "image_format.h"

namespace photon::server {

class JobFolders {
public:
    // Creates the folders and locks the data directory (DIR/lock) for this process; throws
    // if another server holds it. Discards staging folders an earlier run left behind.
    explicit JobFolders(std::filesystem::path dataDir);
    ~JobFolders();
    JobFolders(const JobFolders&) = delete;
    JobFolders& operator=(const JobFolders&) = delete;

    std::filesystem::path databaseFile() const { return root_ / "jobs.db"; }
    std::filesystem::path jobDir(const std::string& id) const { return root_ / "jobs" / id; }
    // Where the render farm workers this server runs unpack the scenes they render.
    std::filesystem::path farmScratchDir() const { return root_ / "farm-scratch"; }
    // The job's scene file, whichever of sceneFileNames() its folder holds.
    std::filesystem::path sceneFile(const std::string& id) const;
    // The names a job's scene is stored under, one a kind of scene file the service
    // accepts: photon's JSON, and the pbrt-v4 and glTF files the engine imports. The name
    // keeps the uploaded file's extension, which is how the engine tells the kinds apart.
    static const std::vector<std::string>& sceneFileNames();
    // The name for an uploaded scene file called `uploaded` (by its extension, in any case;
    // none or no name at all: JSON), or nullopt for an extension the service does not take.
    static std::optional<std::string> sceneFileNameFor(const std::string& uploaded);
    // "a .json, .pbrt, .gltf or .glb file": the kinds, for messages.
    static std::string acceptedSceneFiles();
    // The running render's saved state (engine checkpoint bytes), while there is one.
    std::filesystem::path checkpointFile(const std::string& id) const { return jobDir(id) / "checkpoint.bin"; }
    std::filesystem::path imageFile(const std::string& id, ImageFormat format) const;
    std::filesystem::path logFile(const std::string& id) const { return jobDir(id) / "job.log"; }
    // An earlier pass kept for comparison (EXR with every layer), and the passes kept.
    std::filesystem::path keptPassFile(const std::string& id, int pass) const;
    std::vector<int> keptPasses(const std::string& id) const;
    // The job's progress over its passes (progress_history.h).
    std::filesystem::path progressFile(const std::string& id) const { return jobDir(id) / "progress.txt"; }
    // A name (relative to a job folder, in normal form) that is one of the service's own
    // files above (any of the scene file names), or their temporary copies ("image.png.tmp"): never an asset's.
    static bool isServiceFile(const std::string& name);

    // A new, empty, uniquely named folder on the same file system as jobs/, so that
    // committing it is an atomic rename.
    std::filesystem::path newStagingDir() const;
    void commit(const std::filesystem::path& stagingDir, const std::string& id) const;
    void remove(const std::string& id) const;

private:
    std::filesystem::path root_;
    int lockFd_ = -1;
};

// Writes through a temporary file and a rename: readers see the old file or the whole new one.
void writeFileAtomically(const std::filesystem::path& file, const std::string& bytes);
std::optional<std::string> readWholeFile(const std::filesystem::path& file);

}  // namespace photon::server
