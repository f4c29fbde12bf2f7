#include "safe_files.h"
#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>
#include <cerrno>
#include <cstring>
#include <stdexcept>
#include <vector>
#include "errors.h"
#include "sqlite.h"

namespace photon::server {

namespace fs = std::filesystem;

namespace {

// Closes a descriptor when it leaves scope.
struct Fd {
    int fd;
    explicit Fd(int f) : fd(f) {}
    ~Fd() {
        if (fd >= 0) ::close(fd);
    }
    Fd(const Fd&) = delete;
    Fd& operator=(const Fd&) = delete;
};

[[noreturn]] void refuse(const std::string& relative, const std::string& why) {
    throw ServiceError(ErrorKind::BadRequest, "asset " + relative + ": " + why);
}

// Opens `name` inside `dir` as a folder, creating it if missing, never following a symlink.
int enterFolder(int dir, const std::string& name, const std::string& relative) {
    if (::mkdirat(dir, name.c_str(), 0755) != 0 && errno != EEXIST)
        throwStorageError("creating the folder of " + relative, errno);
    int fd = ::openat(dir, name.c_str(), O_RDONLY | O_DIRECTORY | O_NOFOLLOW | O_CLOEXEC);
    if (fd >= 0) return fd;
    if (errno == ELOOP || errno == ENOTDIR) refuse(relative, "a folder on its path is a symlink or a file");
    throwStorageError("opening the folder of " + relative, errno);
}

constexpr int kCreateFlags = O_WRONLY | O_CREAT | O_EXCL | O_NOFOLLOW | O_CLOEXEC;

}  // namespace

void throwStorageError(const std::string& what, int err) {
    if (err == ENOSPC || err == EDQUOT)
        throw ServiceError(ErrorKind::StorageFull, "no space left on the data directory's disk (" + what + ")");
    if (err == EROFS) throw ServiceError(ErrorKind::Unavailable, "the data directory is read-only (" + what + ")");
    throw std::runtime_error(what + ": " + std::strerror(err));
}

[[noreturn]] void rethrowStorageError(const std::string& what) {
    try {
        throw;
    } catch (const fs::filesystem_error& e) {
        throwStorageError(what, e.code().value());
    } catch (const sql::Error& e) {
        if (e.diskFull()) throwStorageError(what, ENOSPC);
        if (e.readOnly()) throwStorageError(what, EROFS);
        throw;
    }
}

NewFile::NewFile(const fs::path& folder, const std::string& relative) : name_(relative) {
    Fd dir(::open(folder.c_str(), O_RDONLY | O_DIRECTORY | O_NOFOLLOW | O_CLOEXEC));
    if (dir.fd < 0) throwStorageError("opening the upload folder", errno);
    fs::path rel(relative);
    std::vector<std::string> parts;
    for (const fs::path& part : rel) parts.push_back(part.string());
    for (size_t i = 0; i + 1 < parts.size(); ++i) {
        int next = enterFolder(dir.fd, parts[i], relative);
        ::close(dir.fd);
        dir.fd = next;
    }
    fd_ = ::openat(dir.fd, parts.back().c_str(), kCreateFlags, 0644);
    if (fd_ >= 0) return;
    if (errno == EEXIST || errno == ELOOP) refuse(relative, "a file or symlink of that name already exists");
    throwStorageError("creating " + relative, errno);
}

// Messages reach clients: they name the file, not the server's folders.
NewFile::NewFile(const fs::path& file) : name_(file.filename().string()) {
    fd_ = ::open(file.c_str(), kCreateFlags, 0644);
    if (fd_ < 0) throwStorageError("creating " + name_, errno);
}

NewFile::~NewFile() {
    if (fd_ >= 0) ::close(fd_);
}

void NewFile::write(const char* data, size_t size) {
    while (size > 0) {
        ssize_t n = ::write(fd_, data, size);
        if (n < 0 && errno == EINTR) continue;
        if (n < 0) throwStorageError("writing " + name_, errno);
        data += n;
        size -= size_t(n);
    }
}

void NewFile::close() {
    if (fd_ < 0) return;
    int fd = fd_;
    fd_ = -1;
    bool synced = ::fdatasync(fd) == 0;
    int err = errno;
    if (::close(fd) != 0 && synced) {
        synced = false;
        err = errno;
    }
    if (!synced) throwStorageError("writing " + name_, err);
}

}  // namespace photon::server
