// The engine tests' main. With PHOTON_TEST_THREADS=N every test runs inside a oneTBB arena
// of N threads, however many cores the machine has: run with N well above them (say 64 on
// 2 cores), it shakes out tests that pass only because passes, chunks or cancels happen to
// line up with few threads.
#include <gtest/gtest.h>
#include <tbb/global_control.h>
#include <tbb/task_arena.h>
#include <cstdlib>
#include <cstdio>

int main(int argc, char** argv) {
    ::testing::InitGoogleTest(&argc, argv);
    const char* threads = std::getenv("PHOTON_TEST_THREADS");
    const int n = threads ? std::atoi(threads) : 0;
    if (n <= 0) return RUN_ALL_TESTS();
    std::printf("running every test in a oneTBB arena of %d threads\n", n);
    tbb::global_control limit(tbb::global_control::max_allowed_parallelism, static_cast<size_t>(n));
    tbb::task_arena arena(n);
    int result = 1;
    arena.execute([&] { result = RUN_ALL_TESTS(); });
    return result;
}
