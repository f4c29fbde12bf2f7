// Command-line checks shared by photon-render, photon-server and photon-bench, all of which
// declare their options with CLI11 (so each program's help text comes from the same
// declarations as its parsing).
#pragma once
#include <CLI/CLI.hpp>
#include <charconv>
#include <string>

namespace photon::cli {

// A whole decimal integer in [lo, hi] (declare the option with ->type_name("N")). CLI11 runs validators on the text before it
// converts it, so a bad value reads "--passes: expected an integer in [1, 1000000], got
// "zero"" rather than a conversion error.
inline CLI::Validator integerIn(long long lo, long long hi) {
    std::string range = "[" + std::to_string(lo) + ", " + std::to_string(hi) + "]";
    return CLI::Validator(
        [lo, hi, range](std::string& text) -> std::string {
            long long value = 0;
            const char* end = text.data() + text.size();
            auto [stop, error] = std::from_chars(text.data(), end, value);
            if (!text.empty() && error == std::errc() && stop == end && value >= lo && value <= hi) return "";
            return "expected an integer in " + range + ", got \"" + text + "\"";
        },
        "");  // the help shows the option as "N", its help text says what it is
}

// Parses argv into `app`. Returns the exit code for main to return, or -1 to go on: 0
// after printing --help or --version, 2 after printing "<program>: <what is wrong>" and the
// usage.
inline int parseCommandLine(CLI::App& app, int argc, char** argv) {
    app.set_version_flag("--version", std::string(app.get_name()) + " " + PHOTON_VERSION);
    try {
        app.parse(argc, argv);
        return -1;
    } catch (const CLI::CallForHelp&) {
        std::fputs(app.help().c_str(), stdout);
        return 0;
    } catch (const CLI::CallForVersion& e) {
        std::printf("%s\n", e.what());
        return 0;
    } catch (const CLI::ParseError& e) {
        std::fprintf(stderr, "%s: %s\n%s", app.get_name().c_str(), e.what(), app.help().c_str());
        return 2;
    }
}

}  // namespace photon::cli
