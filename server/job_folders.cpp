#include "job_folders.h"
#include <fcntl.h>
#include <sys/file.h>
#include <unistd.h>
#include <fstream>
#include <sstream>
#include <stdexcept>
#include "clock.h"

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

fs::path JobFolders::newStagingDir() const {
    for (;;) {
        fs::path dir = root_ / "tmp" / ("upload-" + randomJobId());
        if (fs::create_directory(dir)) return dir;  // false: the name exists, try another
    }
}

void JobFolders::commit(const fs::path& stagingDir, const std::string& id) const {
    fs::rename(stagingDir, jobDir(id));
}

void JobFolders::remove(const std::string& id) const {
    std::error_code ignored;  // a folder already gone is what we want anyway
    fs::remove_all(jobDir(id), ignored);
}

void writeFileAtomically(const fs::path& file, const std::string& bytes) {
    fs::path temp = file;
    temp += ".tmp";
    {
        std::ofstream out(temp, std::ios::binary | std::ios::trunc);
        out.write(bytes.data(), std::streamsize(bytes.size()));
        if (!out.flush()) throw std::runtime_error("cannot write " + temp.string());
    }
    fs::rename(temp, file);
}

std::optional<std::string> readWholeFile(const fs::path& file) {
    std::ifstream in(file, std::ios::binary);
    if (!in) return std::nullopt;
    std::ostringstream bytes;
    bytes << in.rdbuf();
    return std::move(bytes).str();
}

}  // namespace photon::server
