#include "cli/render_options.h"
#include <unistd.h>
#include <algorithm>
#include <cctype>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include "cli/option_checks.h"

namespace photon::cli {

namespace fs = std::filesystem;

void declareOptions(CLI::App& app, RenderOptions& o) {
    app.add_option("scene", o.scene, "the scene file: photon JSON, pbrt-v4 (.pbrt) or glTF 2.0 (.gltf, .glb)")
        ->required();
    app.add_option("--camera", o.camera, "glTF: the camera to render, by name (default: the first)");
    app.add_option("--resolution", o.resolution, "image size instead of the scene's, e.g. 640x360")
        ->type_name("WxH")
        ->check([](const std::string& r) {
            int w = 0, h = 0;
            char x = 0, rest = 0;
            return std::sscanf(r.c_str(), "%d%c%d%c", &w, &x, &h, &rest) == 3 && (x == 'x' || x == 'X') && w >= 1 &&
                           h >= 1 && w <= 16384 && h <= 16384
                       ? ""
                       : "expected WIDTHxHEIGHT, each in [1, 16384]";
        });
    app.add_option("-o,--output", o.outputs,
                   "image to write, by its extension: .exr (linear HDR, with the denoiser's layers) or .png "
                   "(the scene's exposure, sRGB); repeatable")
        ->allow_extra_args(false);
    app.add_option_function<std::vector<std::string>>(
           "--png", [&o](const std::vector<std::string>& names) { o.outputs.insert(o.outputs.end(), names.begin(), names.end()); },
           "the same as -o with a .png name")
        ->allow_extra_args(false);
    app.add_option("--passes,--spp", o.passes, "passes (samples per pixel for the path tracer)")
        ->type_name("N")
        ->check(integerIn(1, 1000000));
    app.add_option("--photons-per-pass", o.photons, "photons per pass")->type_name("N")->check(integerIn(1, 100000000));
    app.add_option("--time-limit", o.timeLimit, "stop after the pass that crosses this many seconds")
        ->type_name("SECONDS")
        ->check(CLI::Range(0.0, 1e9));
    app.add_option("--target-error", o.targetError,
                   "stop after the pass whose estimated relative error is at or below this, e.g. 0.02")
        ->type_name("E")
        ->check(CLI::Range(0.0, 1e9));
    app.add_option("--threads", o.threads, "threads (default: one per core)")->type_name("N")->check(integerIn(1, 1024));
    app.add_option("--seed", o.seed, "random seed")->type_name("N")->check(integerIn(0, 1LL << 62));
    std::vector<std::string> names(kIntegratorNames.begin(), kIntegratorNames.end());
    app.add_option("--integrator", o.integrator, "the integrator, instead of the scene's")->check(CLI::IsMember(names));
    app.add_option("-D,--define", o.defines,
                   "set a render or camera setting, e.g. -D render.alpha=0.5 -D camera.resolution=[640,360]; "
                   "repeatable")
        ->type_name("KEY=VALUE")
        ->allow_extra_args(false)
        ->check([](const std::string& d) { return d.find('=') == std::string::npos ? "expected KEY=VALUE" : ""; });
    app.add_option("--checkpoint", o.checkpoint,
                   "write the render's state here every 30 s and when it stops, to --resume it later");
    app.add_option("--resume", o.resume, "continue the render saved in this checkpoint (same scene and settings)")
        ->check(CLI::ExistingFile);
    app.add_flag("--lenient", o.lenient, "pbrt: leave out or replace what photon cannot render (media, unknown materials, textures, shapes, lights), with a warning for each, instead of refusing the scene");
    app.add_flag("--check", o.check, "load and check the scene, print what it asks for, render nothing");
    app.add_flag("--quiet", o.quiet, "no progress bar");
}

std::vector<SettingOverride> RenderOptions::overrides() const {
    std::vector<SettingOverride> out;
    if (passes) out.push_back({"render.passes", std::to_string(*passes)});
    if (photons) out.push_back({"render.photons_per_pass", std::to_string(*photons)});
    if (seed) out.push_back({"render.seed", std::to_string(*seed)});
    if (timeLimit) out.push_back({"render.time_limit", std::to_string(*timeLimit)});
    if (targetError) out.push_back({"render.target_error", std::to_string(*targetError)});
    if (!integrator.empty()) out.push_back({"render.integrator", integrator});
    if (!resolution.empty()) {
        std::string r = resolution;
        std::replace(r.begin(), r.end(), 'X', 'x');
        out.push_back({"camera.resolution", "[" + r.replace(r.find('x'), 1, ",") + "]"});
    }
    for (const std::string& d : defines) {
        const size_t eq = d.find('=');
        out.push_back({d.substr(0, eq), d.substr(eq + 1)});
    }
    return out;
}

std::optional<std::string> checkOutputs(const RenderOptions& o) {
    if (o.outputs.empty() && !o.check) return "give -o OUT.exr and/or -o OUT.png";
    for (const std::string& name : o.outputs) {
        std::string ext = fs::path(name).extension().string();
        std::transform(ext.begin(), ext.end(), ext.begin(), [](unsigned char c) { return char(std::tolower(c)); });
        if (ext != ".exr" && ext != ".png") return "-o " + name + ": the name must end in .exr or .png";
        const fs::path folder = fs::absolute(name).parent_path();
        const fs::path probe = folder / (".photon-render-" + std::to_string(::getpid()));
        bool writable = std::ofstream(probe).good();
        std::error_code ec;
        fs::remove(probe, ec);
        if (!writable) return "-o " + name + ": cannot write in " + folder.string();
    }
    return std::nullopt;
}

}  // namespace photon::cli
