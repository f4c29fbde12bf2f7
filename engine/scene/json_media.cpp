// "media": named media that absorb, scatter and emit, homogeneous or of a density sampled
// on a grid, and a shape's "medium": the media on its two sides (docs/scene-format.md#media).
#include <array>
#include <cmath>
#include <limits>
#include "scene/json_scene_parts.h"
#include "media/cloud_density.h"
#include "media/diffusion_dipole.h"
#include "scene/nanovdb_density.h"

namespace photon::scene_json {

namespace {
// "density": {"file": "x.nvdb", "grid": "density", "transform": T}: a NanoVDB file's grid.
std::shared_ptr<const DensityGrid> readNanoVdbGrid(JsonObject& obj, const LoadContext& ctx) {
    const JsonValue file = obj.required("file");
    const std::filesystem::path path = resolveFile(file, ctx);
    std::string grid = "density";
    if (auto name = obj.optional("grid")) grid = name->string();
    Transform worldFromGrid;
    if (auto transform = obj.optional("transform")) worldFromGrid = readTransform(*transform);
    obj.finish();
    try {
        return readNanoVdbDensity(path, grid, worldFromGrid);
    } catch (const std::runtime_error& e) {
        file.fail(e.what());
    }
}

// The box a grid's samples fill: "bounds" [p0, p1], [0, 1]^3 where not given.
std::pair<Vec3, Vec3> readBounds(JsonObject& obj) {
    Vec3 p0(0.0f), p1(1.0f);
    if (auto bounds = obj.optional("bounds")) {
        const std::vector<JsonValue> corners = bounds->elements();
        if (corners.size() != 2) bounds->fail("must be [[x0, y0, z0], [x1, y1, z1]]");
        p0 = corners[0].vec3(), p1 = corners[1].vec3();
        if (!(p0.x < p1.x && p0.y < p1.y && p0.z < p1.z)) bounds->fail("each of the first corner's coordinates must be below the second's");
    }
    return {p0, p1};
}

// The samples of "values", nx * ny * nz finite numbers >= 0, read straight off the JSON: a
// grid's millions of numbers need no JsonValue each.
std::vector<float> readSampleValues(const JsonValue& values, double count) {
    if (!values.json().is_array()) values.fail("must be an array");
    if (double(values.json().size()) != count)
        values.fail("must hold nx * ny * nz = " + std::to_string(int64_t(count)) + " numbers, not " +
                    std::to_string(values.json().size()));
    std::vector<float> samples;
    samples.reserve(values.json().size());
    for (const Json& v : values.json()) {
        const double x = v.is_number() ? v.get<double>() : -1.0;
        if (!(x >= 0 && x <= std::numeric_limits<float>::max()))
            JsonValue(v, values.path() + "[" + std::to_string(samples.size()) + "]")
                .fail("must be a finite number >= 0");
        samples.push_back(static_cast<float>(x));
    }
    return samples;
}

// "cloud": {"density": 1, "wispiness": 1, "frequency": 5}: pbrt-v4's procedural cloud.
CloudParameters readCloud(const JsonValue& value) {
    JsonObject obj = value.object();
    CloudParameters c;
    c.density = obj.number("density", c.density, Range::nonNegative());
    c.wispiness = obj.number("wispiness", c.wispiness, Range::nonNegative());
    c.frequency = obj.number("frequency", c.frequency, Range::positive());
    obj.finish();
    return c;
}

// "density": {"resolution": [nx, ny, nz], "values": [...], "bounds": [p0, p1], "transform": T};
// {"cloud": {...}, "bounds", "resolution" (chosen from the cloud's frequency where not
// given), "transform"}, sampled at the grid's points; or a NanoVDB file's grid.
std::shared_ptr<const DensityGrid> readDensityGrid(const JsonValue& value, const LoadContext& ctx) {
    JsonObject obj = value.object();
    if (obj.has("file")) {
        if (obj.has("resolution") || obj.has("values") || obj.has("bounds") || obj.has("cloud"))
            value.fail("give either \"file\" or \"resolution\" and \"values\", not both");
        return readNanoVdbGrid(obj, ctx);
    }
    const auto cloud = obj.optional("cloud");
    if (cloud && obj.has("values")) value.fail("give either \"cloud\" or \"values\", not both");
    const auto [p0, p1] = readBounds(obj);
    std::array<int, 3> size{};
    if (auto resolution = cloud ? obj.optional("resolution") : obj.required("resolution")) {
        const std::vector<JsonValue> n = resolution->elements();
        if (n.size() != 3) resolution->fail("must be [nx, ny, nz]");
        for (int a = 0; a < 3; ++a) size[a] = static_cast<int>(n[a].integer(1, 4096));
        if (double(size[0]) * size[1] * size[2] > double(1 << 28)) resolution->fail("more than 2^28 samples");
    } else {
        const CloudParameters c = readCloud(*cloud);
        for (int a = 0; a < 3; ++a) size[a] = cloudResolution(c, p1[a] - p0[a]);
    }
    const double count = double(size[0]) * size[1] * size[2];
    std::vector<float> samples =
        cloud ? sampleCloud(readCloud(*cloud), size, p0, p1) : readSampleValues(obj.required("values"), count);
    Transform worldFromMedium;
    if (auto transform = obj.optional("transform")) worldFromMedium = readTransform(*transform);
    obj.finish();
    return std::make_shared<const DensityGrid>(size[0], size[1], size[2], std::move(samples),
                                               DensityGrid::latticeFromBox(size[0], size[1], size[2], p0, p1) *
                                                   worldFromMedium.inverse());
}
// "emission": {"radiance": [r, g, b], "scale": s, "grid": G, "temperature": G,
// "temperature_offset": t0, "temperature_scale": k}: Le(p) = radiance * scale, times the
// grid G's value at p, times pbrt-v4's blackbody at (T(p) - t0) k kelvin where a temperature
// grid is given (description/medium_emission.h); the medium emits sigma_a(p) Le(p).
std::shared_ptr<const MediumEmission> readEmission(const JsonValue& value, const LoadContext& ctx) {
    JsonObject obj = value.object();
    MediumEmission e;
    if (auto radiance = obj.optional("radiance")) e.radiance = radiance->vec3(Range::nonNegative());
    e.radiance *= obj.number("scale", 1.0f, Range::nonNegative());
    if (auto grid = obj.optional("grid")) e.scale = readDensityGrid(*grid, ctx);
    if (auto temperature = obj.optional("temperature")) e.temperature = readDensityGrid(*temperature, ctx);
    for (const char* key : {"temperature_offset", "temperature_scale"})
        if (!e.temperature && obj.has(key)) obj.required(key).fail("applies only with a \"temperature\" grid");
    e.temperatureOffset = obj.number("temperature_offset", 0.0f);
    e.temperatureScale = obj.number("temperature_scale", 1.0f, Range::positive());
    obj.finish();
    return std::make_shared<const MediumEmission>(std::move(e));
}
// "reflectance" (a colour or texture in [0, 1]), "mean_free_path" (a colour > 0, divided by
// the medium's "scale" as its coefficients are multiplied) and "boundary_ior" (1.33).
std::shared_ptr<const MediumReflectance> readReflectance(JsonObject& obj, LoadContext& ctx, float scale) {
    MediumReflectance r;
    r.reflectance = readColorParam(obj.required("reflectance"), ctx, Range::closed(0, 1));
    const JsonValue mfp = obj.required("mean_free_path");
    r.meanFreePath = mfp.vec3(Range::positive());
    if (!(scale > 0)) mfp.fail("a medium given by its reflectance needs a \"scale\" > 0");
    r.meanFreePath /= scale;
    r.boundaryIor = obj.number("boundary_ior", r.boundaryIor, Range::positive());
    return std::make_shared<const MediumReflectance>(std::move(r));
}
}  // namespace

void readMedia(const JsonValue& value, LoadContext& ctx, SceneDescription& scene) {
    JsonObject media = value.object();
    for (auto& [name, medium] : media.members()) {
        JsonObject obj = medium.object();
        MediumDescription m;
        m.name = name;
        // Per unit of scene length; the scale lets a file keep a measured colour's ratios.
        const float scale = obj.number("scale", 1.0f, Range::nonNegative());
        auto coefficient = [&](std::string_view key) {
            auto v = obj.optional(key);
            return v ? v->vec3(Range::nonNegative()) * scale : Color(0.0f);
        };
        if (obj.has("reflectance")) {
            for (const char* key : {"absorption", "scattering"})
                if (obj.has(key)) obj.required(key).fail("give either \"reflectance\" and \"mean_free_path\" or \"absorption\" and \"scattering\", not both");
            m.reflectance = readReflectance(obj, ctx, scale);
            const ScatteringCoefficients c = coefficientsOfReflectance(
                m.reflectance->reflectance.average(), m.reflectance->meanFreePath, m.reflectance->boundaryIor);
            m.absorption = c.absorption, m.scattering = c.scattering;
        } else {
            if (!obj.has("absorption") && !obj.has("scattering"))
                medium.fail("a medium needs \"absorption\", \"scattering\" or both, or \"reflectance\" and \"mean_free_path\"");
            for (const char* key : {"mean_free_path", "boundary_ior"})
                if (obj.has(key)) obj.required(key).fail("applies only with \"reflectance\"");
            m.absorption = coefficient("absorption");
            m.scattering = coefficient("scattering");
        }
        m.subsurface = obj.boolean("subsurface", m.reflectance != nullptr);
        if (auto g = obj.optional("g")) m.g = g->number(Range::open(-1.0f, 1.0f));
        if (auto density = obj.optional("density")) m.density = readDensityGrid(*density, ctx);
        if (auto emission = obj.optional("emission")) {
            m.emission = readEmission(*emission, ctx);
            if (isBlack(m.absorption))
                emission->fail("a medium emits in proportion to its \"absorption\" (sigma_a Le), which is 0");
            if (m.reflectance && m.reflectance->reflectance.textured())
                emission->fail("a medium whose \"reflectance\" is a texture cannot emit");
        }
        obj.finish();
        ctx.mediumIndex[name] = int32_t(scene.media.size());
        scene.media.push_back(std::move(m));
    }
}

int32_t mediumNamed(const JsonValue& value, const LoadContext& ctx) {
    auto it = ctx.mediumIndex.find(value.string());
    if (it == ctx.mediumIndex.end()) value.fail("unknown medium \"" + value.string() + "\" (define it under \"media\")");
    return it->second;
}

void readShapeMedia(const JsonValue& value, const LoadContext& ctx, ShapeDescription& shape) {
    JsonObject obj = value.object();
    auto side = [&](std::string_view key) {
        auto v = obj.optional(key);
        return v ? mediumNamed(*v, ctx) : -1;
    };
    shape.insideMedium = side("inside");
    shape.outsideMedium = side("outside");
    obj.finish();
    if (!shape.boundsMedium()) value.fail("\"inside\" and \"outside\" are the same: the shape bounds no medium");
}

}  // namespace photon::scene_json
