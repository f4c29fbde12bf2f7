#include "job_folders.h"
#include <fcntl.h>
#include <sys/file.h>
#include <sys/stat.h>
#include <unistd.h>
#include <algorithm>
#include <cctype>
#include <cerrno>
#include <cstdio>
#include <fstream>
#include <sstream>
#include <stdexcept>
#include "clock.h"
#include "safe_files.h"

namespace photon::server {

namespace fs = std::filesystem;

namespace {

// Two servers on one data directory would delete each other's uploads and race on the
// database; the lock makes the second one refuse to start.
int lockDataDir(const fs::path& root) {
    fs::path file = root / "lock";
    int fd = ::open(file.c_str(), O_RDWR | O_CREAT | O_CLOEXEC, 0644);
    if (fd < 0) throw std::runtime_error("cannot open " + file.string());
    if (::flock(fd, LOCK_EX | LOCK_NB) != 0) {
        ::close(fd);
        throw std::runtime_error("data directory " + root.string() + " is in use by another photon-server");
    }
    return fd;
}

}  // namespace

JobFolders::JobFolders(fs::path dataDir) : root_(fs::absolute(std::move(dataDir))) {
    fs::create_directories(root_ / "jobs");
    lockFd_ = lockDataDir(root_);
    std::error_code ignored;
    fs::remove_all(root_ / "tmp", ignored);  // half-received uploads of a previous run
    fs::create_directories(root_ / "tmp");
}

JobFolders::~JobFolders() {
    if (lockFd_ >= 0) ::close(lockFd_);
}

fs::path JobFolders::imageFile(const std::string& id, ImageFormat format) const {
    return jobDir(id) / (std::string("image.") + toString(format));
}

const std::vector<std::string>& JobFolders::sceneFileNames() {
    static const std::vector<std::string> names{"scene.json", "scene.pbrt", "scene.gltf", "scene.glb"};
    return names;
}

std::optional<std::string> JobFolders::sceneFileNameFor(const std::string& uploaded) {
    std::string extension = fs::path(uploaded).extension().string();
    if (extension.empty()) return sceneFileNames().front();
    std::transform(extension.begin(), extension.end(), extension.begin(),
                   [](unsigned char c) { return char(std::tolower(c)); });
    for (const std::string& name : sceneFileNames())
        if (fs::path(name).extension() == extension) return name;
    return std::nullopt;
}

std::string JobFolders::acceptedSceneFiles() {
    const std::vector<std::string>& names = sceneFileNames();
    std::string text = "a ";
    for (size_t i = 0; i < names.size(); ++i) {
        if (i > 0) text += i + 1 == names.size() ? " or " : ", ";
        text += fs::path(names[i]).extension().string();
    }
    return text + " file";
}

fs::path JobFolders::sceneFile(const std::string& id) const {
    const fs::path dir = jobDir(id);
    std::error_code ec;
    for (const std::string& name : sceneFileNames())
        if (fs::exists(dir / name, ec)) return dir / name;
    return dir / sceneFileNames().front();
}

namespace {
constexpr const char* kKeptPassesDir = "kept-passes";
}  // namespace

fs::path JobFolders::keptPassFile(const std::string& id, int pass) const {
    return jobDir(id) / kKeptPassesDir / ("pass-" + std::to_string(pass) + ".exr");
}

std::vector<int> JobFolders::keptPasses(const std::string& id) const {
    std::vector<int> passes;
    std::error_code ec;
    for (const fs::directory_entry& e : fs::directory_iterator(jobDir(id) / kKeptPassesDir, ec)) {
        const std::string name = e.path().filename().string();
        int pass = 0;
        if (std::sscanf(name.c_str(), "pass-%d.exr", &pass) == 1 && name == "pass-" + std::to_string(pass) + ".exr")
            passes.push_back(pass);
    }
    std::sort(passes.begin(), passes.end());
    return passes;
}

bool JobFolders::isServiceFile(const std::string& name) {
    std::vector<std::string> own = sceneFileNames();
    own.insert(own.end(), {"image.png", "image.exr", "checkpoint.bin", "job.log", "progress.txt"});
    for (const std::string& file : own)
        if (name == file || name == file + ".tmp") return true;
    return name == kKeptPassesDir || name.rfind(std::string(kKeptPassesDir) + "/", 0) == 0;
}

fs::path JobFolders::newStagingDir() const {
    for (;;) {
        fs::path dir = root_ / "tmp" / ("upload-" + randomJobId());
        if (::mkdir(dir.c_str(), 0755) == 0) return dir;
        if (errno != EEXIST) throwStorageError("creating an upload folder", errno);  // EEXIST: try another name
    }
}

void JobFolders::commit(const fs::path& stagingDir, const std::string& id) const {
    if (::rename(stagingDir.c_str(), jobDir(id).c_str()) != 0) throwStorageError("storing job " + id, errno);
}

void JobFolders::remove(const std::string& id) const {
    std::error_code ignored;  // a folder already gone is what we want anyway
    fs::remove_all(jobDir(id), ignored);
}

void writeFileAtomically(const fs::path& file, const std::string& bytes) {
    fs::path temp = file;
    temp += ".tmp";
    // A crash may have left a temporary file behind; it is ours to replace.
    if (::unlink(temp.c_str()) != 0 && errno != ENOENT) throwStorageError("replacing " + temp.filename().string(), errno);
    try {
        NewFile out(temp);
        out.write(bytes.data(), bytes.size());
        out.close();
        if (::rename(temp.c_str(), file.c_str()) != 0) throwStorageError("renaming " + temp.filename().string(), errno);
    } catch (...) {
        ::unlink(temp.c_str());  // a full disk must not leave half-written files behind
        throw;
    }
}

std::optional<std::string> readWholeFile(const fs::path& file) {
    std::ifstream in(file, std::ios::binary);
    if (!in) return std::nullopt;
    std::ostringstream bytes;
    bytes << in.rdbuf();
    return std::move(bytes).str();
}

}  // namespace photon::server
