#include <gtest/gtest.h>
#include <map>
#include <stdexcept>
#include <string>
#include <vector>
#include "server/job_table.h"

using namespace photon::server;

namespace {

const std::string kStarted = "2024-05-01T10:00:00.000Z";
const std::string kFinished = "2024-05-01T10:05:00.000Z";

JobRecord queuedJob(const std::string& id, int64_t seq = 1, const std::string& client = "10.0.0.1") {
    JobRecord job;
    job.id = id;
    job.seq = seq;
    job.status = JobStatus::Queued;
    job.createdAt = "2024-05-01T09:59:00.000Z";
    job.client = client;
    job.settings.passes = 8;
    return job;
}

JobRecord withStatus(JobRecord job, JobStatus status) {
    job.status = status;
    return job;
}

std::vector<std::string> ids(const JobTable::Page& page) {
    std::vector<std::string> out;
    for (const JobRecord& job : page.jobs) out.push_back(job.id);
    return out;
}

}  // namespace

TEST(JobTable, InsertedJobIsFound) {
    JobTable table;
    table.insert(queuedJob("a", 3));
    EXPECT_TRUE(table.contains("a"));
    std::optional<JobRecord> found = table.find("a");
    ASSERT_TRUE(found);
    EXPECT_EQ(found->id, "a");
    EXPECT_EQ(found->seq, 3);
    EXPECT_EQ(found->status, JobStatus::Queued);
    EXPECT_EQ(found->client, "10.0.0.1");
}

TEST(JobTable, UnknownJobIsNotFound) {
    JobTable table;
    EXPECT_FALSE(table.contains("nope"));
    EXPECT_FALSE(table.find("nope").has_value());
}

TEST(JobTable, StartMovesQueuedJobToRunning) {
    JobTable table;
    table.insert(queuedJob("a"));
    std::optional<JobTable::Started> started = table.start("a", kStarted);
    ASSERT_TRUE(started);
    EXPECT_EQ(started->job.id, "a");
    EXPECT_EQ(started->job.status, JobStatus::Running);
    EXPECT_EQ(started->job.startedAt, kStarted);
    ASSERT_NE(started->cancel, nullptr);
    EXPECT_FALSE(started->cancel->cancelled());
    EXPECT_EQ(table.find("a")->status, JobStatus::Running);
    EXPECT_EQ(table.find("a")->startedAt, kStarted);
}

TEST(JobTable, StartResetsProgress) {
    JobTable table;
    JobRecord job = queuedJob("a");
    job.progress = JobProgress{5, 5000, 0.25, 12.5, 3.0};
    table.insert(job);
    std::optional<JobTable::Started> started = table.start("a", kStarted);
    ASSERT_TRUE(started);
    EXPECT_EQ(started->job.progress.pass, 0);
    EXPECT_EQ(started->job.progress.photonsTraced, 0);
    EXPECT_EQ(started->job.progress.meanRadius, 0);
    EXPECT_EQ(started->job.progress.elapsedSeconds, 0);
    EXPECT_EQ(started->job.progress.etaSeconds, 0);
}

TEST(JobTable, StartOfUnknownJobReturnsNullopt) {
    JobTable table;
    EXPECT_FALSE(table.start("nope", kStarted).has_value());
}

TEST(JobTable, StartOfRunningJobReturnsNullopt) {
    JobTable table;
    table.insert(queuedJob("a"));
    ASSERT_TRUE(table.start("a", kStarted));
    EXPECT_FALSE(table.start("a", kFinished).has_value());
    EXPECT_EQ(table.find("a")->startedAt, kStarted);
}

TEST(JobTable, StartOfJobCancelledWhileQueuedReturnsNullopt) {
    JobTable table;
    table.insert(queuedJob("a"));
    JobRecord job;
    ASSERT_EQ(table.cancel("a", kFinished, job), JobTable::CancelResult::CancelledNow);
    EXPECT_FALSE(table.start("a", kStarted).has_value());
    EXPECT_EQ(table.find("a")->status, JobStatus::Cancelled);
    EXPECT_EQ(table.find("a")->startedAt, "");
}

TEST(JobTable, StartOfFinishedJobReturnsNullopt) {
    JobTable table;
    table.insert(withStatus(queuedJob("a"), JobStatus::Completed));
    EXPECT_FALSE(table.start("a", kStarted).has_value());
}

TEST(JobTable, SetProgressStoresAndReturnsTheRecord) {
    JobTable table;
    table.insert(queuedJob("a"));
    ASSERT_TRUE(table.start("a", kStarted));
    JobRecord job = table.setProgress("a", JobProgress{3, 300000, 0.125, 4.5, 7.25});
    EXPECT_EQ(job.id, "a");
    EXPECT_EQ(job.status, JobStatus::Running);
    EXPECT_EQ(job.progress.pass, 3);
    EXPECT_EQ(job.progress.photonsTraced, 300000);
    EXPECT_EQ(job.progress.meanRadius, 0.125);
    EXPECT_EQ(job.progress.elapsedSeconds, 4.5);
    EXPECT_EQ(job.progress.etaSeconds, 7.25);
    EXPECT_EQ(table.find("a")->progress.pass, 3);
    EXPECT_EQ(table.find("a")->progress.photonsTraced, 300000);
}

TEST(JobTable, SetProgressOfUnknownJobThrows) {
    JobTable table;
    EXPECT_THROW(table.setProgress("nope", JobProgress{}), std::logic_error);
}

TEST(JobTable, FinishCompletesARunningJob) {
    JobTable table;
    table.insert(queuedJob("a"));
    ASSERT_TRUE(table.start("a", kStarted));
    table.setProgress("a", JobProgress{8, 800, 0.5, 10.0, 2.5});
    JobRecord job = table.finish("a", JobStatus::Completed, "", kFinished);
    EXPECT_EQ(job.status, JobStatus::Completed);
    EXPECT_EQ(job.startedAt, kStarted);
    EXPECT_EQ(job.finishedAt, kFinished);
    EXPECT_EQ(job.error, "");
    EXPECT_EQ(job.progress.pass, 8);
    EXPECT_EQ(job.progress.elapsedSeconds, 10.0);
    EXPECT_EQ(job.progress.etaSeconds, 0);  // nothing left to wait for
    EXPECT_EQ(table.find("a")->status, JobStatus::Completed);
}

TEST(JobTable, FinishAsFailedKeepsTheReason) {
    JobTable table;
    table.insert(queuedJob("a"));
    ASSERT_TRUE(table.start("a", kStarted));
    JobRecord job = table.finish("a", JobStatus::Failed, "scene file vanished", kFinished);
    EXPECT_EQ(job.status, JobStatus::Failed);
    EXPECT_EQ(job.error, "scene file vanished");
    EXPECT_EQ(table.find("a")->error, "scene file vanished");
}

TEST(JobTable, FinishOfUnknownJobThrows) {
    JobTable table;
    EXPECT_THROW(table.finish("nope", JobStatus::Completed, "", kFinished), std::logic_error);
}

TEST(JobTable, CancelOfQueuedJobCancelsAtOnce) {
    JobTable table;
    table.insert(queuedJob("a"));
    JobRecord job;
    EXPECT_EQ(table.cancel("a", kFinished, job), JobTable::CancelResult::CancelledNow);
    EXPECT_EQ(job.id, "a");
    EXPECT_EQ(job.status, JobStatus::Cancelled);
    EXPECT_EQ(job.finishedAt, kFinished);
    EXPECT_EQ(table.find("a")->status, JobStatus::Cancelled);
}

TEST(JobTable, CancelOfRunningJobSetsItsTokenAndLeavesItRunning) {
    JobTable table;
    table.insert(queuedJob("a"));
    std::optional<JobTable::Started> started = table.start("a", kStarted);
    ASSERT_TRUE(started);
    EXPECT_FALSE(table.cancelRequested("a"));

    JobRecord job;
    EXPECT_EQ(table.cancel("a", kFinished, job), JobTable::CancelResult::Requested);
    EXPECT_EQ(job.status, JobStatus::Running);
    EXPECT_EQ(job.finishedAt, "");
    EXPECT_TRUE(started->cancel->cancelled());
    EXPECT_TRUE(table.cancelRequested("a"));

    // The render stops at its next check and records the outcome.
    JobRecord finished = table.finish("a", JobStatus::Cancelled, "", kFinished);
    EXPECT_EQ(finished.status, JobStatus::Cancelled);
    EXPECT_EQ(finished.finishedAt, kFinished);
}

TEST(JobTable, CancelOfRunningJobTwiceIsRequestedBothTimes) {
    JobTable table;
    table.insert(queuedJob("a"));
    ASSERT_TRUE(table.start("a", kStarted));
    JobRecord job;
    EXPECT_EQ(table.cancel("a", kFinished, job), JobTable::CancelResult::Requested);
    EXPECT_EQ(table.cancel("a", kFinished, job), JobTable::CancelResult::Requested);
}

TEST(JobTable, CancelOfFinishedJobReportsItUnchanged) {
    JobTable table;
    table.insert(queuedJob("a"));
    ASSERT_TRUE(table.start("a", kStarted));
    table.finish("a", JobStatus::Completed, "", kFinished);
    JobRecord job;
    EXPECT_EQ(table.cancel("a", "2024-05-01T11:00:00.000Z", job), JobTable::CancelResult::AlreadyFinished);
    EXPECT_EQ(job.status, JobStatus::Completed);
    EXPECT_EQ(job.finishedAt, kFinished);
    EXPECT_FALSE(table.cancelRequested("a"));
}

TEST(JobTable, CancelOfCancelledJobIsAlreadyFinished) {
    JobTable table;
    table.insert(queuedJob("a"));
    JobRecord job;
    ASSERT_EQ(table.cancel("a", kFinished, job), JobTable::CancelResult::CancelledNow);
    EXPECT_EQ(table.cancel("a", kFinished, job), JobTable::CancelResult::AlreadyFinished);
    EXPECT_EQ(job.status, JobStatus::Cancelled);
}

TEST(JobTable, CancelOfUnknownJobIsNotFound) {
    JobTable table;
    JobRecord job;
    EXPECT_EQ(table.cancel("nope", kFinished, job), JobTable::CancelResult::NotFound);
    EXPECT_FALSE(table.cancelRequested("nope"));
}

TEST(JobTable, InterruptAllStopsRendersWithoutCancellingThem) {
    JobTable table;
    table.insert(queuedJob("running", 1));
    table.insert(queuedJob("queued", 2));
    std::optional<JobTable::Started> started = table.start("running", kStarted);
    ASSERT_TRUE(started);

    table.interruptAll();

    EXPECT_TRUE(started->cancel->cancelled());
    // Not a client's cancel: the runner leaves the job running so a restart resumes it.
    EXPECT_FALSE(table.cancelRequested("running"));
    EXPECT_EQ(table.find("running")->status, JobStatus::Running);
    EXPECT_EQ(table.find("queued")->status, JobStatus::Queued);
}

TEST(JobTable, RemoveDeletesOnlyFinishedJobs) {
    JobTable table;
    table.insert(queuedJob("queued", 1));
    table.insert(queuedJob("running", 2));
    ASSERT_TRUE(table.start("running", kStarted));
    table.insert(withStatus(queuedJob("completed", 3), JobStatus::Completed));
    table.insert(withStatus(queuedJob("failed", 4), JobStatus::Failed));
    table.insert(withStatus(queuedJob("cancelled", 5), JobStatus::Cancelled));

    EXPECT_EQ(table.remove("queued"), JobTable::RemoveResult::NotFinished);
    EXPECT_EQ(table.remove("running"), JobTable::RemoveResult::NotFinished);
    EXPECT_EQ(table.remove("completed"), JobTable::RemoveResult::Removed);
    EXPECT_EQ(table.remove("failed"), JobTable::RemoveResult::Removed);
    EXPECT_EQ(table.remove("cancelled"), JobTable::RemoveResult::Removed);

    EXPECT_TRUE(table.contains("queued"));
    EXPECT_TRUE(table.contains("running"));
    EXPECT_FALSE(table.contains("completed"));
    EXPECT_FALSE(table.contains("failed"));
    EXPECT_FALSE(table.contains("cancelled"));
}

TEST(JobTable, RemoveOfUnknownJobIsNotFound) {
    JobTable table;
    EXPECT_EQ(table.remove("nope"), JobTable::RemoveResult::NotFound);
    table.insert(withStatus(queuedJob("a"), JobStatus::Completed));
    ASSERT_EQ(table.remove("a"), JobTable::RemoveResult::Removed);
    EXPECT_EQ(table.remove("a"), JobTable::RemoveResult::NotFound);
}

TEST(JobTable, ListIsNewestFirst) {
    JobTable table;
    table.insert(queuedJob("second", 2));
    table.insert(queuedJob("third", 3));
    table.insert(queuedJob("first", 1));
    JobTable::Page page = table.list({}, 10, 0);
    EXPECT_EQ(page.total, 3u);
    EXPECT_EQ(ids(page), (std::vector<std::string>{"third", "second", "first"}));
}

TEST(JobTable, ListFiltersByStatus) {
    JobTable table;
    table.insert(queuedJob("q1", 1));
    table.insert(withStatus(queuedJob("c1", 2), JobStatus::Completed));
    table.insert(queuedJob("q2", 3));
    table.insert(withStatus(queuedJob("f1", 4), JobStatus::Failed));
    JobTable::Page queued = table.list({{JobStatus::Queued}}, 10, 0);
    EXPECT_EQ(queued.total, 2u);
    EXPECT_EQ(ids(queued), (std::vector<std::string>{"q2", "q1"}));
    JobTable::Page running = table.list({{JobStatus::Running}}, 10, 0);
    EXPECT_EQ(running.total, 0u);
    EXPECT_TRUE(running.jobs.empty());
}

TEST(JobTable, ListFiltersBySeveralStatusesANameAndLabels) {
    JobTable table;
    auto job = [](std::string id, int64_t seq, JobStatus status, std::string name, std::vector<std::string> labels) {
        JobRecord j = withStatus(queuedJob(id, seq), status);
        j.name = std::move(name);
        j.labels = std::move(labels);
        return j;
    };
    table.insert(job("a", 1, JobStatus::Queued, "Atrium draft", {"project=atrium", "draft"}));
    table.insert(job("b", 2, JobStatus::Running, "atrium final", {"project=atrium"}));
    table.insert(job("c", 3, JobStatus::Completed, "Kitchen", {"project=kitchen", "draft"}));
    table.insert(job("d", 4, JobStatus::Failed, "ATRIUM", {}));
    EXPECT_EQ(ids(table.list({{JobStatus::Queued, JobStatus::Running}}, 10, 0)), (std::vector<std::string>{"b", "a"}));
    JobFilter byName;
    byName.nameContains = "atrium";
    EXPECT_EQ(ids(table.list(byName, 10, 0)), (std::vector<std::string>{"d", "b", "a"}));
    JobFilter byLabels;
    byLabels.labels = {"draft", "project=atrium"};
    EXPECT_EQ(ids(table.list(byLabels, 10, 0)), (std::vector<std::string>{"a"}));
    JobFilter all;
    all.statuses = {JobStatus::Completed, JobStatus::Queued};
    all.labels = {"draft"};
    all.nameContains = "KITCH";
    EXPECT_EQ(ids(table.list(all, 10, 0)), (std::vector<std::string>{"c"}));
}

TEST(JobTable, ACursorPagesOnFromTheJobItNamesEvenWhenJobsComeAndGo) {
    JobTable table;
    for (int seq = 1; seq <= 5; ++seq) table.insert(withStatus(queuedJob("j" + std::to_string(seq), seq), JobStatus::Completed));
    JobTable::Page first = table.list({}, 2, 0);
    EXPECT_EQ(ids(first), (std::vector<std::string>{"j5", "j4"}));
    ASSERT_EQ(first.nextAfterSeq, 4);
    // A new job and a deleted one between pages shift offsets, not the cursor.
    table.insert(queuedJob("j6", 6));
    EXPECT_EQ(table.remove("j5"), JobTable::RemoveResult::Removed);
    JobFilter next;
    next.afterSeq = first.nextAfterSeq;
    JobTable::Page second = table.list(next, 2, 0);
    EXPECT_EQ(ids(second), (std::vector<std::string>{"j3", "j2"}));
    ASSERT_EQ(second.nextAfterSeq, 2);
    next.afterSeq = second.nextAfterSeq;
    JobTable::Page last = table.list(next, 2, 0);
    EXPECT_EQ(ids(last), (std::vector<std::string>{"j1"}));
    EXPECT_FALSE(last.nextAfterSeq);
}

TEST(JobTable, ListPagesWithLimitAndOffsetAndCountsAllMatches) {
    JobTable table;
    for (int seq = 1; seq <= 5; ++seq) table.insert(queuedJob("j" + std::to_string(seq), seq));
    JobTable::Page page = table.list({}, 2, 1);
    EXPECT_EQ(page.total, 5u);
    EXPECT_EQ(ids(page), (std::vector<std::string>{"j4", "j3"}));

    JobTable::Page tail = table.list({}, 10, 4);
    EXPECT_EQ(ids(tail), (std::vector<std::string>{"j1"}));

    JobTable::Page beyond = table.list({}, 10, 9);
    EXPECT_EQ(beyond.total, 5u);
    EXPECT_TRUE(beyond.jobs.empty());

    EXPECT_TRUE(table.list({}, 0, 0).jobs.empty());
}

TEST(JobTable, CountByStatusNamesEveryStatus) {
    JobTable table;
    std::map<JobStatus, int> empty = table.countByStatus();
    EXPECT_EQ(empty, (std::map<JobStatus, int>{{JobStatus::Queued, 0},
                                               {JobStatus::Running, 0}, {JobStatus::Paused, 0},
                                               {JobStatus::Completed, 0},
                                               {JobStatus::Failed, 0},
                                               {JobStatus::Cancelled, 0}}));

    table.insert(queuedJob("q1", 1));
    table.insert(queuedJob("q2", 2));
    table.insert(queuedJob("r", 3));
    ASSERT_TRUE(table.start("r", kStarted));
    table.insert(withStatus(queuedJob("c", 4), JobStatus::Completed));
    table.insert(withStatus(queuedJob("x", 5), JobStatus::Cancelled));
    EXPECT_EQ(table.countByStatus(), (std::map<JobStatus, int>{{JobStatus::Queued, 2},
                                                               {JobStatus::Running, 1}, {JobStatus::Paused, 0},
                                                               {JobStatus::Completed, 1},
                                                               {JobStatus::Failed, 0},
                                                               {JobStatus::Cancelled, 1}}));
}

TEST(JobTable, ActiveJobsOfCountsQueuedAndRunningJobsOfThatClient) {
    JobTable table;
    table.insert(queuedJob("a1", 1, "A"));
    table.insert(queuedJob("a2", 2, "A"));
    ASSERT_TRUE(table.start("a2", kStarted));
    table.insert(withStatus(queuedJob("a3", 3, "A"), JobStatus::Completed));
    table.insert(withStatus(queuedJob("a4", 4, "A"), JobStatus::Failed));
    table.insert(queuedJob("b1", 5, "B"));

    EXPECT_EQ(table.activeJobsOf("A"), 2);
    EXPECT_EQ(table.activeJobsOf("B"), 1);
    EXPECT_EQ(table.activeJobsOf("C"), 0);

    JobRecord job;
    table.cancel("a1", kFinished, job);
    EXPECT_EQ(table.activeJobsOf("A"), 1);
    table.finish("a2", JobStatus::Completed, "", kFinished);
    EXPECT_EQ(table.activeJobsOf("A"), 0);
}
