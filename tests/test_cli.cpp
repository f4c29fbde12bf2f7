// photon-render end to end: writes a readable EXR of the scene's size, and on a bad
// scene exits non-zero with the error's JSON path.
#include <gtest/gtest.h>
#include <sys/wait.h>
#include <unistd.h>
#include <csignal>
#include <chrono>
#include <thread>
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

// A pbrt scene with a medium of a kind photon does not render: refused, naming its line;
// with --lenient rendered without it, the warning printed.
TEST(Cli, LenientRendersAPbrtSceneWithoutWhatItCannot) {
    auto dir = tempDir();
    std::ofstream(dir / "fog.pbrt") << R"(LookAt 0 1 5  0 1 0  0 1 0
Camera "perspective" "float fov" [40]
Film "rgb" "integer xresolution" [8] "integer yresolution" [8]
WorldBegin
MakeNamedMedium "fog" "string type" "rgbgrid"
LightSource "infinite" "rgb L" [1 1 1]
Shape "sphere" "float radius" [1]
)";
    const std::string args = (dir / "fog.pbrt").string() + " -o " + (dir / "fog.exr").string() + " --passes 1 --quiet";
    CommandResult strict = runRender(args);
    EXPECT_EQ(strict.exitCode, 1);
    EXPECT_NE(strict.output.find("fog.pbrt:5: medium \"fog\": a \"rgbgrid\" medium is not supported"),
              std::string::npos) << strict.output;
    CommandResult lenient = runRender(args + " --lenient");
    EXPECT_EQ(lenient.exitCode, 0) << lenient.output;
    EXPECT_NE(lenient.output.find("\"cloud\" media); left out (lenient import)"), std::string::npos) << lenient.output;
    EXPECT_TRUE(std::filesystem::exists(dir / "fog.exr"));
    std::filesystem::remove_all(dir);
}

TEST(Cli, BadOptionsExitWithUsage) {
    CommandResult r = runRender("scene.json -o x.exr --passes zero");
    EXPECT_EQ(r.exitCode, 2);
    EXPECT_NE(r.output.find("--passes: expected an integer"), std::string::npos) << r.output;
}

TEST(Cli, OutputFormatFollowsTheExtension) {
    auto dir = tempDir();
    const std::string scene = test::sourcePath("scenes/cornell-box.json").string();
    CommandResult r = runRender(scene + " -D camera.resolution=[24,16] -D render.exposure=1 --passes 2 "
                                "--photons-per-pass 2000 --quiet -o " + (dir / "a.exr").string() + " -o " +
                                (dir / "a.PNG").string());
    ASSERT_EQ(r.exitCode, 0) << r.output;
    Image linear = readImage(dir / "a.exr"), png = readImage(dir / "a.PNG");
    ASSERT_EQ(png.width, 24);
    ASSERT_EQ(png.height, 16);
    std::vector<uint8_t> expected = toneMapToSrgb8(linear, 1.0f);
    for (size_t i = 0; i < expected.size(); ++i) ASSERT_FLOAT_EQ(png.rgb[i], expected[i] / 255.0f) << i;
    std::filesystem::remove_all(dir);
}

TEST(Cli, BadOutputsAreRefusedBeforeRendering) {
    const std::string scene = test::sourcePath("scenes/cornell-box.json").string();
    CommandResult tiff = runRender(scene + " -o /tmp/x.tif");
    EXPECT_EQ(tiff.exitCode, 2);
    EXPECT_NE(tiff.output.find("-o /tmp/x.tif: the name must end in .exr or .png"), std::string::npos) << tiff.output;
    CommandResult folder = runRender(scene + " -o /nonexistent-folder/x.exr");
    EXPECT_EQ(folder.exitCode, 2);
    EXPECT_NE(folder.output.find("-o /nonexistent-folder/x.exr: cannot write in /nonexistent-folder"),
              std::string::npos)
        << folder.output;
    EXPECT_EQ(folder.output.find("pass 1/"), std::string::npos);  // nothing was rendered
}

TEST(Cli, VersionAndCheck) {
    CommandResult version = runRender("--version");
    EXPECT_EQ(version.exitCode, 0);
    EXPECT_EQ(version.output, "photon-render " PHOTON_VERSION_FOR_TESTS "\n");
    CommandResult check = runRender(test::sourcePath("scenes/cornell-box.json").string() + " --check --spp 3");
    EXPECT_EQ(check.exitCode, 0) << check.output;
    EXPECT_EQ(check.output, "scene ok: 512x512 pixels, 32 triangles, sppm, 3 passes of 200000 photons\n");
}

TEST(Cli, DefinesOverrideSettingsAndAreCheckedLikeTheScenesOwn) {
    auto dir = tempDir();
    const std::string scene = test::sourcePath("scenes/cornell-box.json").string() + " --quiet -o " + (dir / "d.exr").string();
    CommandResult ok = runRender(scene + " -D render.passes=2 -D camera.resolution=[16,8] --photons-per-pass 1000");
    ASSERT_EQ(ok.exitCode, 0) << ok.output;
    Image image = readImage(dir / "d.exr");
    EXPECT_EQ(image.width, 16);
    EXPECT_EQ(image.height, 8);
    CommandResult geometry = runRender(scene + " -D shapes.radius=1");
    EXPECT_EQ(geometry.exitCode, 1);
    EXPECT_NE(geometry.output.find("shapes.radius: only render.* and camera.* settings can be overridden"),
              std::string::npos)
        << geometry.output;
    CommandResult range = runRender(scene + " -D render.alpha=2");
    EXPECT_EQ(range.exitCode, 1);
    EXPECT_NE(range.output.find("render.alpha: must be"), std::string::npos) << range.output;
    std::filesystem::remove_all(dir);
}

TEST(Cli, AFractionalTimeLimitEndsTheRender) {
    auto dir = tempDir();
    CommandResult r = runRender(test::sourcePath("scenes/cornell-box.json").string() +
                                " -D camera.resolution=[16,16] --photons-per-pass 1000 --passes 1000000 --time-limit 0.25 "
                                "--quiet -o " + (dir / "t.exr").string());
    EXPECT_EQ(r.exitCode, 0) << r.output;
    EXPECT_EQ(readImage(dir / "t.exr").width, 16);
    std::filesystem::remove_all(dir);
}

TEST(Cli, AResumedRenderEndsWhereAnUninterruptedOneDoes) {
    auto dir = tempDir();
    const std::string scene = test::sourcePath("scenes/cornell-box.json").string() +
                              " -D camera.resolution=[24,24] --photons-per-pass 5000 --quiet";
    ASSERT_EQ(runRender(scene + " --passes 4 -o " + (dir / "whole.exr").string()).exitCode, 0);
    ASSERT_EQ(runRender(scene + " --passes 2 -o " + (dir / "half.exr").string() + " --checkpoint " +
                        (dir / "state.bin").string())
                  .exitCode,
              0);
    CommandResult resumed = runRender(scene + " --passes 4 -o " + (dir / "resumed.exr").string() + " --resume " +
                                      (dir / "state.bin").string());
    ASSERT_EQ(resumed.exitCode, 0) << resumed.output;
    EXPECT_TRUE(readImage(dir / "resumed.exr").rgb == readImage(dir / "whole.exr").rgb);
    CommandResult other = runRender(scene + " --passes 4 --seed 99 -o " + (dir / "x.exr").string() + " --resume " +
                                    (dir / "state.bin").string());
    EXPECT_EQ(other.exitCode, 1);
    EXPECT_NE(other.output.find("made with other render settings"), std::string::npos) << other.output;
    std::filesystem::remove_all(dir);
}

TEST(Cli, SigintStopsTheRenderAndStillWritesItsImage) {
    auto dir = tempDir();
    const std::filesystem::path log = dir / "stderr.txt", out = dir / "i.exr";
    pid_t pid = fork();
    if (pid == 0) {
        std::freopen(log.c_str(), "w", stderr);
        const std::string scene = test::sourcePath("scenes/cornell-box.json").string();
        execl(PHOTON_RENDER_BIN, PHOTON_RENDER_BIN, scene.c_str(), "-D", "camera.resolution=[32,32]",
              "--photons-per-pass", "20000", "--passes", "1000000", "-o", out.c_str(), nullptr);
        _exit(127);
    }
    // Once a pass is done (its progress line is out), interrupt.
    for (int waited = 0; waited < 30000; waited += 20) {
        std::ifstream in(log);
        std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
        if (text.find("pass 1/") != std::string::npos) break;
        std::this_thread::sleep_for(std::chrono::milliseconds(20));
    }
    kill(pid, SIGINT);
    int status = 0;
    waitpid(pid, &status, 0);
    ASSERT_TRUE(WIFEXITED(status));
    EXPECT_EQ(WEXITSTATUS(status), 130);
    Image image = readImage(out);
    EXPECT_EQ(image.width, 32);
    EXPECT_GT(test::meanOver(image, 0, 0, 32, 32).y, 0.0f);
    std::ifstream in(log);
    std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    EXPECT_NE(text.find("interrupted; wrote the image of"), std::string::npos) << text;
    std::filesystem::remove_all(dir);
}

}  // namespace
}  // namespace photon
