#include "import/pbrt/pbrt_import.h"
#include <algorithm>
#include <photon/errors.h>
#include "import/pbrt/pbrt_builder.h"

namespace photon {

namespace pbrt {

void SceneBuilder::warn(const Location& where, const std::string& message) {
    out_.warnings.push_back(where.str() + ": " + message);
}

Json SceneBuilder::matrixJson(const Transform& t) const {
    Json m = Json::array();
    for (float v : t.m) m.push_back(v);
    for (float v : {0.0f, 0.0f, 0.0f, 1.0f}) m.push_back(v);
    return Json{{"matrix", m}};
}

void SceneBuilder::handle(Directive&& d) {
    addAttributes(d);
    const std::string& n = d.name;
    if (n == "AttributeBegin") {
        stack_.push_back(state_);
    } else if (n == "AttributeEnd") {
        if (stack_.empty()) fail(d.where, "AttributeEnd without a matching AttributeBegin");
        state_ = stack_.back();
        stack_.pop_back();
    } else if (n == "TransformBegin") {
        transformStack_.push_back(ctm());
    } else if (n == "TransformEnd") {
        if (transformStack_.empty()) fail(d.where, "TransformEnd without a matching TransformBegin");
        setCtm(transformStack_.back());
        transformStack_.pop_back();
    } else if (n == "Identity" || n == "Translate" || n == "Scale" || n == "Rotate" || n == "LookAt" ||
               n == "Transform" || n == "ConcatTransform" || n == "CoordinateSystem" || n == "CoordSysTransform") {
        transformDirective(d);
    } else if (n == "ActiveTransform" || n == "TransformTimes") {
        // Motion blur: photon renders the scene at the start time.
        if (n == "ActiveTransform" && !d.strings.empty() && d.strings[0] != "StartTime" && d.strings[0] != "All")
            warn(d.where, "ActiveTransform " + d.strings[0] + ": motion blur is not rendered; the start time is used");
    } else if (n == "ReverseOrientation") {
        state_.reverseOrientation = !state_.reverseOrientation;
    } else if (n == "WorldBegin") {
        worldBegun_ = true;
        setCtm({});
        coordinateSystems_["world"] = {};
    } else if (n == "WorldEnd") {
        // pbrt-v3's end of file.
    } else if (n == "Camera") {
        camera(d);
    } else if (n == "Film") {
        film(d);
    } else if (n == "Sampler") {
        sampler(d);
    } else if (n == "Integrator") {
        integrator(d);
    } else if (n == "PixelFilter") {
        pixelFilter(d);
    } else if (n == "Accelerator" || n == "ColorSpace" || n == "Option") {
        if (n == "Option" && d.find("seed")) {
            Params p(d);
            render_["seed"] = static_cast<int64_t>(p.number("seed", 0));
        } else if (!(n == "ColorSpace" && !d.strings.empty() && d.strings[0] == "srgb")) {
            const char* why = n == "Accelerator" ? "photon builds Embree's BVH"
                              : n == "ColorSpace"  ? "photon renders in linear sRGB"
                                                   : "not an option photon has";
            warn(d.where, describe(d) + " ignored (" + why + ")");
        }
        return;
    } else if (n == "MakeNamedMaterial") {
        makeNamedMaterial(d);
    } else if (n == "Material") {
        material(d);
    } else if (n == "NamedMaterial") {
        state_.material = namedMaterial(d.strings.at(0), d.where);
    } else if (n == "Texture") {
        texture(d);
    } else if (n == "Shape") {
        shape(d);
    } else if (n == "LightSource") {
        lightSource(d);
    } else if (n == "AreaLightSource") {
        areaLightSource(d);
    } else if (n == "ObjectBegin") {
        objectBegin(d);
    } else if (n == "ObjectEnd") {
        if (!currentObject_) fail(d.where, "ObjectEnd without a matching ObjectBegin");
        flushCurves(currentObject_);
        currentObject_.reset();
        if (stack_.empty()) fail(d.where, "ObjectEnd without a matching ObjectBegin");
        state_ = stack_.back();
        stack_.pop_back();
    } else if (n == "ObjectInstance") {
        objectInstance(d);
    } else if (n == "MakeNamedMedium") {
        return makeNamedMedium(d);
    } else if (n == "MediumInterface") {
        return mediumInterface(d);
    } else if (n == "Attribute") {
        return attribute(d);
    } else {
        fail(d.where, "directive " + n + " is not supported");
    }
    Params(d).warnUnused(out_.warnings);
}

namespace {

// The kind of directive each Attribute target gives parameters to.
const std::map<std::string, std::vector<std::string>, std::less<>> kAttributeTargets = {
    {"shape", {"Shape"}},
    {"light", {"LightSource", "AreaLightSource"}},
    {"material", {"Material", "MakeNamedMaterial"}},
    {"medium", {"MakeNamedMedium"}},
    {"texture", {"Texture"}}};

}  // namespace

void SceneBuilder::attribute(const Directive& d) {
    const std::string& target = d.strings.at(0);
    if (!kAttributeTargets.count(target))
        fail(d.where, "Attribute \"" + target + "\": the target must be \"shape\", \"light\", \"material\", \"medium\" or \"texture\"");
    std::vector<Param>& list = state_.attributes[target];
    for (const Param& p : d.params) {
        std::erase_if(list, [&](const Param& q) { return q.name == p.name; });
        list.push_back(p);
        // pbrt-v4 reports a directive's own unused parameters, not the attributes it was given.
        list.back().used = true;
    }
}

void SceneBuilder::addAttributes(Directive& d) const {
    for (const auto& [target, directives] : kAttributeTargets) {
        if (std::find(directives.begin(), directives.end(), d.name) == directives.end()) continue;
        auto it = state_.attributes.find(target);
        if (it == state_.attributes.end()) return;
        for (const Param& p : it->second)
            if (!d.find(p.name)) d.params.push_back(p);
        return;
    }
}

void SceneBuilder::unsupported(const Directive& d, const std::string& message, const std::string& instead) {
    if (!lenient_) fail(d.where, message);
    warn(d.where, message + "; " + instead + " (lenient import)");
    Params(d).markAllRead();
}

void SceneBuilder::finish() {
    if (!stack_.empty()) warn(Location{}, "the file ends inside an AttributeBegin block");
    writeCameraAndRender();
    flushCurves(std::nullopt);
    checkMaterialsNamedAhead();
    placeSubsurfaceMedia();
    Json& doc = out_.document;
    // An object with nothing photon renders (only interfaces) is never instanced.
    for (auto it = objects_.begin(); it != objects_.end();)
        it = it.value()["shapes"].empty() ? objects_.erase(it) : std::next(it);
    if (!objects_.empty()) doc["objects"] = objects_;
    doc["materials"] = materials_;
    if (!mediaJson_.empty()) doc["media"] = mediaJson_;
    doc["shapes"] = shapes_;
    if (!lights_.empty()) doc["lights"] = lights_;
    // pbrt-v4's defaults where the file has no Sampler (zsobol, 16 samples a pixel) or no
    // Integrator (volpath, maxdepth 5), as when it names them without those parameters.
    if (!render_.contains("passes")) render_["passes"] = 16;
    if (!render_.contains("max_depth")) render_["max_depth"] = 5;
    if (photonsPerPixel_) render_["photons_per_pass"] = std::clamp<int64_t>(int64_t(width_) * height_, 1, 100'000'000);
    doc["render"] = render_;
    if (shapes_.empty()) throw SceneError("", "the pbrt scene has no shapes that photon can render");
}

}  // namespace pbrt

ImportedScene importPbrt(const std::filesystem::path& file, bool lenient) {
    ImportedScene out;
    const std::filesystem::path root = file.parent_path().empty() ? std::filesystem::path(".") : file.parent_path();
    pbrt::SceneBuilder builder(root, out, lenient);
    try {
        pbrt::parseFile(file, root, [&](pbrt::Directive&& d) { builder.handle(std::move(d)); });
    } catch (const pbrt::ParseError& e) {
        // Its text starts with the location, which SceneError adds again.
        const std::string what = e.what(), prefix = e.where().str() + ": ";
        throw SceneError(e.where().str(), what.rfind(prefix, 0) == 0 ? what.substr(prefix.size()) : what);
    }
    builder.finish();
    return out;
}

}  // namespace photon
