// Constructors for each kind of light, one file each under lights/.
#pragma once
#include <functional>
#include <memory>
#include "description/scene_description.h"
#include "lights/light.h"
#include <photon/render_settings.h>

namespace photon {

// Isotropic, or with d.environment.image its intensity profile over directions
// (makeProfiledPointLight).
std::unique_ptr<Light> makePointLight(const LightDescription& d);
std::unique_ptr<Light> makeProfiledPointLight(const LightDescription& d);
// A slide projector: d.environment.image projected through d.projectionFovDegrees along the
// light frame's +z (projection_light.cpp).
std::unique_ptr<Light> makeProjectionLight(const LightDescription& d);
std::unique_ptr<Light> makeSpotLight(const LightDescription& d);
std::unique_ptr<Light> makeDirectionalLight(const LightDescription& d, SceneSphere bounds);
// Constant radiance, or an image when d.environment.image is set (makeImageEnvironmentLight);
// behind d.portal when it is set.
std::unique_ptr<Light> makeEnvironmentLight(const LightDescription& d, SceneSphere bounds);
std::unique_ptr<Light> makeImageEnvironmentLight(const LightDescription& d, SceneSphere bounds);
// Either of those seen only through the rectangle d.portal (portal_environment_light.cpp).
std::unique_ptr<Light> makePortalEnvironmentLight(const LightDescription& d, SceneSphere bounds);
// An emissive triangle mesh (quads arrive as meshes) or sphere. The shape must outlive the
// light. `kind`: how a mesh's light samples pick among its triangles (render.light_sampler).
std::unique_ptr<Light> makeMeshAreaLight(const ShapeDescription& shape, LightSamplerKind kind);
std::unique_ptr<Light> makeSphereAreaLight(const ShapeDescription& shape);
// A medium that emits (MediumDescription::emits), whose photons leave from the cells of
// `region` (medium_light.cpp) where `contains` says a point is in the medium. The medium
// must outlive the light.
std::unique_ptr<Light> makeMediumLight(const MediumDescription& medium, std::shared_ptr<const DensityGrid> region,
                                       std::function<bool(Vec3)> contains);
// The area light of an emitter no ray meets (ShapeDescription::invisible): `light` with its
// samples weighted in full (invisible_area_light.cpp).
std::unique_ptr<Light> makeInvisibleAreaLight(std::unique_ptr<Light> light);

}  // namespace photon
