// Storage faults: with the data directory's disk full or its file system read-only, a
// submission is refused with 507 or 503 and a clear message, a running job fails with the
// reason, the server keeps answering, and what was stored before is untouched. The faults
// are real file systems (a 4 MiB tmpfs, a read-only bind mount), so the tests need the
// right to mount (root); without it they skip.
#include <fcntl.h>
#include <sys/mount.h>
#include <unistd.h>
#include <cerrno>
#include <cstring>
#include <fstream>
#include "server_fixture.h"

namespace photon::test {
namespace {

namespace fs = std::filesystem;

std::string fileBytes(const fs::path& file) {
    std::ifstream in(file, std::ios::binary);
    return std::string((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
}

class FaultsTest : public ServerTest {
protected:
    void TearDown() override {
        ServerTest::stopServer();
        for (auto it = mounts_.rbegin(); it != mounts_.rend(); ++it)
            if (::umount2(it->c_str(), 0) != 0) ::umount2(it->c_str(), MNT_DETACH);
        ServerTest::TearDown();
    }
    // False (and the reason in `why_`) if this environment may not mount.
    bool mountOk(const char* source, const fs::path& target, const char* type, unsigned long flags,
                 const char* options) {
        if (::mount(source, target.c_str(), type, flags, options) != 0) {
            why_ = std::string("mounting is not permitted here (") + std::strerror(errno) +
                   "); the fault tests need root or CAP_SYS_ADMIN";
            return false;
        }
        if (!(flags & MS_REMOUNT)) mounts_.push_back(target);
        return true;
    }
    // Makes `folder` read-only through a bind mount of itself.
    bool makeReadOnly(const fs::path& folder) {
        return mountOk(folder.c_str(), folder, nullptr, MS_BIND, nullptr) &&
               mountOk(nullptr, folder, nullptr, MS_REMOUNT | MS_BIND | MS_RDONLY, nullptr);
    }

    // A completed job and what the server and the disk hold for it.
    struct Stored {
        std::string id;
        json record;
        std::string png, exr;
    };
    Stored completeAJob() {
        Stored s;
        s.id = submitOk(smallScene(2, 1000, 16));
        s.record = waitForStatus(s.id, "completed");
        EXPECT_EQ(s.record["status"], "completed");
        s.png = client().Get(("/api/v1/jobs/" + s.id + "/image?format=png").c_str())->body;
        s.exr = fileBytes(dataDir() / "jobs" / s.id / "image.exr");
        return s;
    }
    // The server still answers and still has `s` exactly as before.
    void expectIntact(const Stored& s) {
        EXPECT_EQ(client().Get("/api/v1/health")->status, 200);
        httplib::Result list = client().Get("/api/v1/jobs?status=completed");
        ASSERT_TRUE(list);
        ASSERT_EQ(list->status, 200);
        json listed, page = json::parse(list->body);
        for (const json& job : page["jobs"])
            if (job["id"] == s.id) listed = job;
        EXPECT_EQ(listed, s.record);
        EXPECT_EQ(getJob(s.id), s.record);
        EXPECT_EQ(client().Get(("/api/v1/jobs/" + s.id + "/image?format=png").c_str())->body, s.png);
        EXPECT_EQ(fileBytes(dataDir() / "jobs" / s.id / "image.png"), s.png);
        EXPECT_EQ(fileBytes(dataDir() / "jobs" / s.id / "image.exr"), s.exr);
        EXPECT_FALSE(s.png.empty());
    }
    // Writes to `file` until the disk refuses; returns the bytes written.
    static size_t fillDisk(const fs::path& file) {
        int fd = ::open(file.c_str(), O_WRONLY | O_CREAT | O_TRUNC | O_CLOEXEC, 0644);
        std::vector<char> block(64 << 10, 'x');
        size_t total = 0;
        for (;;) {
            ssize_t n = ::write(fd, block.data(), block.size());
            if (n <= 0) break;
            total += size_t(n);
        }
        ::close(fd);
        return total;
    }

    std::vector<fs::path> mounts_;
    std::string why_;
};

TEST_F(FaultsTest, AFullDiskRefusesSubmissionsFailsRendersAndKeepsWhatIsStored) {
    if (!mountOk("tmpfs", dataDir(), "tmpfs", 0, "size=4m")) GTEST_SKIP() << why_;
    startServer({"--workers", "1", "--checkpoint-seconds", "1"});
    Stored before = completeAJob();
    std::string running = submitOk(longScene());
    waitFor(running, [](const json& j) { return j["pass"].get<int>() >= 1; });
    EXPECT_GT(fillDisk(dataDir() / "filler"), 0u);

    httplib::Result r = submit(smallScene());
    ASSERT_TRUE(r);
    EXPECT_EQ(r->status, 507) << r->body;
    // The upload fails at its first write that finds no room: the scene file, or, when the
    // running render has just released a few blocks of a pass it could not keep, the
    // database's record of the job. Either way nothing of it stays (checked below).
    const std::string error = json::parse(r->body)["error"];
    EXPECT_TRUE(error == "no space left on the data directory's disk (writing scene.json.tmp)" ||
                error == "no space left on the data directory's disk (recording the job)")
        << error;
    // The render's next checkpoint cannot be written: the job fails and says why.
    json failed = waitForStatus(running, "failed");
    EXPECT_EQ(failed["status"], "failed");
    EXPECT_EQ(failed["error"], "no space left on the data directory's disk (writing checkpoint.bin.tmp)");
    expectIntact(before);
    EXPECT_TRUE(fs::is_empty(dataDir() / "tmp"));  // the refused upload left nothing behind
    EXPECT_EQ(std::distance(fs::directory_iterator(dataDir() / "jobs"), fs::directory_iterator()), 2);

    // Room again: the server takes jobs again without a restart.
    fs::remove(dataDir() / "filler");
    std::string after = submitOk(smallScene(2, 1000, 16));
    EXPECT_EQ(waitForStatus(after, "completed")["status"], "completed");
    expectIntact(before);
}

TEST_F(FaultsTest, AReadOnlyDataDirectoryRefusesSubmissionsAndKeepsServing) {
    startServer({"--workers", "1"});
    Stored before = completeAJob();
    // The job folders and the upload area turn read-only under the running server. (The
    // database file stays writable: a file system cannot be remounted read-only while
    // SQLite holds files on it open for writing.)
    if (!makeReadOnly(dataDir() / "jobs") || !makeReadOnly(dataDir() / "tmp")) GTEST_SKIP() << why_;

    httplib::Result r = submit(smallScene());
    ASSERT_TRUE(r);
    EXPECT_EQ(r->status, 503) << r->body;
    EXPECT_EQ(json::parse(r->body)["error"], "the data directory is read-only (creating an upload folder)");
    EXPECT_EQ(r->get_header_value("Retry-After"), "5");
    expectIntact(before);

    // Writable again: the server takes jobs again without a restart.
    for (const fs::path& m : mounts_) ASSERT_EQ(::umount2(m.c_str(), 0), 0) << std::strerror(errno);
    mounts_.clear();
    std::string after = submitOk(smallScene(2, 1000, 16));
    EXPECT_EQ(waitForStatus(after, "completed")["status"], "completed");
    expectIntact(before);
}

}  // namespace
}  // namespace photon::test
