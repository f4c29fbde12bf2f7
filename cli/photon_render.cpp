// photon-render: renders a scene file to EXR and/or PNG with a progress bar on stderr.
// Ctrl-C (SIGINT) or SIGTERM stops the render within the pass in flight and still writes the
// image of the passes done (exit 130), and the checkpoint when one is asked for.
#include <photon/image_io.h>
#include <photon/render.h>
#include <photon/threads.h>
#include <cctype>
#include <chrono>
#include <csignal>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <optional>
#include <string>
#include "cli/option_checks.h"
#include "cli/render_options.h"

namespace {

namespace fs = std::filesystem;
using photon::cli::RenderOptions;

// The token a signal sets: an atomic flag, which a handler may store to.
photon::CancelToken gInterrupt;
extern "C" void onStopSignal(int) { gInterrupt.cancel(); }

std::string formatSeconds(double s) {
    char buf[32];
    int t = static_cast<int>(s + 0.5);
    std::snprintf(buf, sizeof buf, "%d:%02d:%02d", t / 3600, (t / 60) % 60, t % 60);
    return buf;
}

void printProgress(const photon::RenderProgress& p) {
    const int width = 30;
    int filled = p.totalPasses ? width * p.pass / p.totalPasses : 0;
    std::string bar(filled, '#');
    bar.resize(width, '.');
    char error[32] = "";
    if (p.relativeError) std::snprintf(error, sizeof error, "  error %.2f%%", 100 * *p.relativeError);
    std::fprintf(stderr, "\r[%s] pass %d/%d  %.3g photons/s  radius %.4g%s  elapsed %s  ETA %s ", bar.c_str(), p.pass,
                 p.totalPasses, p.photonsPerSecond, p.meanRadius, error, formatSeconds(p.elapsedSeconds).c_str(),
                 formatSeconds(p.etaSeconds).c_str());
    std::fflush(stderr);
}

void printScene(const photon::SceneFile& scene) {
    const photon::RenderSettings& r = scene.render();
    std::printf("scene ok: %dx%d pixels, %lld triangles, %s, %d passes of %lld photons\n", scene.width(),
                scene.height(), static_cast<long long>(scene.triangleCount()),
                std::string(photon::integratorName(r.integrator)).c_str(), r.passes,
                static_cast<long long>(r.photonsPerPass));
}

// Written to a temporary name and renamed, so a crash never leaves half a checkpoint.
void saveCheckpoint(const photon::Renderer& renderer, const fs::path& file) {
    const fs::path temporary = file.string() + ".tmp";
    {
        std::ofstream out(temporary, std::ios::binary);
        renderer.saveCheckpoint(out);
        if (!out.flush()) throw std::runtime_error("cannot write checkpoint " + temporary.string());
    }
    fs::rename(temporary, file);
}

void writeImages(const photon::Renderer& renderer, const RenderOptions& options) {
    // With render.denoise on, the EXR's R, G, B are denoised and it carries the raw image
    // and the guides as more channels; the PNG shows the denoised image.
    std::shared_ptr<const photon::PendingImage> image = renderer.pendingLayers();
    for (const std::string& out : options.outputs) {
        // checkOutputs let through .exr and .png names only, in any case.
        if (std::tolower(static_cast<unsigned char>(out[out.size() - 3])) == 'e') photon::writeExr(*image, out);
        else photon::writePng(*image, out);
    }
}

int render(const RenderOptions& options) {
    std::optional<photon::ThreadLimit> threads;
    if (options.threads) threads.emplace(static_cast<size_t>(*options.threads));
    photon::SceneFile scene = photon::SceneFile::read(options.scene, options.overrides(), {options.camera, options.lenient});
    // An import never leaves out or approximates anything silently.
    for (const std::string& w : scene.warnings()) std::fprintf(stderr, "photon-render: warning: %s\n", w.c_str());
    if (options.check) {
        printScene(scene);
        return 0;
    }
    photon::Renderer renderer(std::move(scene));
    if (!options.resume.empty()) {
        std::ifstream in(options.resume, std::ios::binary);
        renderer.restoreCheckpoint(in);
    }
    auto lastCheckpoint = std::chrono::steady_clock::now();
    photon::RenderOutcome outcome = renderer.run(gInterrupt, [&](const photon::RenderProgress& p) {
        if (!options.quiet) printProgress(p);
        if (!options.checkpoint.empty() && std::chrono::steady_clock::now() - lastCheckpoint > std::chrono::seconds(30)) {
            saveCheckpoint(renderer, options.checkpoint);
            lastCheckpoint = std::chrono::steady_clock::now();
        }
    });
    if (!options.quiet) std::fprintf(stderr, "\n");
    writeImages(renderer, options);
    if (!options.checkpoint.empty()) saveCheckpoint(renderer, options.checkpoint);
    if (outcome != photon::RenderOutcome::Cancelled) return 0;
    std::fprintf(stderr, "photon-render: interrupted; wrote the image of %d passes\n", renderer.progress().pass);
    return 130;  // 128 + SIGINT, as shells report an interrupted command
}

}  // namespace

int main(int argc, char** argv) {
    CLI::App app("Renders a scene to linear EXR and/or tone-mapped PNG.", "photon-render");
    RenderOptions options;
    photon::cli::declareOptions(app, options);
    if (int exit = photon::cli::parseCommandLine(app, argc, argv); exit >= 0) return exit;
    if (std::optional<std::string> wrong = photon::cli::checkOutputs(options)) {
        std::fprintf(stderr, "photon-render: %s\n%s", wrong->c_str(), app.help().c_str());
        return 2;
    }
    std::signal(SIGINT, onStopSignal);
    std::signal(SIGTERM, onStopSignal);
    try {
        return render(options);
    } catch (const photon::SceneError& e) {
        std::fprintf(stderr, "photon-render: %s: %s\n", options.scene.c_str(), e.what());
    } catch (const photon::CheckpointError& e) {
        std::fprintf(stderr, "photon-render: %s: %s\n", options.resume.c_str(), e.what());
    } catch (const std::exception& e) {
        std::fprintf(stderr, "photon-render: %s\n", e.what());
    }
    return 1;
}
