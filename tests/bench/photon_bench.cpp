// photon-bench: SPPM throughput on a scene over its whole render (or --passes N) against
// raw Embree throughput in the same process, per-pass timings, memory per pixel and peak
// RSS, and the share of photons that miss a scene with and without projection maps,
// printed as JSON. With --compare SECONDS it
// instead renders the scene with every integrator for that long and reports the RMSE of
// each against an SPPM reference rendered --reference-seconds (default 10x as long).
//   photon-bench [--scene FILE] [--passes N] [--photons-per-pass N] [--threads N] [--no-rss-check]
//                [--projection-scene FILE] [--compare SECONDS [--reference-seconds SECONDS]]
//                [--compare-schedules SECONDS] [--compare-reference FILE [--seconds S,S...] [-D KEY=VALUE]...]
//                [--instancing] [--mesh-memory TRIANGLES]
// With --instancing it instead times loading and building 10,000 instances of a 10k-triangle
// mesh, and their memory, against the mesh placed once; with --mesh-memory, the peak memory
// per triangle of a large mesh as OBJ and PLY.
#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>
#include <algorithm>
#include <cstdio>
#include <iostream>
#include <nlohmann/json.hpp>
#include <optional>
#include <string>
#include "embree_throughput.h"
#include "reference_comparison.h"
#include "schedule_comparison.h"
#include "instancing_load.h"
#include "mesh_memory.h"
#include "integrator_comparison.h"
#include "projection_misses.h"
#include <photon/render.h>
#include <photon/threads.h>
#include "integrators/integrator.h"
#include "scene/scene.h"
#include "scene/scene_loader.h"
#include "cli/option_checks.h"

namespace {

using nlohmann::json;

struct Options {
    std::string scene = std::string(PHOTON_SOURCE_DIR) + "/scenes/cornell-glass.json";
    std::string projectionScene = std::string(PHOTON_SOURCE_DIR) + "/scenes/distant-spheres.json";
    int passes = 0;       // 0: the scene's own setting (the whole render)
    int64_t photons = 0;  // 0: the scene's own setting
    int threads = 0;      // 0: all cores
    bool rssCheck = true;
    double compareSeconds = 0;    // > 0: compare the integrators instead
    double referenceSeconds = 0;  // 0: 10x compareSeconds
    double compareSchedulesSeconds = 0;  // > 0: compare SPPM's radius schedules instead
    std::string compareReference;        // set: SPPM against this reference image instead
    std::vector<std::string> scorePair;  // with compareReference: two renders to score, not render
    std::vector<double> referenceRuns{10, 30};
    std::vector<std::string> settings;  // KEY=VALUE for --compare-reference
    std::vector<std::string> variants;  // NAME:KEY=VALUE for --compare-reference
    bool markdown = false;              // --compare-reference prints a table instead of JSON
    bool instancing = false;      // time instanced loading instead
    int meshMemoryTriangles = 0;  // > 0: measure a mesh's memory per triangle instead
};

void declareOptions(CLI::App& app, Options& o) {
    using photon::cli::integerIn;
    app.add_option("--scene", o.scene, "the scene to time")->capture_default_str();
    app.add_option("--passes", o.passes, "passes instead of the scene's (at least 2: the first is not timed)")
        ->type_name("N")
        ->check(integerIn(2, 1000000));
    app.add_option("--photons-per-pass", o.photons, "photons per pass instead of the scene's")
        ->type_name("N")
        ->check(integerIn(1, 100000000));
    app.add_option("--threads", o.threads, "threads (default: one per core)")->type_name("N")->check(integerIn(1, 1024));
    app.add_flag("--instancing", o.instancing, "time loading 10,000 instances of a 10k-triangle mesh instead");
    app.add_option("--mesh-memory", o.meshMemoryTriangles,
                   "measure the peak memory per triangle of loading and building a mesh of about N triangles instead")
        ->type_name("N")
        ->check(integerIn(1000, 10000000));
    app.add_flag("--no-rss-check", [&o](int64_t) { o.rssCheck = false; }, "skip the peak-memory children");
    app.add_option("--projection-scene", o.projectionScene, "the scene for projection-map misses")
        ->capture_default_str();
    app.add_option("--compare", o.compareSeconds, "compare the integrators at this many seconds each instead")
        ->check(CLI::PositiveNumber);
    app.add_option("--compare-schedules", o.compareSchedulesSeconds,
                   "compare SPPM's per-pixel and global radius schedules at this many seconds each instead");
    CLI::Option* reference = app.add_option("--compare-reference", o.compareReference,
                   "render the scene with SPPM for --seconds each (two seeds) and compare with this reference image "
                   "instead: relative noise, bias, RMSE")
        ->check(CLI::ExistingFile);
    app.add_option("-D", o.settings, "a setting of the scene for --compare-reference, KEY=VALUE (e.g. "
                                     "render.max_depth=64 to match the reference's); repeatable")
        ->allow_extra_args(false);
    app.add_option("--variant", o.variants,
                   "a variant of the scene for --compare-reference, NAME:KEY=VALUE (e.g. lightweight:render.lightweight=true, "
                   "path:render.integrator=path); repeat a NAME for more settings; each variant is rendered and "
                   "compared (with the -D settings too)")
        ->allow_extra_args(false);
    app.add_option("--score-pair", o.scorePair,
                   "--compare-reference: score these two renders (A.exr,B.exr: the same scene and time, seeds that "
                   "differ) against the reference instead of rendering")
        ->delimiter(',')
        ->expected(2)
        ->check(CLI::ExistingFile)
        ->needs(reference);
    app.add_flag("--markdown", o.markdown, "--compare-reference: print a Markdown table instead of JSON");
    app.add_option("--seconds", o.referenceRuns, "the render times for --compare-reference")
        ->delimiter(',')
        ->capture_default_str();
    app.add_option("--reference-seconds", o.referenceSeconds, "the SPPM reference's seconds (default 10x --compare)")
        ->check(CLI::PositiveNumber);
}

long peakRssKiB() {
    rusage u{};
    getrusage(RUSAGE_SELF, &u);
    return u.ru_maxrss;
}

std::shared_ptr<const photon::Scene> loadScene(const Options& o, int64_t photons) {
    photon::SceneDescription d = photon::loadSceneFile(o.scene);
    d.render.integrator = photon::IntegratorKind::Sppm;
    if (o.passes > 0) d.render.passes = o.passes;
    if (photons > 0) d.render.photonsPerPass = photons;
    return photon::Scene::build(std::move(d));
}

// Raw Embree rays cast between two passes.
constexpr int64_t kRaysPerBurst = 1000000;

// Passes 2-8 alone, when the gather radii are widest, for comparison with figures measured
// over those passes only.
constexpr int kFirstPassesTimed = 7;

// Sums over timed passes.
struct PassTotals {
    double cameraMs = 0, gridMs = 0, photonMs = 0;
    int64_t passes = 0, rays = 0, segments = 0, emitted = 0, candidates = 0, accepted = 0, cameraRays = 0, gridEntries = 0;
    photon::bench::RayThroughput raw, rawPackets;

    void add(const photon::PassStats& s, const photon::bench::RayThroughput& r, const photon::bench::RayThroughput& rp) {
        ++passes;
        cameraMs += s.cameraMs;
        gridMs += s.gridMs;
        photonMs += s.photonMs;
        rays += s.photonRays;
        segments += s.photonSegments;
        emitted += s.photons;
        candidates += s.gatherCandidates;
        accepted += s.gatherHits;
        cameraRays += s.cameraRays;
        gridEntries += s.gridEntries;
        raw += r;
        rawPackets += rp;
    }
    double segmentsPerSecond() const { return static_cast<double>(segments) / (photonMs / 1000.0); }
    double perSegment(int64_t n) const { return static_cast<double>(n) / static_cast<double>(std::max<int64_t>(segments, 1)); }
};

// Renders the scene pass by pass. Every pass but the first (which warms caches and sets the
// radii) is timed, and raw Embree rays are cast in bursts between the passes, so that both
// sides of the ratio see the same machine: a load that comes and goes slows them alike.
json renderStats(const Options& o, int64_t photons, photon::bench::RayThroughput& raw,
                 photon::bench::RayThroughput& rawPackets, json& firstPasses) {
    photon::Renderer renderer(loadScene(o, photons));
    photon::CancelToken cancel;
    PassTotals all, first;
    const int passes = renderer.scene().settings().passes;
    if (passes < 2) throw std::invalid_argument("needs at least 2 passes: the first is not timed");
    for (int p = 0; p < passes; ++p) {
        renderer.renderPass(cancel);
        if (p == 0) continue;
        photon::bench::RayThroughput r = photon::bench::measureEmbreeThroughput(renderer.scene(), kRaysPerBurst);
        photon::bench::RayThroughput rp = photon::bench::measureEmbreePacketThroughput(renderer.scene(), kRaysPerBurst);
        const photon::PassStats& s = renderer.integrator().lastPassStats();
        all.add(s, r, rp);
        if (p <= kFirstPassesTimed) first.add(s, r, rp);
    }
    raw = all.raw;
    rawPackets = all.rawPackets;
    firstPasses = {{"passes_timed", first.passes},
                   {"segments_to_embree_ratio", first.segmentsPerSecond() / first.raw.raysPerSecond()},
                   {"gather_candidates_per_segment", first.perSegment(first.candidates)},
                   {"gather_accepted_per_segment", first.perSegment(first.accepted)}};
    const double timed = static_cast<double>(std::max<int64_t>(all.passes, 1));
    const photon::Integrator& integrator = renderer.integrator();
    return {{"photons_per_pass", renderer.scene().settings().photonsPerPass},
            {"passes_timed", all.passes},
            {"photons_per_second", all.emitted / (all.photonMs / 1000.0)},
            {"photon_segments_per_second", all.segmentsPerSecond()},
            {"photon_rays_per_second", all.rays / (all.photonMs / 1000.0)},
            {"segments_per_photon", static_cast<double>(all.segments) / static_cast<double>(std::max<int64_t>(all.emitted, 1))},
            {"gather_candidates_per_segment", all.perSegment(all.candidates)},
            {"gather_accepted_per_segment", all.perSegment(all.accepted)},
            {"camera_pass_ms", all.cameraMs / timed},
            {"hash_build_ms", all.gridMs / timed},
            // The costs render.adaptive_photons weighs by counts (photon_budget.h), in time.
            {"camera_ns_per_ray", all.cameraMs * 1e6 / static_cast<double>(std::max<int64_t>(all.cameraRays, 1))},
            {"grid_ns_per_entry", all.gridMs * 1e6 / static_cast<double>(std::max<int64_t>(all.gridEntries, 1))},
            {"photon_ns_per_ray", all.photonMs * 1e6 / static_cast<double>(std::max<int64_t>(all.rays, 1))},
            {"photon_pass_ms", all.photonMs / timed},
            {"bytes_per_pixel_sppm_state", integrator.bytesPerPixel()},
            {"grid_entries_per_pixel", static_cast<double>(integrator.lastPassStats().gridEntries) /
                                           (renderer.scene().camera().width() * renderer.scene().camera().height())},
            {"mean_radius", renderer.progress().meanRadius}};
}

// Peak RSS of a child process that renders two passes with `photons` per pass.
long childPeakRssKiB(const Options& o, int64_t photons) {
    pid_t pid = fork();
    if (pid == 0) {
        Options c = o;
        c.passes = 2;
        photon::Renderer renderer(loadScene(c, photons));
        photon::CancelToken cancel;
        renderer.run(cancel);
        _exit(0);
    }
    int status = 0;
    rusage u{};
    wait4(pid, &status, 0, &u);
    return u.ru_maxrss;
}

}  // namespace

int main(int argc, char** argv) {
    CLI::App app("SPPM throughput against raw Embree, memory, projection-map misses; or integrators at equal time.",
                 "photon-bench");
    Options o;
    declareOptions(app, o);
    if (int exit = photon::cli::parseCommandLine(app, argc, argv); exit >= 0) return exit;
    try {
        std::optional<photon::ThreadLimit> limit;
        if (o.threads > 0) limit.emplace(size_t(o.threads));
        if (o.instancing) {
            std::cout << photon::bench::instancingLoad(10000, 10000).dump(2) << std::endl;
            return 0;
        }
        if (o.meshMemoryTriangles > 0) {
            std::cout << photon::bench::meshMemory(o.meshMemoryTriangles, PHOTON_RENDER_BIN).dump(2) << std::endl;
            return 0;
        }
        if (!o.compareReference.empty() && !o.scorePair.empty()) {
            std::cout << photon::bench::scoreRenderPair(o.scorePair[0], o.scorePair[1], o.compareReference).dump(2)
                      << std::endl;
            return 0;
        }
        if (!o.compareReference.empty()) {
            std::vector<photon::bench::SceneVariant> variants = photon::bench::parseVariants(o.settings, o.variants);
            const json result = photon::bench::compareVariantsWithReference(o.scene, o.compareReference, o.referenceRuns,
                                                                            variants);
            std::cout << (o.markdown ? photon::bench::markdownTable(result) : result.dump(2)) << std::endl;
            return 0;
        }
        if (o.compareSchedulesSeconds > 0) {
            double reference = o.referenceSeconds > 0 ? o.referenceSeconds : 10 * o.compareSchedulesSeconds;
            std::cout << photon::bench::compareRadiusSchedules(o.scene, o.compareSchedulesSeconds, reference).dump(2)
                      << std::endl;
            return 0;
        }
        if (o.compareSeconds > 0) {
            double reference = o.referenceSeconds > 0 ? o.referenceSeconds : 10 * o.compareSeconds;
            std::cout << photon::bench::compareIntegrators(o.scene, o.compareSeconds, reference).dump(2) << std::endl;
            return 0;
        }
        json out;
        out["scene"] = o.scene;
        out["threads"] = photon::ThreadLimit::active();
        if (o.rssCheck) {
            // Children first, so they do not inherit this process's memory.
            int64_t base = loadScene(o, o.photons)->settings().photonsPerPass;
            long small = childPeakRssKiB(o, base), large = childPeakRssKiB(o, 10 * base);
            out["peak_rss_kib"] = {{"photons_x1", small}, {"photons_x10", large},
                                   {"ratio", static_cast<double>(large) / static_cast<double>(small)}};
        }
        photon::bench::RayThroughput raw, rawPackets;
        json firstPasses;
        json sppm = renderStats(o, o.photons, raw, rawPackets, firstPasses);
        out["sppm"] = sppm;
        out["embree_random_rays"] = {{"rays_per_second", raw.raysPerSecond()},
                                     {"packet_rays_per_second", rawPackets.raysPerSecond()},
                                     {"hit_fraction", static_cast<double>(raw.hits) / static_cast<double>(raw.rays)}};
        const double segmentsPerSecond = sppm["photon_segments_per_second"].get<double>();
        out["segments_to_embree_ratio"] = segmentsPerSecond / raw.raysPerSecond();
        // Against the same random rays cast sixteen at a time, as the photon walk casts its
        // rays: the stricter figure when packets are the faster way to cast them.
        out["segments_to_embree_packet_ratio"] = segmentsPerSecond / rawPackets.raysPerSecond();
        // Like for like: the raw rays are counted whether they hit or not, and so are these.
        out["photon_rays_to_embree_ratio"] = sppm["photon_rays_per_second"].get<double>() / raw.raysPerSecond();
        out["first_passes"] = firstPasses;
        out["projection_maps"] = photon::bench::projectionMapMisses(o.projectionScene, 1000000);
        out["process_peak_rss_kib"] = peakRssKiB();
        std::cout << out.dump(2) << std::endl;
    } catch (const std::exception& e) {
        std::fprintf(stderr, "photon-bench: %s\n", e.what());
        return 1;
    }
    return 0;
}
