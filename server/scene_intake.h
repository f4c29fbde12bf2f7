// Accepting a scene: load it with the engine's own loader against the folder that holds its
// assets (so a scene the service accepts is one the worker can load), apply the submit
// overrides, and hold the result to the server's limits. Imported scenes (pbrt-v4, glTF)
// are held to them as imported, and keep the importer's warnings.
#pragma once
#include <cstdint>
#include <filesystem>
#include <optional>
#include <string>
#include <vector>
#include <photon/render_settings.h>
#include <photon/scene_file.h>
#include "job.h"
#include "service_limits.h"

namespace photon::server {

// Query-string overrides of the scene's render block, and the job's queue priority.
struct SubmitOptions {
    std::optional<int64_t> passes;
    std::optional<int64_t> photonsPerPass;
    std::optional<uint64_t> seed;
    std::optional<double> targetError;  // render.target_error instead of the scene's
    std::optional<std::string> camera;  // an imported glTF's camera, by name (default: its first)
    // An imported pbrt scene's parts photon cannot render left out, with warnings, instead of
    // refused (ImportOptions::lenient).
    std::optional<bool> lenient;
    int priority = 0;
    std::string name;                 // see job_labels.h
    std::vector<std::string> labels;
};

struct AcceptedScene {
    JobSettings settings;            // the effective settings
    std::vector<std::string> files;  // the files it names, relative to its folder (SceneFile::files)
    bool imported = false;           // read from a pbrt-v4 or glTF file
    std::vector<std::string> warnings;  // what the import approximated or left out
};

// The scene file `sceneFile` (in `folder`, with its assets); a JSON scene is `sceneText`.
// Throws ServiceError: BadRequest (with the scene path, or an imported file's "file:line")
// for scene errors, LimitExceeded for requests beyond `limits`.
AcceptedScene validateScene(const std::string& sceneText, const std::filesystem::path& sceneFile,
                            const SubmitOptions& options, const Limits& limits);

// Reads a stored job's scene file as validateScene did, importing with the job's options.
SceneFile readJobScene(const std::filesystem::path& sceneFile, const JobSettings& settings);

// Puts a job's stored settings into a freshly loaded scene's render block, so the render
// uses exactly what was accepted at submission.
void applySettings(const JobSettings& settings, RenderSettings& render);

}  // namespace photon::server
