// photon-render's command line: what to render, the settings to override, where to write.
#pragma once
#include <optional>
#include <string>
#include <vector>
#include <photon/scene_file.h>

namespace CLI {
class App;
}

namespace photon::cli {

struct RenderOptions {
    std::string scene;
    std::vector<std::string> outputs;  // -o: .exr (linear, every layer) or .png (tone-mapped)
    std::optional<long long> passes, photons, threads, seed;
    std::optional<double> timeLimit;
    std::optional<double> targetError;
    std::string integrator;
    std::string camera;      // glTF: the camera's name
    bool lenient = false;    // pbrt: leave out what photon cannot render (ImportOptions::lenient)
    std::string resolution;  // "WxH"
    std::vector<std::string> defines;  // -D key=value
    std::string checkpoint, resume;
    bool check = false, quiet = false;

    // Every override as the scene loader takes them: the named options first, then -D.
    std::vector<SettingOverride> overrides() const;
};

void declareOptions(CLI::App& app, RenderOptions& options);

// What is wrong with the output names, or nothing: each must end in .exr or .png (any case)
// and its folder must take a new file. Checked before a render, not after hours of one.
std::optional<std::string> checkOutputs(const RenderOptions& options);

}  // namespace photon::cli
