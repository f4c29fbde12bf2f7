#include "job_log.h"
#include <fcntl.h>
#include <unistd.h>
#include <cstdint>
#include "clock.h"

namespace photon::server {

void appendJobLog(const std::filesystem::path& file, const std::string& line) {
    // O_NOFOLLOW: the job folder holds client files; the log is never written through a link.
    int fd = ::open(file.c_str(), O_WRONLY | O_APPEND | O_CREAT | O_CLOEXEC | O_NOFOLLOW, 0644);
    if (fd < 0) return;
    off_t size = ::lseek(fd, 0, SEEK_END);
    if (size >= 0 && std::uintmax_t(size) < kMaxJobLogBytes) {
        std::string text = utcNowIso8601() + " " + line + "\n";
        [[maybe_unused]] ssize_t written = ::write(fd, text.data(), text.size());  // one write: one whole line
    }
    ::close(fd);
}

}  // namespace photon::server
