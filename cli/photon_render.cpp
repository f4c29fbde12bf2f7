// photon-render: renders a scene file to EXR and/or PNG with a progress bar on stderr.
#include <tbb/global_control.h>
#include <cstdio>
#include <cstdlib>
#include <iostream>
#include <optional>
#include <string>
#include "film/image_io.h"
#include "render.h"

namespace {

const char* kUsage =
    "usage: photon-render SCENE.json [-o OUT.exr] [--png OUT.png] [--passes N] [--photons-per-pass N]\n"
    "                     [--time-limit SECONDS] [--threads N] [--seed N] [--integrator sppm|path|radiosity|photonmap] [--quiet]\n";

struct Options {
    std::string scene, exr, png;
    std::optional<long long> passes, photons, threads, seed;
    std::optional<double> timeLimit;
    std::string integrator;
    bool quiet = false;
};

long long parseInteger(const std::string& flag, const std::string& v, long long lo, long long hi) {
    try {
        size_t used = 0;
        long long n = std::stoll(v, &used);
        if (used == v.size() && n >= lo && n <= hi) return n;
    } catch (const std::exception&) {
    }
    throw std::invalid_argument(flag + ": expected an integer in [" + std::to_string(lo) + ", " + std::to_string(hi) +
                                "], got \"" + v + "\"");
}

Options parseOptions(int argc, char** argv) {
    Options o;
    for (int i = 1; i < argc; ++i) {
        std::string a = argv[i];
        auto value = [&]() -> std::string {
            if (i + 1 >= argc) throw std::invalid_argument(a + ": missing value");
            return argv[++i];
        };
        if (a == "-o" || a == "--output") o.exr = value();
        else if (a == "--png") o.png = value();
        else if (a == "--passes") o.passes = parseInteger(a, value(), 1, 1000000);
        else if (a == "--photons-per-pass") o.photons = parseInteger(a, value(), 1, 100000000);
        else if (a == "--threads") o.threads = parseInteger(a, value(), 1, 1024);
        else if (a == "--seed") o.seed = parseInteger(a, value(), 0, 1LL << 62);
        else if (a == "--time-limit") o.timeLimit = static_cast<double>(parseInteger(a, value(), 0, 1 << 30));
        else if (a == "--integrator") o.integrator = value();
        else if (a == "--quiet") o.quiet = true;
        else if (a == "-h" || a == "--help") {
            std::cout << kUsage;
            std::exit(0);
        } else if (!a.empty() && a[0] == '-') throw std::invalid_argument("unknown option " + a);
        else if (o.scene.empty()) o.scene = a;
        else throw std::invalid_argument("more than one scene given");
    }
    if (o.scene.empty()) throw std::invalid_argument("no scene file given");
    if (o.exr.empty() && o.png.empty()) throw std::invalid_argument("give -o OUT.exr and/or --png OUT.png");
    return o;
}

void applyOverrides(const Options& o, photon::RenderSettings& s) {
    if (o.passes) s.passes = static_cast<int>(*o.passes);
    if (o.photons) s.photonsPerPass = *o.photons;
    if (o.seed) s.seed = static_cast<uint64_t>(*o.seed);
    if (o.timeLimit) s.timeLimitSeconds = *o.timeLimit;
    if (o.integrator.empty()) return;
    std::optional<photon::IntegratorKind> kind = photon::integratorNamed(o.integrator);
    if (!kind) throw std::invalid_argument("--integrator: expected sppm, path, radiosity or photonmap");
    s.integrator = *kind;
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
    Options options;
    try {
        options = parseOptions(argc, argv);
    } catch (const std::exception& e) {
        std::fprintf(stderr, "photon-render: %s\n%s", e.what(), kUsage);
        return 2;
    }
    try {
        std::optional<tbb::global_control> threads;
        if (options.threads)
            threads.emplace(tbb::global_control::max_allowed_parallelism, static_cast<size_t>(*options.threads));
        photon::SceneDescription description = photon::loadSceneFile(options.scene);
        applyOverrides(options, description.render);
        float exposure = description.render.exposure;
        photon::Renderer renderer(photon::Scene::build(std::move(description)));
        photon::CancelToken cancel;
        renderer.run(cancel, options.quiet ? photon::Renderer::ProgressFn{} : printProgress);
        if (!options.quiet) std::fprintf(stderr, "\n");
        // With render.denoise on, the EXR's R, G, B are denoised and it carries the raw image
        // and the guides as more channels; the PNG shows the denoised image.
        photon::LayeredImage image = renderer.layers();
        if (!options.exr.empty()) photon::writeExr(image, options.exr);
        if (!options.png.empty()) photon::writePng(image.main, options.png, exposure);
    } catch (const photon::SceneError& e) {
        std::fprintf(stderr, "photon-render: %s: %s\n", options.scene.c_str(), e.what());
        return 1;
    } catch (const std::exception& e) {
        std::fprintf(stderr, "photon-render: %s\n", e.what());
        return 1;
    }
    return 0;
}
