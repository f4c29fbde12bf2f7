// An upload being received: asset files streamed into a private staging folder inside the
// data directory, and the scene text. Nothing is visible under jobs/ until the service
// accepts the scene and renames the folder into place; a rejected upload leaves nothing.
#pragma once
#include <cstddef>
#include <filesystem>
#include <memory>
#include <optional>
#include <map>
#include <string>
#include <vector>
#include "safe_files.h"

namespace photon::server {

// Why `name` (a client-chosen asset path such as "meshes/x.obj") may not be stored under a
// job folder: absolute (a leading "/" or a drive letter), "..", backslashes, NUL or other
// control characters, too long (512 bytes, 255 a component), too deep (16 components),
// reserved names. nullopt if acceptable.
std::optional<std::string> assetNameProblem(const std::string& name);

class StagedUpload {
public:
    StagedUpload(std::filesystem::path dir, size_t maxAssetBytes);
    ~StagedUpload();  // removes the staging folder unless it was committed
    StagedUpload(const StagedUpload&) = delete;
    StagedUpload& operator=(const StagedUpload&) = delete;

    // Starts a new asset file from the multipart part `part` with file name `name`; throws
    // ServiceError (BadRequest, naming the part) for unsafe or repeated names and for paths
    // through a symlink.
    void beginAsset(const std::string& part, const std::string& name);
    // Throws ServiceError (LimitExceeded) once the asset exceeds the size limit.
    void appendAsset(const char* data, size_t size);
    void endAsset();

    // Removes the assets whose names (in normal form) are not in `used` (sorted); returns
    // their names.
    std::vector<std::string> keepOnly(const std::vector<std::string>& used);
    // Bytes of the scene and the assets kept.
    int64_t storedBytes() const;

    // The scene file's bytes as received (binary for a .glb), and the name it is stored
    // under in the job folder (JobFolders::sceneFileNameFor).
    std::string& sceneText() { return sceneText_; }
    const std::string& sceneFileName() const { return sceneFileName_; }
    void setSceneFileName(std::string name) { sceneFileName_ = std::move(name); }
    const std::filesystem::path& dir() const { return dir_; }
    // The folder was renamed into place: do not remove it.
    void markCommitted() { committed_ = true; }

private:
    std::filesystem::path dir_;
    size_t maxAssetBytes_;
    std::unique_ptr<NewFile> asset_;
    std::string assetName_, assetNormal_;
    size_t assetBytes_ = 0;
    std::map<std::string, int64_t> names_;  // assets by name in normal form: their bytes
    std::string sceneText_;
    std::string sceneFileName_;  // JSON unless set
    bool committed_ = false;
};

}  // namespace photon::server
