#include "api/job_json.h"
#include <httplib.h>

namespace photon::api {

namespace {

nlohmann::json timestamp(const std::string& iso) { return iso.empty() ? nlohmann::json() : nlohmann::json(iso); }

}  // namespace

// Each method's own figures: samples per pixel for the methods that take one camera sample a
// pixel a pass, the radiosity solve, the photon maps' sizes (SPPM's are the record's photons
// and radius).
nlohmann::json figuresOf(const std::string& integrator, const server::JobProgress& p) {
    nlohmann::json f = nlohmann::json::object();
    if (integrator != "sppm") f["samples_per_pixel"] = p.pass;
    if (integrator == "radiosity") {
        f["patches"] = p.figures.patches;
        f["solver_iterations"] = p.figures.solverIterations;
        f["solver_residual"] = p.figures.solverResidual;
    }
    if (integrator == "photonmap") {
        f["global_map_photons"] = p.figures.globalMapPhotons;
        f["caustic_map_photons"] = p.figures.causticMapPhotons;
    }
    return f;
}

nlohmann::json toJson(const server::JobRecord& job) {
    const server::JobSettings& s = job.settings;
    const server::JobProgress& p = job.progress;
    return {
        {"id", job.id},
        {"status", server::toString(job.status)},
        {"priority", job.priority},
        {"created_at", timestamp(job.createdAt)},
        {"started_at", timestamp(job.startedAt)},
        {"finished_at", timestamp(job.finishedAt)},
        {"settings",
         {{"passes", s.passes},
          {"photons_per_pass", s.photonsPerPass},
          {"seed", s.seed},
          {"integrator", s.integrator},
          {"resolution", {s.width, s.height}},
          {"camera", s.camera.empty() ? nlohmann::json() : nlohmann::json(s.camera)},
          {"lenient", s.lenient},
          {"denoise", s.denoise},
          {"target_error", s.targetError}}},
        {"pass", p.pass},
        {"total_passes", s.passes},
        {"photons_traced", p.photonsTraced},
        {"mean_radius", p.meanRadius},
        {"elapsed_seconds", p.elapsedSeconds},
        {"eta_seconds", p.etaSeconds},
        {"relative_error", p.relativeError ? nlohmann::json(*p.relativeError) : nlohmann::json()},
        {"target_error", s.targetError > 0 ? nlohmann::json(s.targetError) : nlohmann::json()},
        {"figures", figuresOf(s.integrator, p)},
        {"error", job.error.empty() ? nlohmann::json() : nlohmann::json(job.error)},
        {"warnings", job.warnings},
        {"kept_passes", job.keptPasses},
        {"name", job.name},
        {"labels", job.labels},
        {"updated_at", timestamp(job.updatedAt)},
    };
}

void sendJson(httplib::Response& res, int status, const nlohmann::json& body) {
    res.status = status;
    res.set_content(body.dump(-1, ' ', false, nlohmann::json::error_handler_t::replace), "application/json");
}

}  // namespace photon::api
