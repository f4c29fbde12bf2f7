// A plane whose albedo is a texture, under a point light: its radiance is
// albedo(u, v) / pi * I cos(theta) / r^2 point by point, so the image follows the texture.
// The texture is a ramp that is different along u and v and under every flip, so a mapping
// turned or mirrored anywhere (file rows, the quad's corners, v's direction) shows.
#include <gtest/gtest.h>
#include <unistd.h>
#include <fstream>
#include <photon/image_io.h>
#include <photon/render.h>
#include "camera/camera.h"
#include "integrators/integrator.h"
#include "scene/scene.h"
#include "texture/image_texture.h"
#include "test_support.h"

namespace photon {
namespace {

constexpr float kIntensity = 10.0f, kHeight = 1.0f;
constexpr int kResolution = 64;

// The plane spans [-1, 1] in x and z; the quad's corner uvs make u run along +x and v
// along -z (origin (-1, 0, 1), edge_u +x, edge_v -z).
const char* kScene = R"({
  "camera": {"position": [0, 3, 0], "look_at": [0, 0, 0], "up": [0, 0, -1], "fov": 50,
             "resolution": [64, 64]},
  "materials": {"ramp": {"type": "diffuse", "albedo": {"texture": "ramp.png"}}},
  "shapes": [{"type": "quad", "origin": [-1, 0, 1], "edge_u": [2, 0, 0], "edge_v": [0, 0, -2],
              "material": "ramp"}],
  "lights": [{"type": "point", "position": [0, 1, 0], "intensity": [10, 10, 10]}],
  "render": {"integrator": "sppm", "direct": "light_sampling", "passes": 16, "photons_per_pass": 1000,
             "max_depth": 1}
})";

// Red grows with u, green with v, blue with u * v: 8 x 8 texels, written as an sRGB PNG.
void writeRamp(const std::filesystem::path& file) {
    Image ramp(8, 8);
    for (int y = 0; y < 8; ++y)
        for (int x = 0; x < 8; ++x) {
            float u = (x + 0.5f) / 8, v = 1 - (y + 0.5f) / 8;  // v = 0 at the bottom row
            ramp.set(x, y, {0.1f + 0.8f * u, 0.1f + 0.8f * v, 0.1f + 0.8f * u * v});
        }
    writePng(ramp, file, 0);
}

TEST(TexturedAlbedo, RadianceFollowsTheTexture) {
    std::filesystem::path dir = std::filesystem::temp_directory_path() / ("photon-ramp-" + std::to_string(::getpid()));
    std::filesystem::create_directories(dir);
    writeRamp(dir / "ramp.png");
    SceneDescription d = loadSceneJson(kScene, dir);
    std::shared_ptr<const ImageTexture> texture = ImageTexture::load(dir / "ramp.png");  // as the loader reads it
    std::filesystem::remove_all(dir);
    Camera camera(d.camera);
    Renderer renderer(Scene::build(std::move(d)));
    CancelToken cancel;
    ASSERT_EQ(renderer.run(cancel), RenderOutcome::Completed);
    Image image = renderer.snapshot();

    // Each 4x4 block inside the plane against the analytic radiance averaged over it.
    int blocks = 0;
    for (int by = 12; by + 4 <= 52; by += 4)
        for (int bx = 12; bx + 4 <= 52; bx += 4) {
            Color expected(0.0f);
            const int n = 4;  // samples per pixel side
            for (int y = by; y < by + 4; ++y)
                for (int x = bx; x < bx + 4; ++x)
                    for (int j = 0; j < n; ++j)
                        for (int i = 0; i < n; ++i) {
                            Ray ray = camera.generateRay(x + (i + 0.5f) / n, y + (j + 0.5f) / n, {0.5f, 0.5f});
                            Vec3 p = ray.o + ray.d * (-ray.o.y / ray.d.y);
                            Vec2 uv{(p.x + 1) / 2, (1 - p.z) / 2};
                            float r2 = p.x * p.x + p.z * p.z + kHeight * kHeight;
                            float cosTheta = kHeight / std::sqrt(r2);
                            expected += texture->lookup({uv}) * (kInvPi * kIntensity * cosTheta / r2);
                        }
            expected = expected / float(16 * n * n);
            Color got = test::meanOver(image, bx, by, bx + 4, by + 4);
            for (int c = 0; c < 3; ++c)
                EXPECT_NEAR(got[c], expected[c], 0.02f * expected[c]) << "block " << bx << "," << by << " channel " << c;
            ++blocks;
        }
    EXPECT_EQ(blocks, 100);
}

}  // namespace
}  // namespace photon
