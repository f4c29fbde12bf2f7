#include "staged_upload.h"
#include <algorithm>
#include <array>
#include <cctype>
#include "errors.h"
#include "job_folders.h"
#include "service_limits.h"

namespace photon::server {

namespace fs = std::filesystem;

namespace {

constexpr size_t kMaxNameLength = 512;
constexpr size_t kMaxComponentLength = 255;  // NAME_MAX on Linux file systems
constexpr int kMaxComponents = 16;

bool isControl(char c) { return static_cast<unsigned char>(c) < 0x20 || c == 0x7f; }

// "C:..." names a drive on Windows: a client on one must not think it wrote there.
bool hasDriveLetter(const std::string& name) {
    return name.size() >= 2 && name[1] == ':' && std::isalpha(static_cast<unsigned char>(name[0]));
}

// "a" and "a/b" cannot both be files: the second would fail to be created.
bool clashesWithFolder(const std::map<std::string, int64_t>& names, const std::string& normal) {
    for (fs::path folder = fs::path(normal).parent_path(); !folder.empty(); folder = folder.parent_path())
        if (names.count(folder.generic_string())) return true;
    auto inside = names.lower_bound(normal + "/");  // the first name that could be inside
    return inside != names.end() && inside->first.rfind(normal + "/", 0) == 0;
}

}  // namespace

std::optional<std::string> assetNameProblem(const std::string& name) {
    if (name.empty()) return "asset name is empty";
    if (name.size() > kMaxNameLength)
        return "asset name is " + std::to_string(name.size()) + " bytes, longer than " +
               std::to_string(kMaxNameLength);
    if (name.find('\0') != std::string::npos) return "asset name contains NUL";
    if (name.find('\\') != std::string::npos) return "asset name contains a backslash";
    for (char c : name)
        if (isControl(c)) return "asset name contains a control character";
    if (hasDriveLetter(name)) return "asset name must not start with a drive letter";
    fs::path p(name);
    if (p.is_absolute() || p.has_root_path()) return "asset name must be a relative path";
    int components = 0;
    for (const fs::path& part : p) {
        if (part == "..") return "asset name must not contain \"..\"";
        if (part.native().size() > kMaxComponentLength)
            return "asset name has a component longer than " + std::to_string(kMaxComponentLength) + " bytes";
        ++components;
    }
    if (components > kMaxComponents)
        return "asset name has " + std::to_string(components) + " path components, more than " +
               std::to_string(kMaxComponents);
    fs::path normal = p.lexically_normal();
    if (normal.empty() || !normal.has_filename() || normal == ".") return "asset name must name a file";
    if (JobFolders::isServiceFile(normal.generic_string()))
        return "asset name \"" + normal.generic_string() + "\" is reserved";
    return std::nullopt;
}

StagedUpload::StagedUpload(fs::path dir, size_t maxAssetBytes)
    : dir_(std::move(dir)), maxAssetBytes_(maxAssetBytes), sceneFileName_(JobFolders::sceneFileNames().front()) {}

StagedUpload::~StagedUpload() {
    asset_.reset();
    if (committed_) return;
    std::error_code ignored;
    fs::remove_all(dir_, ignored);
}

void StagedUpload::beginAsset(const std::string& part, const std::string& name) {
    endAsset();
    const std::string where = "part \"" + part + "\" (file name \"" + name + "\")";
    if (auto problem = assetNameProblem(name)) throw ServiceError(ErrorKind::BadRequest, *problem + ": " + where);
    std::string normal = fs::path(name).lexically_normal().generic_string();
    if (clashesWithFolder(names_, normal))
        throw ServiceError(ErrorKind::BadRequest, "asset name is both a file and a folder: " + where);
    if (!names_.emplace(normal, 0).second) throw ServiceError(ErrorKind::BadRequest, "asset uploaded twice: " + where);
    // Created relative to the staging folder, one component at a time, never through a
    // symlink and never over an existing file.
    asset_ = std::make_unique<NewFile>(dir_, normal);
    assetName_ = name;
    assetNormal_ = normal;
    assetBytes_ = 0;
}

void StagedUpload::appendAsset(const char* data, size_t size) {
    if (!asset_) return;
    assetBytes_ += size;
    if (assetBytes_ > maxAssetBytes_)
        throw ServiceError(ErrorKind::LimitExceeded, "asset " + assetName_ + " is larger than the server limit of " +
                                                         std::to_string(maxAssetBytes_) + " bytes (" +
                                                         optionOf(&Limits::maxAssetBytes) + ")");
    asset_->write(data, size);
}

void StagedUpload::endAsset() {
    if (!asset_) return;
    std::unique_ptr<NewFile> done = std::move(asset_);
    done->close();
    names_[assetNormal_] = int64_t(assetBytes_);
}

std::vector<std::string> StagedUpload::keepOnly(const std::vector<std::string>& used) {
    endAsset();
    std::vector<std::string> dropped;
    for (auto it = names_.begin(); it != names_.end();) {
        if (std::binary_search(used.begin(), used.end(), it->first)) {
            ++it;
            continue;
        }
        dropped.push_back(it->first);
        std::error_code ec;
        fs::remove(dir_ / it->first, ec);
        it = names_.erase(it);
    }
    return dropped;
}

int64_t StagedUpload::storedBytes() const {
    int64_t total = int64_t(sceneText_.size());
    for (const auto& [name, bytes] : names_) total += bytes;
    return total;
}

}  // namespace photon::server
