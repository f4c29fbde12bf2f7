#include <gtest/gtest.h>
#include <chrono>
#include <future>
#include <string>
#include <vector>
#include "server/event_hub.h"

using namespace photon::server;
using namespace std::chrono_literals;

namespace event_hub_tests {

namespace {

// Only a guard against a hang: every wait that uses it is expected to end at once.
constexpr auto kGuard = 10s;

constexpr size_t kLogLength = EventHub::kLogLength;
constexpr size_t kFinishedLogsKept = EventHub::kFinishedLogsKept;

JobRecord job(const std::string& id, JobStatus status = JobStatus::Running, int pass = 0) {
    JobRecord j;
    j.id = id;
    j.status = status;
    j.progress.pass = pass;
    return j;
}

void publishPasses(EventHub& hub, const std::string& id, int passes) {
    for (int p = 1; p <= passes; ++p) hub.publish(job(id, JobStatus::Running, p), EventType::Progress);
}

std::vector<uint64_t> seqs(const std::vector<JobEvent>& events) {
    std::vector<uint64_t> out;
    for (const JobEvent& e : events) out.push_back(e.seq);
    return out;
}

}  // namespace

TEST(EventHub, EventTypeNames) {
    EXPECT_STREQ(toString(EventType::Progress), "progress");
    EXPECT_STREQ(toString(EventType::Done), "done");
    EXPECT_STREQ(toString(EventType::Failed), "failed");
    EXPECT_STREQ(toString(EventType::Cancelled), "cancelled");
}

TEST(EventHub, EventTypeForStatusEndsFinishedJobsOnly) {
    EXPECT_EQ(eventTypeFor(JobStatus::Queued), EventType::Progress);
    EXPECT_EQ(eventTypeFor(JobStatus::Running), EventType::Progress);
    EXPECT_EQ(eventTypeFor(JobStatus::Completed), EventType::Done);
    EXPECT_EQ(eventTypeFor(JobStatus::Failed), EventType::Failed);
    EXPECT_EQ(eventTypeFor(JobStatus::Cancelled), EventType::Cancelled);
}

TEST(EventHub, CurrentOfUnknownJobIsEmpty) {
    EventHub hub;
    EXPECT_FALSE(hub.current("nope").has_value());
}

TEST(EventHub, PublishWithoutEventSetsStateButLogsNothing) {
    EventHub hub;
    hub.publish(job("a", JobStatus::Queued), std::nullopt);
    auto snap = hub.current("a");
    ASSERT_TRUE(snap);
    EXPECT_EQ(snap->job.id, "a");
    EXPECT_EQ(snap->job.status, JobStatus::Queued);
    EXPECT_EQ(snap->seq, 0u);
    EXPECT_EQ(snap->oldestSeq, 0u);
}

TEST(EventHub, EventsAreNumberedFromOnePerJob) {
    EventHub hub;
    publishPasses(hub, "a", 3);
    publishPasses(hub, "b", 2);
    auto a = hub.current("a");
    auto b = hub.current("b");
    ASSERT_TRUE(a && b);
    EXPECT_EQ(a->seq, 3u);
    EXPECT_EQ(a->oldestSeq, 1u);
    EXPECT_EQ(a->job.progress.pass, 3);
    EXPECT_EQ(b->seq, 2u);
    EXPECT_EQ(b->oldestSeq, 1u);
}

TEST(EventHub, StateOnlyPublishUpdatesCurrentWithoutNumberingAnEvent) {
    EventHub hub;
    publishPasses(hub, "a", 2);
    hub.publish(job("a", JobStatus::Running, 7), std::nullopt);
    auto snap = hub.current("a");
    ASSERT_TRUE(snap);
    EXPECT_EQ(snap->seq, 2u);
    EXPECT_EQ(snap->job.progress.pass, 7);
    EventHub::Wait wait = hub.waitAfter("a", 0, 0ms);
    EXPECT_EQ(seqs(wait.events), (std::vector<uint64_t>{1, 2}));
    EXPECT_EQ(wait.events.back().job.progress.pass, 2);
}

TEST(EventHub, WaitReturnsTheWholeLogOldestFirst) {
    EventHub hub;
    publishPasses(hub, "a", 3);
    hub.publish(job("a", JobStatus::Completed, 3), EventType::Done);
    EventHub::Wait wait = hub.waitAfter("a", 0, 0ms);
    EXPECT_FALSE(wait.closed);
    ASSERT_EQ(seqs(wait.events), (std::vector<uint64_t>{1, 2, 3, 4}));
    for (int i = 0; i < 3; ++i) {
        EXPECT_EQ(wait.events[i].type, EventType::Progress);
        EXPECT_EQ(wait.events[i].job.progress.pass, i + 1);
    }
    EXPECT_EQ(wait.events[3].type, EventType::Done);
    EXPECT_EQ(wait.events[3].job.status, JobStatus::Completed);
}

TEST(EventHub, WaitResumesAfterLastEventId) {
    EventHub hub;
    publishPasses(hub, "a", 5);
    EventHub::Wait wait = hub.waitAfter("a", 2, 0ms);
    EXPECT_FALSE(wait.closed);
    EXPECT_EQ(seqs(wait.events), (std::vector<uint64_t>{3, 4, 5}));
    EXPECT_EQ(wait.events.front().job.progress.pass, 3);
}

TEST(EventHub, WaitWithNothingNewTimesOutEmptyAndOpen) {
    EventHub hub;
    publishPasses(hub, "a", 2);
    EventHub::Wait wait = hub.waitAfter("a", 2, 10ms);
    EXPECT_FALSE(wait.closed);
    EXPECT_TRUE(wait.events.empty());
}

TEST(EventHub, WaitForUnknownJobIsClosed) {
    EventHub hub;
    EventHub::Wait wait = hub.waitAfter("nope", 0, kGuard);
    EXPECT_TRUE(wait.closed);
    EXPECT_TRUE(wait.events.empty());
}

TEST(EventHub, WaiterWakesOnPublishedEvent) {
    EventHub hub;
    hub.publish(job("a", JobStatus::Queued), std::nullopt);
    auto waiting = std::async(std::launch::async, [&] { return hub.waitAfter("a", 0, kGuard); });
    hub.publish(job("a", JobStatus::Running, 1), EventType::Progress);
    ASSERT_EQ(waiting.wait_for(kGuard), std::future_status::ready);
    EventHub::Wait wait = waiting.get();
    EXPECT_FALSE(wait.closed);
    ASSERT_EQ(seqs(wait.events), (std::vector<uint64_t>{1}));
    EXPECT_EQ(wait.events[0].job.progress.pass, 1);
}

TEST(EventHub, StateOnlyPublishDoesNotEndAWait) {
    EventHub hub;
    hub.publish(job("a", JobStatus::Queued), std::nullopt);
    auto waiting = std::async(std::launch::async, [&] { return hub.waitAfter("a", 0, 50ms); });
    hub.publish(job("a", JobStatus::Running), std::nullopt);
    ASSERT_EQ(waiting.wait_for(kGuard), std::future_status::ready);
    EventHub::Wait wait = waiting.get();
    EXPECT_FALSE(wait.closed);
    EXPECT_TRUE(wait.events.empty());
}

TEST(EventHub, SubscriberSeesEveryEventInOrderWhileTheJobRuns) {
    constexpr int kPasses = 300;
    EventHub hub;
    hub.publish(job("a", JobStatus::Queued), std::nullopt);
    auto follower = std::async(std::launch::async, [&] {
        std::vector<JobEvent> seen;
        uint64_t last = 0;
        for (;;) {
            EventHub::Wait wait = hub.waitAfter("a", last, kGuard);
            if (wait.closed || wait.events.empty()) return seen;  // a hang or an early end: fails below
            for (const JobEvent& e : wait.events) seen.push_back(e);
            last = seen.back().seq;
            if (seen.back().type != EventType::Progress) return seen;
        }
    });
    publishPasses(hub, "a", kPasses);
    hub.publish(job("a", JobStatus::Completed, kPasses), EventType::Done);

    ASSERT_EQ(follower.wait_for(kGuard * 2), std::future_status::ready);
    std::vector<JobEvent> seen = follower.get();
    ASSERT_EQ(seen.size(), size_t(kPasses + 1));
    for (int i = 0; i < kPasses; ++i) {
        EXPECT_EQ(seen[i].seq, uint64_t(i + 1));
        EXPECT_EQ(seen[i].type, EventType::Progress);
        EXPECT_EQ(seen[i].job.progress.pass, i + 1);
    }
    EXPECT_EQ(seen.back().seq, uint64_t(kPasses + 1));
    EXPECT_EQ(seen.back().type, EventType::Done);
}

TEST(EventHub, ForgetEndsWaitersAndDropsTheJob) {
    EventHub hub;
    publishPasses(hub, "a", 1);
    auto waiting = std::async(std::launch::async, [&] { return hub.waitAfter("a", 1, kGuard); });
    hub.forget("a");
    ASSERT_EQ(waiting.wait_for(kGuard), std::future_status::ready);
    EXPECT_TRUE(waiting.get().closed);
    EXPECT_FALSE(hub.current("a").has_value());
}

TEST(EventHub, ForgetLeavesOtherJobsAlone) {
    EventHub hub;
    publishPasses(hub, "a", 1);
    publishPasses(hub, "b", 1);
    hub.forget("a");
    EventHub::Wait wait = hub.waitAfter("b", 0, 0ms);
    EXPECT_FALSE(wait.closed);
    EXPECT_EQ(seqs(wait.events), (std::vector<uint64_t>{1}));
}

TEST(EventHub, ShutdownEndsEveryWaiter) {
    EventHub hub;
    publishPasses(hub, "a", 1);
    publishPasses(hub, "b", 1);
    std::vector<std::future<EventHub::Wait>> waits;
    waits.push_back(std::async(std::launch::async, [&] { return hub.waitAfter("a", 1, kGuard); }));
    waits.push_back(std::async(std::launch::async, [&] { return hub.waitAfter("a", 1, kGuard); }));
    waits.push_back(std::async(std::launch::async, [&] { return hub.waitAfter("b", 1, kGuard); }));
    hub.shutdown();
    for (auto& w : waits) {
        ASSERT_EQ(w.wait_for(kGuard), std::future_status::ready);
        EventHub::Wait wait = w.get();
        EXPECT_TRUE(wait.closed);
        EXPECT_TRUE(wait.events.empty());
    }
}

TEST(EventHub, WaitAfterShutdownIsClosedEvenWithEventsPending) {
    EventHub hub;
    publishPasses(hub, "a", 3);
    hub.shutdown();
    EventHub::Wait wait = hub.waitAfter("a", 0, kGuard);
    EXPECT_TRUE(wait.closed);
    EXPECT_TRUE(wait.events.empty());
}

TEST(EventHub, LogKeepsOnlyTheNewestEvents) {
    EventHub hub;
    const int passes = int(kLogLength) + 6;
    publishPasses(hub, "a", passes);
    auto snap = hub.current("a");
    ASSERT_TRUE(snap);
    EXPECT_EQ(snap->seq, uint64_t(passes));
    EXPECT_EQ(snap->oldestSeq, 7u);

    EventHub::Wait all = hub.waitAfter("a", 0, 0ms);
    ASSERT_EQ(all.events.size(), kLogLength);
    EXPECT_EQ(all.events.front().seq, 7u);
    EXPECT_EQ(all.events.back().seq, uint64_t(passes));

    // A client resuming from an event that has left the log gets what is left.
    EventHub::Wait resumed = hub.waitAfter("a", 3, 0ms);
    ASSERT_EQ(resumed.events.size(), kLogLength);
    EXPECT_EQ(resumed.events.front().seq, 7u);
}

TEST(EventHub, OnlyTheNewestFinishedJobsKeepTheirFullLog) {
    EventHub hub;
    auto finishJob = [&](const std::string& id) {
        publishPasses(hub, id, 3);
        hub.publish(job(id, JobStatus::Completed, 3), EventType::Done);
    };
    for (size_t i = 0; i < kFinishedLogsKept; ++i) finishJob("job" + std::to_string(i));
    EXPECT_EQ(hub.current("job0")->oldestSeq, 1u);  // still within the bound

    finishJob("job" + std::to_string(kFinishedLogsKept));

    // The oldest finished job keeps only its final event; its state is untouched.
    auto oldest = hub.current("job0");
    ASSERT_TRUE(oldest);
    EXPECT_EQ(oldest->seq, 4u);
    EXPECT_EQ(oldest->oldestSeq, 4u);
    EXPECT_EQ(oldest->job.status, JobStatus::Completed);
    EventHub::Wait wait = hub.waitAfter("job0", 0, 0ms);
    ASSERT_EQ(seqs(wait.events), (std::vector<uint64_t>{4}));
    EXPECT_EQ(wait.events[0].type, EventType::Done);

    EXPECT_EQ(hub.current("job1")->oldestSeq, 1u);
    EXPECT_EQ(hub.current("job" + std::to_string(kFinishedLogsKept))->oldestSeq, 1u);
}

TEST(EventHub, RunningJobsKeepTheirLogWhateverFinishes) {
    EventHub hub;
    publishPasses(hub, "running", 5);
    for (size_t i = 0; i <= kFinishedLogsKept + 3; ++i) {
        std::string id = "done" + std::to_string(i);
        publishPasses(hub, id, 1);
        hub.publish(job(id, JobStatus::Failed, 1), EventType::Failed);
    }
    auto snap = hub.current("running");
    ASSERT_TRUE(snap);
    EXPECT_EQ(snap->oldestSeq, 1u);
    EXPECT_EQ(snap->seq, 5u);
}

TEST(EventHub, JobCancelledWhileQueuedHasOnlyItsFinalEvent) {
    EventHub hub;
    hub.publish(job("a", JobStatus::Queued), std::nullopt);
    hub.publish(job("a", JobStatus::Cancelled), EventType::Cancelled);
    EventHub::Wait wait = hub.waitAfter("a", 0, 0ms);
    ASSERT_EQ(seqs(wait.events), (std::vector<uint64_t>{1}));
    EXPECT_EQ(wait.events[0].type, EventType::Cancelled);
    EXPECT_EQ(wait.events[0].job.status, JobStatus::Cancelled);
}

TEST(EventHub, TheStreamOfAllJobsNumbersEveryChangeAndEveryDeletion) {
    EventHub hub;
    hub.publish(job("a", JobStatus::Queued), std::nullopt);
    hub.publish(job("b", JobStatus::Queued), std::nullopt);
    hub.publish(job("a", JobStatus::Running, 1), EventType::Progress);
    hub.forget("b");
    EventHub::ServiceWait wait = hub.waitAnyAfter(1, 0ms);
    EXPECT_FALSE(wait.missed);
    EXPECT_EQ(wait.seq, 4u);
    ASSERT_EQ(wait.events.size(), 3u);
    EXPECT_EQ(wait.events[0].seq, 2u);
    EXPECT_EQ(wait.events[0].job.id, "b");
    EXPECT_FALSE(wait.events[0].jobEvent);
    EXPECT_EQ(wait.events[1].jobEvent, EventType::Progress);
    EXPECT_EQ(wait.events[2].kind, ServiceEvent::Kind::Deleted);
    EXPECT_EQ(wait.events[2].job.id, "b");
    EXPECT_TRUE(hub.waitAnyAfter(4, 0ms).events.empty());
}

TEST(EventHub, AClientTooFarBehindOnTheStreamOfAllJobsIsToldItMissedChanges) {
    EventHub hub;
    for (size_t i = 0; i < EventHub::kServiceLogLength + 10; ++i) hub.publish(job("a", JobStatus::Running, int(i)), std::nullopt);
    EventHub::ServiceWait behind = hub.waitAnyAfter(5, 0ms);
    EXPECT_TRUE(behind.missed);
    EXPECT_TRUE(behind.events.empty());
    EXPECT_EQ(behind.seq, EventHub::kServiceLogLength + 10);
    EventHub::ServiceWait caughtUp = hub.waitAnyAfter(10, 0ms);  // the oldest kept is 11
    EXPECT_FALSE(caughtUp.missed);
    EXPECT_EQ(caughtUp.events.size(), EventHub::kServiceLogLength);
}

}  // namespace event_hub_tests
