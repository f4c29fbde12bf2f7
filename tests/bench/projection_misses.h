// How many emitted photons miss the scene, with and without projection maps.
#pragma once
#include <nlohmann/json.hpp>
#include <string>

namespace photon::bench {

// Traces the first ray of `photons` photons from the emitter the photon integrators use,
// once with projection maps and once without, and reports the share that hits nothing.
nlohmann::json projectionMapMisses(const std::string& sceneFile, int photons);

}  // namespace photon::bench
