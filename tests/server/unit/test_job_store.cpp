#include <gtest/gtest.h>
#include <climits>
#include <filesystem>
#include <stdexcept>
#include <string>
#include <thread>
#include <vector>
#include <unistd.h>
#include "server/clock.h"
#include "server/job_store.h"
#include "server/sqlite.h"

using namespace photon::server;
namespace fs = std::filesystem;

namespace {

class JobStoreTest : public ::testing::Test {
protected:
    void SetUp() override {
        dir_ = fs::temp_directory_path() /
               ("photon-job-store-test-" + std::to_string(::getpid()) + "-" + randomJobId());
        ASSERT_TRUE(fs::create_directory(dir_));
    }
    void TearDown() override {
        std::error_code ec;
        fs::remove_all(dir_, ec);
    }
    fs::path dbFile() const { return dir_ / "jobs.db"; }

    fs::path dir_;
};

JobRecord newJob(const std::string& id) {
    JobRecord job;
    job.id = id;
    job.status = JobStatus::Queued;
    job.priority = 0;
    job.createdAt = "2024-05-01T09:00:00.000Z";
    job.settings = JobSettings{16, 100000, 42, "sppm", 320, 240, "", true, 0.025, true};
    job.client = "127.0.0.1";
    return job;
}

// Every field of a record, for exact comparison.
void expectSameJob(const JobRecord& actual, const JobRecord& expected) {
    EXPECT_EQ(actual.id, expected.id);
    EXPECT_EQ(actual.seq, expected.seq);
    EXPECT_EQ(actual.status, expected.status);
    EXPECT_EQ(actual.priority, expected.priority);
    EXPECT_EQ(actual.createdAt, expected.createdAt);
    EXPECT_EQ(actual.startedAt, expected.startedAt);
    EXPECT_EQ(actual.finishedAt, expected.finishedAt);
    EXPECT_EQ(actual.settings.passes, expected.settings.passes);
    EXPECT_EQ(actual.settings.photonsPerPass, expected.settings.photonsPerPass);
    EXPECT_EQ(actual.settings.seed, expected.settings.seed);
    EXPECT_EQ(actual.settings.integrator, expected.settings.integrator);
    EXPECT_EQ(actual.settings.width, expected.settings.width);
    EXPECT_EQ(actual.settings.height, expected.settings.height);
    EXPECT_EQ(actual.progress.pass, expected.progress.pass);
    EXPECT_EQ(actual.progress.photonsTraced, expected.progress.photonsTraced);
    EXPECT_EQ(actual.progress.meanRadius, expected.progress.meanRadius);
    EXPECT_EQ(actual.progress.elapsedSeconds, expected.progress.elapsedSeconds);
    EXPECT_EQ(actual.progress.etaSeconds, expected.progress.etaSeconds);
    EXPECT_EQ(actual.error, expected.error);
    EXPECT_EQ(actual.settings.camera, expected.settings.camera);
    EXPECT_EQ(actual.settings.denoise, expected.settings.denoise);
    EXPECT_EQ(actual.settings.targetError, expected.settings.targetError);
    EXPECT_EQ(actual.settings.lenient, expected.settings.lenient);
    EXPECT_EQ(actual.client, expected.client);
    EXPECT_EQ(actual.uploadBytes, expected.uploadBytes);
    EXPECT_EQ(actual.warnings, expected.warnings);
    EXPECT_EQ(actual.name, expected.name);
    EXPECT_EQ(actual.labels, expected.labels);
    EXPECT_EQ(actual.updatedAt, expected.updatedAt);
}

std::vector<std::string> ids(const std::vector<JobRecord>& jobs) {
    std::vector<std::string> out;
    for (const JobRecord& job : jobs) out.push_back(job.id);
    return out;
}

}  // namespace

TEST_F(JobStoreTest, NewStoreCreatesTheDatabaseEmpty) {
    JobStore store(dbFile());
    EXPECT_TRUE(fs::exists(dbFile()));
    EXPECT_TRUE(store.loadAll().empty());
}

TEST_F(JobStoreTest, InsertReturnsSubmissionSequenceFromOne) {
    JobStore store(dbFile());
    EXPECT_EQ(store.insert(newJob("a")), 1);
    EXPECT_EQ(store.insert(newJob("b")), 2);
    EXPECT_EQ(store.insert(newJob("c")), 3);
}

TEST_F(JobStoreTest, InsertStoresTheSubmissionFields) {
    JobRecord job = newJob("00112233aabbccdd");
    job.priority = -3;
    job.settings = JobSettings{100000, 10'000'000'000LL, 0xFEDCBA9876543210ULL, "path", 4096, 2160, "Camera.001"};
    job.client = "2001:db8::1";
    job.uploadBytes = 5'000'000'000LL;
    job.warnings = {"asset \"a.obj\" is not used by the scene and was not stored", "second warning"};
    job.name = "Atrium, final (\xc3\xa9t\xc3\xa9)";
    job.labels = {"project=atrium", "final"};
    job.updatedAt = "2026-12-01T20:00:00.000Z";
    int64_t seq;
    {
        JobStore store(dbFile());
        seq = store.insert(job);
    }
    JobStore store(dbFile());
    std::vector<JobRecord> jobs = store.loadAll();
    ASSERT_EQ(jobs.size(), 1u);
    job.seq = seq;
    expectSameJob(jobs[0], job);
}

TEST_F(JobStoreTest, InsertLeavesLaterFieldsForUpdate) {
    JobRecord job = newJob("a");
    job.startedAt = "2024-05-01T09:01:00.000Z";
    job.progress = JobProgress{3, 300, 0.5, 1.5, 2.5};
    job.error = "not yet";
    JobStore store(dbFile());
    store.insert(job);
    JobRecord loaded = store.loadAll().at(0);
    EXPECT_EQ(loaded.status, JobStatus::Queued);
    EXPECT_EQ(loaded.startedAt, "");
    EXPECT_EQ(loaded.finishedAt, "");
    EXPECT_EQ(loaded.progress.pass, 0);
    EXPECT_EQ(loaded.progress.photonsTraced, 0);
    EXPECT_EQ(loaded.progress.meanRadius, 0);
    EXPECT_EQ(loaded.error, "");
}

TEST_F(JobStoreTest, EveryFieldRoundTripsThroughInsertAndUpdate) {
    JobRecord job = newJob("ffeeddccbbaa9988");
    job.priority = INT_MAX;
    job.settings = JobSettings{7, 123456789012LL, UINT64_MAX, "sppm", 1, 65535};
    job.client = "192.168.1.20";
    {
        JobStore store(dbFile());
        job.seq = store.insert(job);
        job.status = JobStatus::Failed;
        job.startedAt = "2024-05-01T09:01:02.345Z";
        job.finishedAt = job.updatedAt = "2024-05-01T09:31:02.999Z";
        job.progress = JobProgress{6, 740'000'000'000LL, 0.1, 1234.5678, 1e-9};
        job.error = "it's \"broken\": naïve \xF0\x9F\x99\x82";
        store.update(job);
    }
    JobStore store(dbFile());
    std::vector<JobRecord> jobs = store.loadAll();
    ASSERT_EQ(jobs.size(), 1u);
    expectSameJob(jobs[0], job);
}

TEST_F(JobStoreTest, EveryStatusRoundTrips) {
    JobStore store(dbFile());
    JobRecord job = newJob("a");
    store.insert(job);
    for (JobStatus status : {JobStatus::Queued, JobStatus::Running, JobStatus::Completed, JobStatus::Failed,
                             JobStatus::Cancelled}) {
        job.status = status;
        store.update(job);
        EXPECT_EQ(store.loadAll().at(0).status, status) << toString(status);
    }
}

TEST_F(JobStoreTest, UpdateWithEmptyTextClearsIt) {
    JobStore store(dbFile());
    JobRecord job = newJob("a");
    store.insert(job);
    job.status = JobStatus::Failed;
    job.startedAt = "2024-05-01T09:01:00.000Z";
    job.finishedAt = "2024-05-01T09:02:00.000Z";
    job.error = "boom";
    store.update(job);
    job.status = JobStatus::Queued;
    job.startedAt.clear();
    job.finishedAt.clear();
    job.error.clear();
    store.update(job);
    JobRecord loaded = store.loadAll().at(0);
    EXPECT_EQ(loaded.status, JobStatus::Queued);
    EXPECT_EQ(loaded.startedAt, "");
    EXPECT_EQ(loaded.finishedAt, "");
    EXPECT_EQ(loaded.error, "");
}

// What a submission fixed stays; the priority (while queued) and the pass count (more passes
// of a completed job) may change later, and an update stores them.
TEST_F(JobStoreTest, UpdateDoesNotChangeSubmissionFields) {
    JobStore store(dbFile());
    JobRecord job = newJob("a");
    job.seq = store.insert(job);
    JobRecord changed = job;
    changed.priority = job.priority = 9;
    changed.createdAt = "2030-01-01T00:00:00.000Z";
    changed.settings = JobSettings{1, 1, 1, "path", 1, 1};
    // The settings that change later: more passes of a completed job, whose target error
    // then no longer stops it.
    job.settings.passes = 1;
    job.settings.targetError = 0;
    changed.client = "10.9.9.9";
    store.update(changed);
    expectSameJob(store.loadAll().at(0), job);
}

TEST_F(JobStoreTest, UpdateOfUnknownJobChangesNothing) {
    JobStore store(dbFile());
    JobRecord job = newJob("a");
    job.seq = store.insert(job);
    JobRecord stranger = newJob("b");
    stranger.status = JobStatus::Completed;
    EXPECT_NO_THROW(store.update(stranger));
    std::vector<JobRecord> jobs = store.loadAll();
    ASSERT_EQ(jobs.size(), 1u);
    expectSameJob(jobs[0], job);
}

TEST_F(JobStoreTest, UpdateAffectsOnlyItsJob) {
    JobStore store(dbFile());
    JobRecord a = newJob("a");
    JobRecord b = newJob("b");
    a.seq = store.insert(a);
    b.seq = store.insert(b);
    b.status = JobStatus::Running;
    b.startedAt = "2024-05-01T09:05:00.000Z";
    store.update(b);
    std::vector<JobRecord> jobs = store.loadAll();
    ASSERT_EQ(jobs.size(), 2u);
    expectSameJob(jobs[0], a);
    expectSameJob(jobs[1], b);
}

TEST_F(JobStoreTest, LoadAllIsInSubmissionOrder) {
    JobStore store(dbFile());
    for (const char* id : {"c", "a", "d", "b"}) store.insert(newJob(id));
    std::vector<JobRecord> jobs = store.loadAll();
    EXPECT_EQ(ids(jobs), (std::vector<std::string>{"c", "a", "d", "b"}));
    for (size_t i = 0; i < jobs.size(); ++i) EXPECT_EQ(jobs[i].seq, int64_t(i + 1));
}

TEST_F(JobStoreTest, RemoveDeletesOnlyThatJob) {
    JobStore store(dbFile());
    store.insert(newJob("a"));
    store.insert(newJob("b"));
    store.insert(newJob("c"));
    store.remove("b");
    EXPECT_EQ(ids(store.loadAll()), (std::vector<std::string>{"a", "c"}));
}

TEST_F(JobStoreTest, RemoveOfUnknownJobChangesNothing) {
    JobStore store(dbFile());
    store.insert(newJob("a"));
    EXPECT_NO_THROW(store.remove("nope"));
    EXPECT_EQ(ids(store.loadAll()), (std::vector<std::string>{"a"}));
}

TEST_F(JobStoreTest, InsertOfDuplicateIdThrowsAndKeepsTheFirst) {
    JobStore store(dbFile());
    JobRecord first = newJob("a");
    first.seq = store.insert(first);
    JobRecord second = newJob("a");
    second.priority = 7;
    EXPECT_THROW(store.insert(second), sql::Error);
    std::vector<JobRecord> jobs = store.loadAll();
    ASSERT_EQ(jobs.size(), 1u);
    expectSameJob(jobs[0], first);
    // The failed insert left no transaction open: the store keeps working.
    EXPECT_EQ(store.insert(newJob("b")), 2);
}

TEST_F(JobStoreTest, JobsPersistAcrossReopen) {
    std::vector<JobRecord> written;
    {
        JobStore store(dbFile());
        for (const char* id : {"a", "b"}) {
            JobRecord job = newJob(id);
            job.seq = store.insert(job);
            written.push_back(job);
        }
        written[1].status = JobStatus::Completed;
        written[1].finishedAt = "2024-05-01T10:00:00.000Z";
        store.update(written[1]);
    }
    JobStore store(dbFile());
    std::vector<JobRecord> jobs = store.loadAll();
    ASSERT_EQ(jobs.size(), 2u);
    expectSameJob(jobs[0], written[0]);
    expectSameJob(jobs[1], written[1]);
}

TEST_F(JobStoreTest, RemovalPersistsAcrossReopen) {
    {
        JobStore store(dbFile());
        store.insert(newJob("a"));
        store.insert(newJob("b"));
        store.remove("a");
    }
    JobStore store(dbFile());
    EXPECT_EQ(ids(store.loadAll()), (std::vector<std::string>{"b"}));
}

TEST_F(JobStoreTest, SequenceNumbersAreNeverReusedAfterDeleteAndReopen) {
    {
        JobStore store(dbFile());
        store.insert(newJob("a"));
        store.insert(newJob("b"));
        store.insert(newJob("c"));
        store.remove("c");
    }
    JobStore store(dbFile());
    EXPECT_EQ(store.insert(newJob("d")), 4);
}

TEST_F(JobStoreTest, UnfinishedJobsAreListedAgainAfterRestart) {
    JobRecord queued = newJob("queued");
    JobRecord running = newJob("running");
    JobRecord done = newJob("done");
    queued.priority = 2;
    {
        JobStore store(dbFile());
        queued.seq = store.insert(queued);
        running.seq = store.insert(running);
        done.seq = store.insert(done);
        running.status = JobStatus::Running;
        running.startedAt = "2024-05-01T09:10:00.000Z";
        running.progress = JobProgress{4, 400000, 0.03, 8.0, 24.0};
        store.update(running);
        done.status = JobStatus::Completed;
        done.startedAt = "2024-05-01T09:01:00.000Z";
        done.finishedAt = "2024-05-01T09:09:00.000Z";
        store.update(done);
    }  // the server stopped with a job queued and one running

    JobStore store(dbFile());
    std::vector<JobRecord> jobs = store.loadAll();
    ASSERT_EQ(jobs.size(), 3u);
    // The store reports what it was told; requeueing is the service's decision.
    expectSameJob(jobs[0], queued);
    expectSameJob(jobs[1], running);
    expectSameJob(jobs[2], done);
}

TEST_F(JobStoreTest, RequeuedRunningJobPersistsAsQueuedWithNoProgress) {
    JobRecord job = newJob("a");
    {
        JobStore store(dbFile());
        job.seq = store.insert(job);
        job.status = JobStatus::Running;
        job.startedAt = "2024-05-01T09:10:00.000Z";
        job.progress = JobProgress{4, 400000, 0.03, 8.0, 24.0};
        store.update(job);
    }
    {
        // What restart recovery writes for an interrupted render.
        JobStore store(dbFile());
        JobRecord loaded = store.loadAll().at(0);
        loaded.status = JobStatus::Queued;
        loaded.startedAt.clear();
        loaded.progress = JobProgress{};
        store.update(loaded);
    }
    JobStore store(dbFile());
    JobRecord loaded = store.loadAll().at(0);
    job.status = JobStatus::Queued;
    job.startedAt.clear();
    job.progress = JobProgress{};
    expectSameJob(loaded, job);
}

TEST_F(JobStoreTest, UnknownStatusFromANewerServerLoadsAsFailed) {
    {
        JobStore store(dbFile());
        store.insert(newJob("a"));
    }
    {
        sql::Database db(dbFile());
        db.exec("UPDATE jobs SET status = 'hibernating'");
    }
    JobStore store(dbFile());
    EXPECT_EQ(store.loadAll().at(0).status, JobStatus::Failed);
}

TEST_F(JobStoreTest, RefusesADatabaseOfANewerSchemaVersion) {
    { JobStore store(dbFile()); }
    {
        sql::Database db(dbFile());
        db.exec("PRAGMA user_version = 8");
    }
    try {
        JobStore store(dbFile());
        FAIL() << "opened a version 8 database";
    } catch (const std::runtime_error& e) {
        EXPECT_NE(std::string(e.what()).find("newer version (8)"), std::string::npos) << e.what();
    }
}

TEST_F(JobStoreTest, MigratesAVersionOneDatabase) {
    {
        // The version 1 schema: no client column, no idempotency keys, user_version 0.
        sql::Database db(dbFile());
        db.exec(R"sql(
CREATE TABLE jobs (
    seq INTEGER PRIMARY KEY AUTOINCREMENT,
    id TEXT NOT NULL UNIQUE,
    status TEXT NOT NULL,
    priority INTEGER NOT NULL,
    created_at TEXT NOT NULL,
    started_at TEXT,
    finished_at TEXT,
    passes INTEGER NOT NULL,
    photons_per_pass INTEGER NOT NULL,
    seed INTEGER NOT NULL,
    integrator TEXT NOT NULL,
    width INTEGER NOT NULL,
    height INTEGER NOT NULL,
    pass INTEGER NOT NULL DEFAULT 0,
    photons_traced INTEGER NOT NULL DEFAULT 0,
    mean_radius REAL NOT NULL DEFAULT 0,
    elapsed_seconds REAL NOT NULL DEFAULT 0,
    eta_seconds REAL NOT NULL DEFAULT 0,
    error TEXT
);
INSERT INTO jobs (id, status, priority, created_at, passes, photons_per_pass, seed, integrator, width, height)
VALUES ('old', 'queued', 1, '2023-01-01T00:00:00.000Z', 4, 1000, 7, 'path', 64, 48);
)sql");
    }
    JobStore store(dbFile());
    std::vector<JobRecord> jobs = store.loadAll();
    ASSERT_EQ(jobs.size(), 1u);
    EXPECT_EQ(jobs[0].id, "old");
    EXPECT_EQ(jobs[0].seq, 1);
    EXPECT_EQ(jobs[0].status, JobStatus::Queued);
    EXPECT_EQ(jobs[0].priority, 1);
    EXPECT_EQ(jobs[0].settings.integrator, "path");
    EXPECT_EQ(jobs[0].client, "");  // version 1 did not record it
    EXPECT_EQ(jobs[0].uploadBytes, 0);  // nor versions before 3 these
    EXPECT_TRUE(jobs[0].warnings.empty());
    EXPECT_EQ(jobs[0].name, "");
    EXPECT_TRUE(jobs[0].labels.empty());
    EXPECT_EQ(jobs[0].updatedAt, "2023-01-01T00:00:00.000Z");  // its creation
    EXPECT_EQ(jobs[0].settings.camera, "");  // nor versions before 4 this
    EXPECT_FALSE(jobs[0].settings.denoise);   // nor versions before 5 this
    EXPECT_EQ(jobs[0].settings.targetError, 0.0);  // nor versions before 6 this

    JobRecord fresh = newJob("new");
    EXPECT_EQ(store.insert(fresh, IdempotencyEntry{"k", "0123456789abcdef", "", 1000}), 2);
    EXPECT_EQ(store.loadAll().at(1).client, "127.0.0.1");
    ASSERT_TRUE(store.findKey("k", 1000));
    EXPECT_EQ(store.findKey("k", 1000)->jobId, "new");
}

TEST_F(JobStoreTest, OpeningInAMissingDirectoryThrows) {
    EXPECT_THROW({ JobStore store(dir_ / "missing" / "jobs.db"); }, sql::Error);
}

TEST_F(JobStoreTest, ConcurrentInsertsGetDistinctSequenceNumbers) {
    constexpr int kThreads = 4, kEach = 25;
    JobStore store(dbFile());
    std::vector<std::vector<int64_t>> seqs(kThreads);
    std::vector<std::thread> threads;
    for (int t = 0; t < kThreads; ++t)
        threads.emplace_back([&, t] {
            for (int i = 0; i < kEach; ++i)
                seqs[t].push_back(store.insert(newJob("t" + std::to_string(t) + "-" + std::to_string(i))));
        });
    for (auto& thread : threads) thread.join();

    std::vector<bool> seen(kThreads * kEach + 1, false);
    for (const auto& list : seqs)
        for (int64_t seq : list) {
            ASSERT_GE(seq, 1);
            ASSERT_LE(seq, kThreads * kEach);
            EXPECT_FALSE(seen[seq]) << seq;
            seen[seq] = true;
        }
    EXPECT_EQ(store.loadAll().size(), size_t(kThreads * kEach));
}
