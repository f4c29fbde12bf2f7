#include <gtest/gtest.h>
#include <chrono>
#include <climits>
#include <condition_variable>
#include <future>
#include <mutex>
#include <set>
#include <string>
#include <thread>
#include <vector>
#include "server/job_queue.h"

using namespace photon::server;
using namespace std::chrono_literals;

namespace job_queue_tests {

namespace {

// Only a guard against a hang: every wait that uses it is expected to end at once.
constexpr auto kGuard = 10s;

std::vector<std::string> popAll(JobQueue& queue) {
    std::vector<std::string> ids;
    while (queue.size() > 0) ids.push_back(*queue.pop());
    return ids;
}

}  // namespace

TEST(JobQueue, StartsEmpty) {
    JobQueue queue;
    EXPECT_EQ(queue.size(), 0u);
}

TEST(JobQueue, SizeCountsQueuedJobs) {
    JobQueue queue;
    queue.push("a", 0, 1);
    queue.push("b", 0, 2);
    EXPECT_EQ(queue.size(), 2u);
    queue.pop();
    EXPECT_EQ(queue.size(), 1u);
}

TEST(JobQueue, PopsHigherPriorityFirst) {
    JobQueue queue;
    queue.push("low", 0, 1);
    queue.push("high", 5, 2);
    queue.push("middle", 1, 3);
    EXPECT_EQ(popAll(queue), (std::vector<std::string>{"high", "middle", "low"}));
}

TEST(JobQueue, PopsEqualPriorityInSubmissionOrderNotPushOrder) {
    JobQueue queue;
    // Restart recovery pushes jobs in whatever order; the sequence number decides.
    queue.push("third", 2, 30);
    queue.push("first", 2, 10);
    queue.push("second", 2, 20);
    EXPECT_EQ(popAll(queue), (std::vector<std::string>{"first", "second", "third"}));
}

TEST(JobQueue, OrdersByPriorityThenSubmission) {
    JobQueue queue;
    queue.push("a", 0, 1);
    queue.push("b", 1, 2);
    queue.push("c", 0, 3);
    queue.push("d", 1, 4);
    queue.push("e", -1, 5);
    EXPECT_EQ(popAll(queue), (std::vector<std::string>{"b", "d", "a", "c", "e"}));
}

TEST(JobQueue, HandlesExtremePriorities) {
    JobQueue queue;
    queue.push("min", INT_MIN, 1);
    queue.push("zero", 0, 2);
    queue.push("max", INT_MAX, 3);
    EXPECT_EQ(popAll(queue), (std::vector<std::string>{"max", "zero", "min"}));
}

TEST(JobQueue, RemoveTakesQueuedJobOut) {
    JobQueue queue;
    queue.push("a", 0, 1);
    queue.push("b", 0, 2);
    queue.push("c", 0, 3);
    EXPECT_TRUE(queue.remove("b"));
    EXPECT_EQ(queue.size(), 2u);
    EXPECT_EQ(popAll(queue), (std::vector<std::string>{"a", "c"}));
}

TEST(JobQueue, RemoveOfUnknownIdReturnsFalse) {
    JobQueue queue;
    queue.push("a", 0, 1);
    EXPECT_FALSE(queue.remove("nope"));
    EXPECT_EQ(queue.size(), 1u);
}

TEST(JobQueue, RemoveOfPoppedJobReturnsFalse) {
    JobQueue queue;
    queue.push("a", 0, 1);
    ASSERT_EQ(queue.pop(), "a");
    EXPECT_FALSE(queue.remove("a"));
}

TEST(JobQueue, RemoveSucceedsOnlyOnce) {
    JobQueue queue;
    queue.push("a", 0, 1);
    EXPECT_TRUE(queue.remove("a"));
    EXPECT_FALSE(queue.remove("a"));
    EXPECT_EQ(queue.size(), 0u);
}

TEST(JobQueue, PopBlocksUntilPush) {
    JobQueue queue;
    auto popped = std::async(std::launch::async, [&] { return queue.pop(); });
    // Nothing is queued, so the pop cannot have returned yet, however fast the machine.
    EXPECT_EQ(popped.wait_for(20ms), std::future_status::timeout);
    queue.push("a", 0, 1);
    ASSERT_EQ(popped.wait_for(kGuard), std::future_status::ready);
    EXPECT_EQ(popped.get(), "a");
    EXPECT_EQ(queue.size(), 0u);
}

TEST(JobQueue, PopAfterCloseReturnsNullopt) {
    JobQueue queue;
    queue.close();
    EXPECT_EQ(queue.pop(), std::nullopt);
}

TEST(JobQueue, PopAfterCloseReturnsNulloptEvenWithJobsQueued) {
    JobQueue queue;
    queue.push("a", 0, 1);
    queue.close();
    EXPECT_EQ(queue.pop(), std::nullopt);
}

TEST(JobQueue, CloseWakesEveryBlockedPop) {
    JobQueue queue;
    std::vector<std::future<std::optional<std::string>>> pops;
    for (int i = 0; i < 3; ++i) pops.push_back(std::async(std::launch::async, [&] { return queue.pop(); }));
    queue.close();
    for (auto& pop : pops) {
        ASSERT_EQ(pop.wait_for(kGuard), std::future_status::ready);
        EXPECT_EQ(pop.get(), std::nullopt);
    }
}

TEST(JobQueue, ConcurrentWorkersTakeEachJobExactlyOnce) {
    constexpr int kJobs = 200;
    JobQueue queue;
    std::mutex mutex;
    std::condition_variable allTaken;
    std::multiset<std::string> taken;

    std::vector<std::thread> workers;
    for (int w = 0; w < 4; ++w)
        workers.emplace_back([&] {
            while (std::optional<std::string> id = queue.pop()) {
                std::lock_guard lock(mutex);
                taken.insert(*id);
                if (taken.size() == kJobs) allTaken.notify_all();
            }
        });
    for (int i = 0; i < kJobs; ++i) queue.push("job" + std::to_string(i), i % 3, i + 1);
    {
        std::unique_lock lock(mutex);
        EXPECT_TRUE(allTaken.wait_for(lock, kGuard, [&] { return taken.size() == kJobs; }));
    }
    queue.close();
    for (auto& w : workers) w.join();

    ASSERT_EQ(taken.size(), size_t(kJobs));
    for (int i = 0; i < kJobs; ++i) EXPECT_EQ(taken.count("job" + std::to_string(i)), 1u) << i;
    EXPECT_EQ(queue.size(), 0u);
}

}  // namespace job_queue_tests
