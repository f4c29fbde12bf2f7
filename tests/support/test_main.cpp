// The main of every test program (engine and service).
//
// --photon_source=FILE.cpp runs the cases defined in that source file alone. Each test
// program holds many sources compiled a few to a unit (tests/CMakeLists.txt,
// photon_add_test_group), and ctest runs it once per source, so that results, reports and
// parallelism stay per source while the sources share their compilation. It is combined with
// a negative filter (--gtest_filter=-A.B or GTEST_FILTER): the source's cases but those.
//
// With PHOTON_TEST_THREADS=N every test runs inside a oneTBB arena of N threads, however
// many cores the machine has: run with N well above them (say 64 on 2 cores), it shakes out
// tests that pass only because passes, chunks or cancels happen to line up with few threads.
#include <gtest/gtest.h>
#include <tbb/global_control.h>
#include <tbb/task_arena.h>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <string>
#include <string_view>

namespace {

// Removes --photon_source=FILE from argv and returns FILE ("" without it).
std::string takeSourceArgument(int& argc, char** argv) {
    constexpr std::string_view prefix = "--photon_source=";
    std::string source;
    int kept = 1;
    for (int i = 1; i < argc; ++i) {
        const std::string_view argument = argv[i];
        if (argument.substr(0, prefix.size()) == prefix) {
            source = std::string(argument.substr(prefix.size()));
        } else {
            argv[kept++] = argv[i];
        }
    }
    argc = kept;
    return source;
}

// Narrows gtest's filter to the cases defined in `source` (a file name, matched against the
// file each case was defined in). False, with a message, if the filter names cases itself
// or the source defines none.
bool selectCasesOf(const std::string& source) {
    const std::string filter = GTEST_FLAG_GET(filter);
    const auto dash = filter.find('-');
    const std::string positive = filter.substr(0, dash);
    const std::string negative = dash == std::string::npos ? "" : filter.substr(dash);
    if (!positive.empty() && positive != "*") {
        std::fprintf(stderr, "--photon_source=%s takes a negative filter only, not '%s'\n",
                     source.c_str(), filter.c_str());
        return false;
    }
    const ::testing::UnitTest& tests = *::testing::UnitTest::GetInstance();
    std::string cases;
    for (int s = 0; s < tests.total_test_suite_count(); ++s) {
        const ::testing::TestSuite& suite = *tests.GetTestSuite(s);
        for (int t = 0; t < suite.total_test_count(); ++t) {
            const ::testing::TestInfo& info = *suite.GetTestInfo(t);
            if (std::filesystem::path(info.file()).filename() != source) continue;
            if (!cases.empty()) cases += ':';
            cases += std::string(info.test_suite_name()) + '.' + info.name();
        }
    }
    if (cases.empty()) {
        std::fprintf(stderr, "--photon_source=%s: this program defines no test in that file\n", source.c_str());
        return false;
    }
    GTEST_FLAG_SET(filter, cases + negative);
    return true;
}

}  // namespace

int main(int argc, char** argv) {
    ::testing::InitGoogleTest(&argc, argv);
    const std::string source = takeSourceArgument(argc, argv);
    if (!source.empty() && !selectCasesOf(source)) return 2;
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
