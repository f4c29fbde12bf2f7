// photon-render: renders a scene file to EXR and/or PNG with a progress bar on stderr.
#include <photon/image_io.h>
#include <photon/render.h>
#include <photon/threads.h>
#include <cstdio>
#include <optional>
#include <string>
#include "cli/option_checks.h"

namespace {

struct Options {
    std::string scene, exr, png;
    std::optional<long long> passes, photons, threads, seed, timeLimit;
    std::string integrator;
    bool quiet = false;
};

void declareOptions(CLI::App& app, Options& o) {
    using photon::cli::integerIn;
    app.add_option("scene", o.scene, "the scene file (JSON)")->required();
    app.add_option("-o,--output", o.exr, "linear HDR EXR to write");
    app.add_option("--png", o.png, "tone-mapped PNG to write (the scene's exposure, sRGB)");
    app.add_option("--passes", o.passes, "passes (samples per pixel for the path tracer)")->type_name("N")->check(integerIn(1, 1000000));
    app.add_option("--photons-per-pass", o.photons, "photons per pass")->type_name("N")->check(integerIn(1, 100000000));
    app.add_option("--time-limit", o.timeLimit, "stop after the pass that crosses this many seconds")
        ->type_name("N")->check(integerIn(0, 1 << 30));
    app.add_option("--threads", o.threads, "threads (default: one per core)")->type_name("N")->check(integerIn(1, 1024));
    app.add_option("--seed", o.seed, "random seed")->type_name("N")->check(integerIn(0, 1LL << 62));
    std::vector<std::string> names(photon::kIntegratorNames.begin(), photon::kIntegratorNames.end());
    app.add_option("--integrator", o.integrator, "the integrator, instead of the scene's")->check(CLI::IsMember(names));
    app.add_flag("--quiet", o.quiet, "no progress bar");
}

void applyOverrides(const Options& o, photon::RenderSettings& s) {
    if (o.passes) s.passes = static_cast<int>(*o.passes);
    if (o.photons) s.photonsPerPass = *o.photons;
    if (o.seed) s.seed = static_cast<uint64_t>(*o.seed);
    if (o.timeLimit) s.timeLimitSeconds = static_cast<double>(*o.timeLimit);
    if (!o.integrator.empty()) s.integrator = *photon::integratorNamed(o.integrator);
}

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
    std::fprintf(stderr, "\r[%s] pass %d/%d  %.3g photons/s  radius %.4g  elapsed %s  ETA %s ", bar.c_str(), p.pass,
                 p.totalPasses, p.photonsPerSecond, p.meanRadius, formatSeconds(p.elapsedSeconds).c_str(),
                 formatSeconds(p.etaSeconds).c_str());
    std::fflush(stderr);
}

}  // namespace

int main(int argc, char** argv) {
    CLI::App app("Renders a scene to linear EXR and/or tone-mapped PNG.", "photon-render");
    Options options;
    declareOptions(app, options);
    if (int exit = photon::cli::parseCommandLine(app, argc, argv); exit >= 0) return exit;
    if (options.exr.empty() && options.png.empty()) {
        std::fprintf(stderr, "photon-render: give -o OUT.exr and/or --png OUT.png\n%s", app.help().c_str());
        return 2;
    }
    try {
        std::optional<photon::ThreadLimit> threads;
        if (options.threads) threads.emplace(static_cast<size_t>(*options.threads));
        photon::SceneFile scene = photon::SceneFile::read(options.scene);
        applyOverrides(options, scene.render());
        photon::Renderer renderer(std::move(scene));
        photon::CancelToken cancel;
        renderer.run(cancel, options.quiet ? photon::Renderer::ProgressFn{} : printProgress);
        if (!options.quiet) std::fprintf(stderr, "\n");
        // With render.denoise on, the EXR's R, G, B are denoised and it carries the raw image
        // and the guides as more channels; the PNG shows the denoised image.
        std::shared_ptr<const photon::PendingImage> image = renderer.pendingLayers();
        if (!options.exr.empty()) photon::writeExr(*image, options.exr);
        if (!options.png.empty()) photon::writePng(*image, options.png);
    } catch (const photon::SceneError& e) {
        std::fprintf(stderr, "photon-render: %s: %s\n", options.scene.c_str(), e.what());
        return 1;
    } catch (const std::exception& e) {
        std::fprintf(stderr, "photon-render: %s\n", e.what());
        return 1;
    }
    return 0;
}
