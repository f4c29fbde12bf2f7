#include <gtest/gtest.h>
#include <atomic>
#include <chrono>
#include <filesystem>
#include <future>
#include <string>
#include <thread>
#include <vector>
#include <unistd.h>
#include "server/clock.h"
#include "server/idempotency.h"
#include "server/job_store.h"

using namespace photon::server;
using namespace std::chrono_literals;
namespace fs = std::filesystem;

namespace idempotency_tests {

namespace {

// Only a guard against a hang: every wait that uses it is expected to end at once.
constexpr auto kGuard = 10s;

std::string digestOf(const std::vector<std::string>& fields) {
    RequestDigest digest;
    for (const std::string& field : fields) {
        digest.add(field.data(), field.size());
        digest.endField();
    }
    return digest.hex();
}

}  // namespace

// --- Idempotency-Key validation ---

TEST(IdempotencyKey, AcceptsPrintableAsciiUpTo255Characters) {
    EXPECT_EQ(idempotencyKeyProblem("a"), std::nullopt);
    EXPECT_EQ(idempotencyKeyProblem("retry-7f3c 2024/05/01"), std::nullopt);
    EXPECT_EQ(idempotencyKeyProblem(std::string(kMaxIdempotencyKeyLength, 'k')), std::nullopt);
    std::string everyPrintable;
    for (char c = 0x20; c <= 0x7e; ++c) everyPrintable += c;
    EXPECT_EQ(idempotencyKeyProblem(everyPrintable), std::nullopt);
}

TEST(IdempotencyKey, RefusesEmptyAndOverlongKeys) {
    EXPECT_EQ(idempotencyKeyProblem(""), "Idempotency-Key: must be 1 to 255 characters, got 0");
    EXPECT_EQ(idempotencyKeyProblem(std::string(256, 'k')), "Idempotency-Key: must be 1 to 255 characters, got 256");
}

TEST(IdempotencyKey, RefusesControlAndNonAsciiCharacters) {
    const std::string problem = "Idempotency-Key: must be printable ASCII characters";
    EXPECT_EQ(idempotencyKeyProblem("a\nb"), problem);
    EXPECT_EQ(idempotencyKeyProblem("tab\there"), problem);
    EXPECT_EQ(idempotencyKeyProblem(std::string("nul\0", 4)), problem);
    EXPECT_EQ(idempotencyKeyProblem("del\x7f"), problem);
    EXPECT_EQ(idempotencyKeyProblem("caf\xc3\xa9"), problem);
}

// --- Request digest ---

TEST(RequestDigest, IsPlainFnv1aWithoutFieldBoundaries) {
    // Published FNV-1a 64-bit test vectors.
    EXPECT_EQ(RequestDigest().hex(), "cbf29ce484222325");
    RequestDigest a;
    a.add("a", 1);
    EXPECT_EQ(a.hex(), "af63dc4c8601ec8c");
    RequestDigest foobar;
    foobar.add("foobar", 6);
    EXPECT_EQ(foobar.hex(), "85944171f73967e8");
}

TEST(RequestDigest, IsStableAcrossBuilds) {
    // Stored with the key: a change here would turn every stored retry into a conflict.
    EXPECT_EQ(digestOf({"scene", "{\"camera\":{}}", "passes=16"}), "e32128c21c5f66e4");
    EXPECT_EQ(digestOf({""}), "a8c7f832281a39c5");
}

TEST(RequestDigest, SameRequestSameDigest) {
    EXPECT_EQ(digestOf({"scene", "{}", "passes=4"}), digestOf({"scene", "{}", "passes=4"}));
}

TEST(RequestDigest, DifferentRequestsDiffer) {
    EXPECT_NE(digestOf({"scene", "{}", "passes=4"}), digestOf({"scene", "{}", "passes=5"}));
    EXPECT_NE(digestOf({"scene", "{}"}), digestOf({"scene", "{}", ""}));
}

TEST(RequestDigest, FieldBoundariesCount) {
    EXPECT_NE(digestOf({"ab", "c"}), digestOf({"a", "bc"}));
    EXPECT_NE(digestOf({"abc"}), digestOf({"ab", "c"}));
}

TEST(RequestDigest, AFieldMayArriveInPieces) {
    RequestDigest pieces;
    pieces.add("sc", 2);
    pieces.add("ene", 3);
    pieces.endField();
    pieces.add("{}", 2);
    pieces.endField();
    EXPECT_EQ(pieces.hex(), digestOf({"scene", "{}"}));
}

TEST(RequestDigest, HexIsSixteenLowercaseDigits) {
    std::string hex = digestOf({"anything"});
    ASSERT_EQ(hex.size(), 16u);
    for (char c : hex) EXPECT_TRUE((c >= '0' && c <= '9') || (c >= 'a' && c <= 'f')) << hex;
}

// --- Per-key serialisation ---

TEST(KeyLocks, DifferentKeysDoNotWaitForEachOther) {
    KeyLocks locks;
    KeyLocks::Guard first(locks, "a");
    auto other = std::async(std::launch::async, [&] { KeyLocks::Guard second(locks, "b"); });
    EXPECT_EQ(other.wait_for(kGuard), std::future_status::ready);
}

TEST(KeyLocks, SameKeyWaitsUntilTheHolderReleases) {
    KeyLocks locks;
    std::optional<KeyLocks::Guard> first;
    first.emplace(locks, "k");
    std::atomic<bool> acquired{false};
    auto second = std::async(std::launch::async, [&] {
        KeyLocks::Guard guard(locks, "k");
        acquired = true;
    });
    // The key is held, so the second guard cannot have been taken, however fast the machine.
    EXPECT_EQ(second.wait_for(20ms), std::future_status::timeout);
    EXPECT_FALSE(acquired);
    first.reset();
    EXPECT_EQ(second.wait_for(kGuard), std::future_status::ready);
    EXPECT_TRUE(acquired);
}

TEST(KeyLocks, ReleasedKeyCanBeTakenAgain) {
    KeyLocks locks;
    { KeyLocks::Guard guard(locks, "k"); }
    auto again = std::async(std::launch::async, [&] { KeyLocks::Guard guard(locks, "k"); });
    EXPECT_EQ(again.wait_for(kGuard), std::future_status::ready);
}

TEST(KeyLocks, HoldersOfOneKeyNeverOverlap) {
    KeyLocks locks;
    std::atomic<int> inside{0}, maxInside{0}, entries{0};
    std::vector<std::thread> threads;
    for (int t = 0; t < 4; ++t)
        threads.emplace_back([&] {
            for (int i = 0; i < 200; ++i) {
                KeyLocks::Guard guard(locks, "same");
                int now = ++inside;
                int seen = maxInside.load();
                while (now > seen && !maxInside.compare_exchange_weak(seen, now)) {
                }
                ++entries;
                --inside;
            }
        });
    for (auto& thread : threads) thread.join();
    EXPECT_EQ(entries, 800);
    EXPECT_EQ(maxInside, 1);
}

TEST(Idempotency, UnixNowSecondsIsTheSystemClock) {
    auto seconds = [] {
        return std::chrono::duration_cast<std::chrono::seconds>(std::chrono::system_clock::now().time_since_epoch())
            .count();
    };
    int64_t before = seconds();
    int64_t now = unixNowSeconds();
    int64_t after = seconds();
    EXPECT_LE(before, now);
    EXPECT_LE(now, after);
}

// --- Keys stored with their jobs (JobStore). Time is passed in, so expiry is exact. ---

class IdempotencyStoreTest : public ::testing::Test {
protected:
    static constexpr int64_t kT0 = 1'714'560'000;  // 2024-05-01T10:40:00Z

    void SetUp() override {
        dir_ = fs::temp_directory_path() /
               ("photon-idempotency-test-" + std::to_string(::getpid()) + "-" + randomJobId());
        ASSERT_TRUE(fs::create_directory(dir_));
        store_.emplace(dir_ / "jobs.db");
    }
    void TearDown() override {
        store_.reset();
        std::error_code ec;
        fs::remove_all(dir_, ec);
    }

    static JobRecord job(const std::string& id) {
        JobRecord j;
        j.id = id;
        j.createdAt = "2024-05-01T10:40:00.000Z";
        j.settings = JobSettings{4, 1000, 1, "sppm", 64, 64};
        return j;
    }
    void submit(const std::string& id, const std::string& key, const std::string& digest, int64_t nowUnix) {
        store_->insert(job(id), IdempotencyEntry{key, digest, "", nowUnix});
    }

    fs::path dir_;
    std::optional<JobStore> store_;
};

TEST_F(IdempotencyStoreTest, KeyMapsToTheJobItCreated) {
    const std::string digest = digestOf({"scene", "{}"});
    submit("job1", "key-1", digest, kT0);
    std::optional<IdempotencyEntry> entry = store_->findKey("key-1", kT0 + 5);
    ASSERT_TRUE(entry);
    EXPECT_EQ(entry->key, "key-1");
    EXPECT_EQ(entry->jobId, "job1");
    EXPECT_EQ(entry->requestHash, digest);
    EXPECT_EQ(entry->createdUnix, kT0);
}

TEST_F(IdempotencyStoreTest, UnknownKeyIsNotFound) {
    submit("job1", "key-1", "0000000000000001", kT0);
    EXPECT_FALSE(store_->findKey("key-2", kT0).has_value());
}

TEST_F(IdempotencyStoreTest, JobWithoutKeyStoresNone) {
    store_->insert(job("job1"));
    EXPECT_FALSE(store_->findKey("", kT0).has_value());
    EXPECT_EQ(store_->loadAll().size(), 1u);
}

TEST_F(IdempotencyStoreTest, KeysOfDifferentJobsAreKeptApart) {
    submit("job1", "key-1", "0000000000000001", kT0);
    submit("job2", "key-2", "0000000000000002", kT0 + 1);
    EXPECT_EQ(store_->findKey("key-1", kT0 + 2)->jobId, "job1");
    EXPECT_EQ(store_->findKey("key-2", kT0 + 2)->jobId, "job2");
}

TEST_F(IdempotencyStoreTest, KeyIsValidForExactlyItsWindow) {
    submit("job1", "key-1", "0000000000000001", kT0);
    EXPECT_TRUE(store_->findKey("key-1", kT0 + kIdempotencyKeySeconds).has_value());
    EXPECT_FALSE(store_->findKey("key-1", kT0 + kIdempotencyKeySeconds + 1).has_value());
}

TEST_F(IdempotencyStoreTest, WindowIsTwentyFourHours) { EXPECT_EQ(kIdempotencyKeySeconds, 86400); }

TEST_F(IdempotencyStoreTest, ReuseWithADifferentRequestIsDetectableByItsDigest) {
    const std::string original = digestOf({"scene", "{}", "passes=4"});
    const std::string other = digestOf({"scene", "{}", "passes=8"});
    submit("job1", "key-1", original, kT0);
    std::optional<IdempotencyEntry> entry = store_->findKey("key-1", kT0 + 60);
    ASSERT_TRUE(entry);
    // The service answers a retry with job1 when the digests match, else refuses it.
    EXPECT_EQ(entry->requestHash, original);
    EXPECT_NE(entry->requestHash, other);
}

TEST_F(IdempotencyStoreTest, ExpiredKeyMayNameANewJob) {
    submit("job1", "key-1", "0000000000000001", kT0);
    const int64_t later = kT0 + kIdempotencyKeySeconds + 1;
    ASSERT_FALSE(store_->findKey("key-1", later).has_value());
    submit("job2", "key-1", "0000000000000002", later);
    std::optional<IdempotencyEntry> entry = store_->findKey("key-1", later);
    ASSERT_TRUE(entry);
    EXPECT_EQ(entry->jobId, "job2");
    EXPECT_EQ(entry->requestHash, "0000000000000002");
    EXPECT_EQ(entry->createdUnix, later);
}

TEST_F(IdempotencyStoreTest, StoringAKeyForgetsKeysOlderThanTheWindow) {
    submit("job1", "old", "0000000000000001", kT0);
    submit("job2", "new", "0000000000000002", kT0 + kIdempotencyKeySeconds + 1);
    // Asked as of kT0 the old key would still be valid: only its deletion hides it.
    EXPECT_FALSE(store_->findKey("old", kT0).has_value());
    EXPECT_TRUE(store_->findKey("new", kT0 + kIdempotencyKeySeconds + 1).has_value());
    EXPECT_EQ(store_->loadAll().size(), 2u);  // the jobs themselves stay
}

TEST_F(IdempotencyStoreTest, StoringAKeyKeepsKeysStillInTheirWindow) {
    submit("job1", "old", "0000000000000001", kT0);
    submit("job2", "new", "0000000000000002", kT0 + kIdempotencyKeySeconds);
    EXPECT_TRUE(store_->findKey("old", kT0).has_value());
}

TEST_F(IdempotencyStoreTest, RemovingTheJobForgetsItsKey) {
    submit("job1", "key-1", "0000000000000001", kT0);
    submit("job2", "key-2", "0000000000000002", kT0);
    store_->remove("job1");
    EXPECT_FALSE(store_->findKey("key-1", kT0).has_value());
    EXPECT_TRUE(store_->findKey("key-2", kT0).has_value());
}

TEST_F(IdempotencyStoreTest, KeysSurviveReopen) {
    submit("job1", "key-1", "00000000000000ff", kT0);
    store_.reset();
    store_.emplace(dir_ / "jobs.db");
    std::optional<IdempotencyEntry> entry = store_->findKey("key-1", kT0 + 1);
    ASSERT_TRUE(entry);
    EXPECT_EQ(entry->jobId, "job1");
    EXPECT_EQ(entry->requestHash, "00000000000000ff");
}

TEST_F(IdempotencyStoreTest, KeyIsNotStoredWhenItsJobCannotBe) {
    submit("job1", "key-1", "0000000000000001", kT0);
    EXPECT_THROW(submit("job1", "key-2", "0000000000000002", kT0), std::exception);  // duplicate job id
    EXPECT_FALSE(store_->findKey("key-2", kT0).has_value());
    EXPECT_EQ(store_->findKey("key-1", kT0)->jobId, "job1");
}

}  // namespace idempotency_tests
