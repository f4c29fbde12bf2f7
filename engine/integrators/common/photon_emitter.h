// Where photons come from, for every photon integrator: a light picked in proportion to
// its power, then a ray from it, through a projection map where the light has one.
#pragma once
#include <optional>
#include <vector>
#include "math/lanes.h"
#include "math/rng.h"
#include "math/ray.h"
#include "lights/projection_map.h"
#include "integrators/common/emission_guide.h"

namespace photon {

class Scene;

struct EmittedPhoton {
    Ray ray;
    // Flux in units of the lights' mean total power (LightSampler::totalAveragePower), so
    // that without projection maps a photon's flux averages 1.
    Color beta;
    uint32_t cell = 0;  // the emission guide's cell the photon left from (0 without one)
};

// What a projection map marks: every shape, or only shapes whose material has a delta
// (specular) lobe. Caustic paths (L S+ D) start at such a shape, so a caustic map loses
// nothing by emitting toward them alone (Jensen 2001, sec. 9.2), and gains many photons.
enum class PhotonTargets { AllShapes, SpecularShapes };

class PhotonEmitter {
public:
    // Builds projection maps for the point, spot and directional lights if asked to.
    PhotonEmitter(const Scene& scene, bool projectionMaps, PhotonTargets targets = PhotonTargets::AllShapes);

    // Draws five numbers from rng in every case (light, two for position, two for
    // direction), so the streams that follow do not depend on the light picked.
    std::optional<EmittedPhoton> emit(Rng& rng) const;

    // With a guide, its cells pick the light and where in the four numbers the photon
    // comes from, and the flux carries its weight; null: plain emission. The guide must
    // outlive the emitter's use of it.
    void setGuide(const EmissionGuide* guide) { guide_ = guide; }

    // Eight photons at once, for the photon walk's lanes: lane i (where want[i]) gets what
    // emit() gives with Rng(stream, index[i]), and the stream as emit() leaves it. Photons
    // from triangle meshes are emitted eight at a time in SIMD, others one by one.
    struct Lanes {
        alignas(32) float ox[kLanes], oy[kLanes], oz[kLanes], dx[kLanes], dy[kLanes], dz[kLanes];
        alignas(32) float betaR[kLanes], betaG[kLanes], betaB[kLanes];
        alignas(64) uint64_t state[kLanes], increment[kLanes];
        alignas(32) int32_t emitted[kLanes];  // -1 where a photon left a light
        alignas(32) uint32_t cell[kLanes];    // EmittedPhoton::cell
        alignas(32) int32_t light[kLanes];    // the light it left, an index into Scene::lights()
    };
    void emitLanes(const RngStream& stream, const int64_t* index, const int32_t* want, Lanes& out) const;

    // The map of the sampler's light i, or null.
    const ProjectionMap* projectionMap(size_t light) const {
        return maps_[light] ? &*maps_[light] : nullptr;
    }

private:
    // The light a photon leaves, from the first of its numbers: by power, or by the guide.
    struct LightChoice {
        size_t light = 0;
        bool picked = false;  // false: no light with power
        uint32_t cell = 0;    // the guide's cell and the flux factor it brings
        float weight = 1;
    };
    LightChoice pickLight(float uLight) const;
    // The photon from the other four numbers (uPos, uDir), moved into the guide's cell.
    std::optional<EmittedPhoton> emitFrom(const LightChoice& choice, float u[4]) const;
    // Without the guide: the photon from light's numbers u as they are.
    std::optional<EmittedPhoton> emitFrom(size_t light, const float u[4]) const;

    const Scene& scene_;
    std::vector<std::optional<ProjectionMap>> maps_;  // by the light sampler's index
    // 1 / (probability of the light * the lights' mean total power), by the same index.
    std::vector<float> fluxScale_;
    // Lights on triangle meshes without a projection map, by the same index (else null):
    // their photons are emitted in lanes, each with the flux below.
    std::vector<const EmissionTriangles*> laneTriangles_;
    std::vector<Color> laneFlux_;
    const EmissionGuide* guide_ = nullptr;
};

}  // namespace photon
