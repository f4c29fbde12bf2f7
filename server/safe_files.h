// Writing files under the data directory without trusting what is already there: new files
// are created exclusively (O_EXCL) and never through a symlink (O_NOFOLLOW), parent folders
// are made and entered one component at a time relative to an open folder (openat), so no
// symlink or planted file anywhere on the way can redirect a write. Storage faults (a full
// disk, a read-only file system) become ServiceErrors a client can understand.
#pragma once
#include <cstddef>
#include <filesystem>
#include <string>

namespace photon::server {

// ENOSPC/EDQUOT -> ServiceError(StorageFull), EROFS -> ServiceError(Unavailable), anything
// else -> std::runtime_error; the message names `what` and the system's reason.
[[noreturn]] void throwStorageError(const std::string& what, int err);

// Runs fn(); filesystem and SQLite failures caused by a full disk or a read-only file
// system are rethrown through throwStorageError, everything else unchanged.
template <typename Fn>
auto guardStorage(const std::string& what, Fn&& fn) -> decltype(fn());
[[noreturn]] void rethrowStorageError(const std::string& what);  // inside a catch block

// A file created exclusively inside a folder, written through its descriptor.
class NewFile {
public:
    // Creates `folder/relative` ("a/b/c.obj"): missing parent folders are created; an
    // existing file, or a symlink or non-folder anywhere along the path, is refused with
    // ServiceError(BadRequest). `relative` must already be a checked relative name.
    NewFile(const std::filesystem::path& folder, const std::string& relative);
    // Creates `file` itself exclusively (its folder is trusted: the service made it).
    explicit NewFile(const std::filesystem::path& file);
    ~NewFile();
    NewFile(const NewFile&) = delete;
    NewFile& operator=(const NewFile&) = delete;

    void write(const char* data, size_t size);
    // Flushes to the disk and closes; throws on failure (a full disk may only show here).
    void close();
    bool isOpen() const { return fd_ >= 0; }

private:
    int fd_ = -1;
    std::string name_;
};

template <typename Fn>
auto guardStorage(const std::string& what, Fn&& fn) -> decltype(fn()) {
    try {
        return fn();
    } catch (...) {
        rethrowStorageError(what);
    }
}

}  // namespace photon::server
