#include "integrators/common/photon_emitter.h"
#include "scene/scene.h"

namespace photon {

PhotonEmitter::PhotonEmitter(const Scene& scene, bool projectionMaps, PhotonTargets targets) : scene_(scene) {
    const LightSampler& lights = scene.lights();
    maps_.resize(lights.size());
    for (size_t i = 0; i < lights.size(); ++i) {
        float probability = lights.probability(i);
        fluxScale_.push_back(probability > 0 ? 1.0f / (probability * lights.totalAveragePower()) : 0.0f);
    }
    if (projectionMaps) {
        const SceneDescription& d = scene.description();
        auto include = [&](const ShapeDescription& s) {
            return targets == PhotonTargets::AllShapes || (d.materials[s.material]->lobes() & kDeltaLobe) != 0;
        };
        std::vector<BoundingSphere> objects = shapeBoundingSpheres(d.shapes, include);
        std::vector<std::vector<BoundingSphere>> inObjects;
        for (const ObjectDescription& object : d.objects) inObjects.push_back(shapeBoundingSpheres(object.shapes, include));
        for (const InstanceDescription& instance : d.instances)
            for (BoundingSphere s : inObjects[instance.object]) objects.push_back(placed(s, instance.toWorld));
        for (size_t i = 0; i < lights.size(); ++i) maps_[i] = ProjectionMap::build(lights.light(i), objects);
    }
    for (size_t i = 0; i < lights.size(); ++i) {
        laneTriangles_.push_back(maps_[i] ? nullptr : lights.light(i).emissionTriangles());
        laneFlux_.push_back(lights.light(i).power() * fluxScale_[i]);
    }
}

std::optional<EmittedPhoton> PhotonEmitter::emit(Rng& rng) const {
    const float uLight = rng.uniform();
    float u[4];
    for (float& x : u) x = rng.uniform();
    return emitFrom(pickLight(uLight), u);
}

PhotonEmitter::LightChoice PhotonEmitter::pickLight(float uLight) const {
    if (guide_) {
        const EmissionGuide::Choice c = guide_->pick(uLight);
        return {c.light, true, c.cell, c.weight};
    }
    LightSampler::Pick pick = scene_.lights().pick(uLight);
    return {pick.index, pick.light != nullptr};
}

std::optional<EmittedPhoton> PhotonEmitter::emitFrom(const LightChoice& choice, float u[4]) const {
    if (!choice.picked) return std::nullopt;
    if (!guide_) return emitFrom(choice.light, u);
    guide_->remap(choice.cell, u);
    std::optional<EmittedPhoton> e = emitFrom(choice.light, u);
    if (e) e->beta *= choice.weight, e->cell = choice.cell;
    return e;
}

std::optional<EmittedPhoton> PhotonEmitter::emitFrom(size_t light, const float u[4]) const {
    Vec2 uPos{u[0], u[1]}, uDir{u[2], u[3]};
    std::optional<PhotonEmission> e;
    if (const ProjectionMap* map = projectionMap(light)) {
        // Point lights use only a direction and parallel lights only a position: the pair
        // they leave unused picks the cell, as one 48-bit number (cells are many and small).
        bool point = map->emitsFromPoint();
        Vec2 uCell = point ? uPos : uDir;
        e = map->emit(static_cast<double>(uCell.x) + static_cast<double>(uCell.y) * 0x1p-24, point ? uDir : uPos);
    } else {
        e = scene_.lights().light(light).emitPhoton(uPos, uDir);
    }
    if (!e) return std::nullopt;
    Color beta = e->flux * fluxScale_[light];
    Ray ray = isBlack(e->normal) ? Ray{e->origin, e->direction} : spawnRay(e->origin, e->normal, e->direction);
    return EmittedPhoton{ray, beta};
}

}  // namespace photon
