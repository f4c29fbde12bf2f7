// photon-render end to end: writes a readable EXR of the scene's size, and on a bad
// scene exits non-zero with the error's JSON path.
#include <gtest/gtest.h>
#include <sys/wait.h>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <photon/image_io.h>
#include "test_support.h"

namespace photon {
namespace {

struct CommandResult {
    int exitCode = -1;
    std::string output;  // stdout and stderr
};

CommandResult runRender(const std::string& args) {
    std::string cmd = std::string(PHOTON_RENDER_BIN) + " " + args + " 2>&1";
    CommandResult r;
    FILE* pipe = popen(cmd.c_str(), "r");
    char buf[4096];
    size_t n;
    while ((n = fread(buf, 1, sizeof buf, pipe)) > 0) r.output.append(buf, n);
    int status = pclose(pipe);
    r.exitCode = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
    return r;
}

std::filesystem::path tempDir() {
    auto dir = std::filesystem::temp_directory_path() / ("photon-cli-" + std::to_string(getpid()));
    std::filesystem::create_directories(dir);
    return dir;
}

TEST(Cli, RendersSceneToExrAndPng) {
    auto dir = tempDir();
    CommandResult r = runRender(test::sourcePath("scenes/point-light-plane.json").string() + " -o " + (dir / "out.exr").string() +
                      " --png " + (dir / "out.png").string() + " --passes 2 --photons-per-pass 1000 --threads 2");
    ASSERT_EQ(r.exitCode, 0) << r.output;
    EXPECT_NE(r.output.find("pass 2/2"), std::string::npos) << r.output;
    Image exr = readImage(dir / "out.exr");
    Image png = readImage(dir / "out.png");
    EXPECT_EQ(exr.width, 512);
    EXPECT_EQ(exr.height, 512);
    EXPECT_EQ(png.width, 512);
    EXPECT_GT(test::meanOver(exr, 200, 200, 312, 312).y, 0.0f);
    std::filesystem::remove_all(dir);
}

TEST(Cli, BadSceneExitsWithTheJsonPath) {
    auto dir = tempDir();
    std::ofstream(dir / "bad.json") << R"({"camera": {"position": [0, 0, 5], "look_at": [0, 0, 0], "fov": 40, "resolution": [8, 8]}, "materials": {"m": {"type": "diffuse"}},
        "shapes": [{"type": "sphere", "center": [0, 0, 0], "radius": -1, "material": "m"}]})";
    CommandResult r = runRender((dir / "bad.json").string() + " -o " + (dir / "x.exr").string());
    EXPECT_EQ(r.exitCode, 1);
    EXPECT_NE(r.output.find("shapes[0].radius: must be > 0"), std::string::npos) << r.output;
    EXPECT_FALSE(std::filesystem::exists(dir / "x.exr"));
    std::filesystem::remove_all(dir);
}

TEST(Cli, BadOptionsExitWithUsage) {
    CommandResult r = runRender("scene.json -o x.exr --passes zero");
    EXPECT_EQ(r.exitCode, 2);
    EXPECT_NE(r.output.find("--passes: expected an integer"), std::string::npos) << r.output;
}

}  // namespace
}  // namespace photon
