// Objects placed many times: one Embree scene per object, instanced into the world's
// (Embree's single-level instancing), so that its geometry is held and built once.
#include <stdexcept>
#include "description/shape_transform.h"
#include "scene/scene.h"

namespace photon {

void Scene::placeInstancedEmitters() {
    const auto& objects = description_.objects;
    for (const InstanceDescription& instance : description_.instances) {
        if (instance.object >= objects.size())
            throw std::runtime_error(instance.name + ": no object " + std::to_string(instance.object));
        for (const ShapeDescription& shape : objects[instance.object].shapes) {
            if (isBlack(shape.emission)) continue;
            ShapeDescription copy = shape;
            if (!transformShape(instance.toWorld, copy))
                throw std::runtime_error(instance.name + ": places the emissive sphere " + shape.name +
                                         " with a scale that is not uniform");
            copy.name = shape.name + " in " + instance.name;
            shapes_.push_back(std::move(copy));
        }
    }
}

void Scene::addObjectsAndInstances() {
    std::vector<uint32_t> firstShape;
    for (const ObjectDescription& object : description_.objects) {
        firstShape.push_back(static_cast<uint32_t>(slots_.size()));
        RTCScene scene = rtcNewScene(device_);
        objectScenes_.push_back(scene);
        rtcSetSceneBuildQuality(scene, RTC_BUILD_QUALITY_HIGH);
        for (uint32_t i = 0; i < object.shapes.size(); ++i) {
            const ShapeDescription& shape = object.shapes[i];
            slots_.push_back(&shape);
            // Emitters are among the world's shapes, once per instance.
            if (isBlack(shape.emission)) addShape(shape, scene, i);
        }
        rtcCommitScene(scene);
    }
    firstInstanceId_ = static_cast<uint32_t>(shapes_.size());
    placements_.reserve(description_.instances.size());
    for (uint32_t k = 0; k < description_.instances.size(); ++k) {
        const InstanceDescription& instance = description_.instances[k];
        RTCGeometry g = rtcNewGeometry(device_, RTC_GEOMETRY_TYPE_INSTANCE);
        rtcSetGeometryInstancedScene(g, objectScenes_[instance.object]);
        rtcSetGeometryTransform(g, 0, RTC_FORMAT_FLOAT3X4_ROW_MAJOR, instance.toWorld.m.data());
        rtcCommitGeometry(g);
        rtcAttachGeometryByID(rtcScene_, g, firstInstanceId_ + k);
        rtcReleaseGeometry(g);
        placements_.push_back({instance.toWorld, instance.toWorld.inverse(), firstShape[instance.object]});
    }
}

void Scene::completeInstanceHit(const Ray& ray, unsigned geomID, unsigned instID, SurfaceHit& hit) const {
    hit.instance = instID - firstInstanceId_;
    const Placement& place = placements_[hit.instance];
    hit.shape = place.firstShape + geomID;
    // Embree found the hit with the ray in the object's frame, where the distance along
    // it is the same (the direction is transformed, not normalised).
    completeLocalHit({place.toObject.point(ray.o), place.toObject.vector(ray.d), ray.tMax}, hit);
    hit.p = place.toWorld.point(hit.p);
    hit.ng = place.toWorld.normal(hit.ng);
    hit.ns = place.toWorld.normal(hit.ns);
}

}  // namespace photon
