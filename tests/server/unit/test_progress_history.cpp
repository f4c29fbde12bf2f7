// A job's progress history: every pass while there is room, then thinned evenly to at most
// 256 points with the latest always kept; a render that goes back replaces what followed;
// saved and read back exactly. And which passes are kept as images.
#include <gtest/gtest.h>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <unistd.h>
#include "server/kept_passes.h"
#include "server/progress_history.h"

namespace photon::server {
namespace {

JobProgress progressAt(int pass) {
    // The relative error from pass 2 on, as renders report it.
    return JobProgress{pass,
                       int64_t(pass) * 1000,
                       1.0 / pass,
                       pass * 0.1,
                       0,
                       pass >= 2 ? std::optional<double>(0.3 / std::sqrt(pass)) : std::nullopt};
}

TEST(ProgressHistory, KeepsEveryPassWhileThereIsRoomThenThinsEvenly) {
    ProgressHistory h;
    for (int pass = 1; pass <= 255; ++pass) h.add(progressAt(pass));
    ASSERT_EQ(h.points().size(), 255u);
    h.add(progressAt(256));  // full: every other point goes, and the latest stays
    ASSERT_EQ(h.points().size(), 129u);
    EXPECT_EQ(h.points()[0].pass, 1);
    EXPECT_EQ(h.points()[1].pass, 3);
    EXPECT_EQ(h.points()[127].pass, 255);
    EXPECT_EQ(h.points()[128].pass, 256);
    for (int pass = 257; pass <= 100000; ++pass) h.add(progressAt(pass));
    EXPECT_LE(h.points().size(), ProgressHistory::kMaxPoints);
    EXPECT_GE(h.points().size(), ProgressHistory::kMaxPoints / 2);
    // Evenly: after the first, the points' steps differ at most by the one after a thinning.
    const ProgressPoint& last = h.points().back();
    EXPECT_GT(last.pass, 100000 - 1024);
    EXPECT_EQ(last.photonsTraced, int64_t(last.pass) * 1000);
    EXPECT_DOUBLE_EQ(last.meanRadius, 1.0 / last.pass);
}

TEST(ProgressHistory, ARenderThatGoesBackReplacesWhatFollowed) {
    ProgressHistory h;
    for (int pass = 1; pass <= 10; ++pass) h.add(progressAt(pass));
    h.add(progressAt(6));  // resumed from the checkpoint after pass 5
    ASSERT_EQ(h.points().size(), 6u);
    EXPECT_EQ(h.points().back().pass, 6);
}

TEST(ProgressHistory, SavedAndReadBackExactly) {
    const auto file = std::filesystem::temp_directory_path() / ("photon-progress-" + std::to_string(getpid()) + ".txt");
    ProgressHistory h;
    for (int pass = 1; pass <= 300; ++pass) h.add(progressAt(pass));
    h.save(file);
    ProgressHistory back = ProgressHistory::load(file);
    ASSERT_EQ(back.points().size(), h.points().size());
    for (size_t i = 0; i < h.points().size(); ++i) {
        EXPECT_EQ(back.points()[i].pass, h.points()[i].pass);
        EXPECT_EQ(back.points()[i].elapsedSeconds, h.points()[i].elapsedSeconds);
        EXPECT_EQ(back.points()[i].meanRadius, h.points()[i].meanRadius);
        EXPECT_EQ(back.points()[i].relativeError, h.points()[i].relativeError);
    }
    EXPECT_FALSE(back.points()[0].relativeError.has_value());
    // It goes on thinning at the stride it was saved with: pass 301 is skipped, 302 taken.
    back.add(progressAt(301));
    EXPECT_EQ(back.points().back().pass, h.points().back().pass);
    back.add(progressAt(302));
    EXPECT_EQ(back.points().back().pass, 302);
    std::filesystem::remove(file);
    EXPECT_TRUE(ProgressHistory::load(file).points().empty());  // none: an empty history
}

TEST(ProgressHistory, AFileFromBeforeTheErrorEstimateIsReadWithNone) {
    const auto file = std::filesystem::temp_directory_path() / ("photon-progress-old-" + std::to_string(getpid()) + ".txt");
    std::ofstream(file) << "stride 1\nfigures 0 0 0 0 0\n1 0.5 1000 0.25\n2 1 2000 0.125\n";
    const ProgressHistory h = ProgressHistory::load(file);
    ASSERT_EQ(h.points().size(), 2u);
    EXPECT_EQ(h.points()[1].pass, 2);
    EXPECT_EQ(h.points()[1].meanRadius, 0.125);
    EXPECT_FALSE(h.points()[1].relativeError.has_value());
    std::filesystem::remove(file);
}

TEST(KeptPasses, TheFirstPassAtOrAfterEachPowerOfTwo) {
    std::vector<int> kept;
    for (int pass : {1, 2, 3, 4, 5, 7, 8, 9, 15, 16, 17}) {
        if (isKeptPass(pass, kept)) kept.push_back(pass);
    }
    EXPECT_EQ(kept, (std::vector<int>{1, 2, 4, 8, 16}));
    // Batches of four passes report 4, 8, 12, 16, 20: the first of each range is kept.
    kept.clear();
    for (int pass : {4, 8, 12, 16, 20, 24, 28, 32, 36}) {
        if (isKeptPass(pass, kept)) kept.push_back(pass);
    }
    EXPECT_EQ(kept, (std::vector<int>{4, 8, 16, 32}));
    EXPECT_FALSE(isKeptPass(0, {}));
}

}  // namespace
}  // namespace photon::server
