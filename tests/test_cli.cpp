// photon-render end to end: writes a readable EXR of the scene's size, and on a bad
// scene exits non-zero with the error's JSON path.
#include <gtest/gtest.h>
#include <sys/wait.h>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <photon/image_io.h>
#include <photon/render.h>
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

TEST(Cli, ANonSquareImageKeepsItsShapeAndItsSides) {
    // The Cornell box at 48x24: red wall left, green wall right, the light at the top; the
    // EXR the CLI writes equals the engine's render of the same scene.
    auto dir = tempDir();
    std::ifstream in(test::sourcePath("scenes/cornell-box.json"));
    nlohmann::json scene = nlohmann::json::parse(in);
    scene["camera"]["resolution"] = {48, 24};
    scene["render"]["passes"] = 2;
    scene["render"]["photons_per_pass"] = 20000;
    std::ofstream(dir / "wide.json") << scene.dump();
    CommandResult r = runRender((dir / "wide.json").string() + " -o " + (dir / "wide.exr").string() + " --quiet");
    ASSERT_EQ(r.exitCode, 0) << r.output;
    Image image = readImage(dir / "wide.exr");
    ASSERT_EQ(image.width, 48);
    ASSERT_EQ(image.height, 24);
    Renderer renderer(SceneFile::parseJson(scene.dump(), test::sourcePath("scenes")));
    CancelToken cancel;
    renderer.run(cancel);
    EXPECT_TRUE(image.rgb == renderer.snapshot().rgb);
    Color left = test::meanOver(image, 0, 0, 24, 24), right = test::meanOver(image, 24, 0, 48, 24);
    // The light is orange, so every half is redder than green; the red wall makes the left
    // half redder than the right.
    EXPECT_GT(left.x / left.y, 1.2f * right.x / right.y) << "red wall on the left, green on the right";
    int brightestRow = 0;
    float brightest = 0;
    for (int y = 0; y < 24; ++y)
        for (int x = 0; x < 48; ++x)
            if (float l = luminance(image.at(x, y)); l > brightest) brightest = l, brightestRow = y;
    EXPECT_LT(brightestRow, 6) << "the light in the ceiling, at the top";
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
