#include "staged_upload.h"
#include <array>
#include "errors.h"

namespace photon::server {

namespace fs = std::filesystem;

namespace {

// Files the service itself keeps in a job folder.
constexpr std::array<const char*, 3> kReserved{"scene.json", "image.png", "image.exr"};
constexpr size_t kMaxNameLength = 1024;
constexpr size_t kMaxPartLength = 255;  // NAME_MAX of Linux file systems

// Symlinks cannot exist in a fresh staging folder, but resolve anyway: a mistake elsewhere
// must not turn into a write outside the data directory.
bool staysInside(const fs::path& folder, const fs::path& file) {
    std::error_code ec;
    fs::path root = fs::weakly_canonical(folder, ec);
    if (ec) return false;
    fs::path target = fs::weakly_canonical(file, ec);
    if (ec) return false;
    fs::path rel = target.lexically_relative(root);
    return !rel.empty() && *rel.begin() != ".." && *rel.begin() != ".";
}

// "a" and "a/b" cannot both be files: the second would fail to be created.
bool clashesWithFolder(const std::set<std::string>& names, const std::string& normal) {
    for (fs::path folder = fs::path(normal).parent_path(); !folder.empty(); folder = folder.parent_path())
        if (names.count(folder.generic_string())) return true;
    auto inside = names.lower_bound(normal + "/");
    return inside != names.end() && inside->rfind(normal + "/", 0) == 0;
}

}  // namespace

std::optional<std::string> assetNameProblem(const std::string& name) {
    if (name.empty()) return "asset name is empty";
    if (name.size() > kMaxNameLength) return "asset name is too long";
    if (name.find('\0') != std::string::npos) return "asset name contains NUL";
    if (name.find('\\') != std::string::npos) return "asset name contains a backslash";
    fs::path p(name);
    if (p.is_absolute() || p.has_root_path()) return "asset name must be a relative path";
    for (const fs::path& part : p) {
        if (part == "..") return "asset name must not contain \"..\"";
        if (part.native().size() > kMaxPartLength) return "asset name has a part longer than 255 bytes";
    }
    fs::path normal = p.lexically_normal();
    if (normal.empty() || !normal.has_filename() || normal == ".") return "asset name must name a file";
    for (const char* reserved : kReserved)
        if (normal == reserved) return std::string("asset name \"") + reserved + "\" is reserved";
    return std::nullopt;
}

StagedUpload::StagedUpload(fs::path dir, size_t maxAssetBytes) : dir_(std::move(dir)), maxAssetBytes_(maxAssetBytes) {}

StagedUpload::~StagedUpload() {
    if (asset_.is_open()) asset_.close();
    if (committed_) return;
    std::error_code ignored;
    fs::remove_all(dir_, ignored);
}

void StagedUpload::beginAsset(const std::string& name) {
    endAsset();
    if (auto problem = assetNameProblem(name)) throw ServiceError(ErrorKind::BadRequest, *problem + ": " + name);
    std::string normal = fs::path(name).lexically_normal().generic_string();
    if (clashesWithFolder(names_, normal))
        throw ServiceError(ErrorKind::BadRequest, "asset name is both a file and a folder: " + name);
    if (!names_.insert(normal).second) throw ServiceError(ErrorKind::BadRequest, "asset uploaded twice: " + name);
    fs::path file = dir_ / normal;
    if (!staysInside(dir_, file))
        throw ServiceError(ErrorKind::BadRequest, "asset name leaves the job folder: " + name);
    fs::create_directories(file.parent_path());
    asset_.open(file, std::ios::binary | std::ios::trunc);
    if (!asset_) throw std::runtime_error("cannot create " + file.string());
    assetName_ = name;
    assetBytes_ = 0;
}

void StagedUpload::appendAsset(const char* data, size_t size) {
    if (!asset_.is_open()) return;
    assetBytes_ += size;
    if (assetBytes_ > maxAssetBytes_)
        throw ServiceError(ErrorKind::LimitExceeded, "asset " + assetName_ + " is larger than " +
                                                         std::to_string(maxAssetBytes_) + " bytes");
    if (!asset_.write(data, std::streamsize(size))) throw std::runtime_error("cannot write asset " + assetName_);
}

void StagedUpload::endAsset() {
    if (!asset_.is_open()) return;
    asset_.close();
    if (asset_.fail()) throw std::runtime_error("cannot write asset " + assetName_);
}

}  // namespace photon::server
