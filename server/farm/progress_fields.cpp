#include "progress_fields.h"
#include <cstdio>
#include <stdexcept>

namespace photon::farm {
namespace {

std::string exactly(double v) {
    char text[32];
    std::snprintf(text, sizeof text, "%.17g", v);
    return text;
}

template <typename Number>
Number numberOf(const StreamEntry& e, const std::string& name) {
    const std::string& text = e.field(name);
    try {
        size_t used = 0;
        Number v;
        if constexpr (std::is_floating_point_v<Number>) v = Number(std::stod(text, &used));
        else v = Number(std::stoll(text, &used));
        if (used == text.size()) return v;
    } catch (const std::exception&) {
    }
    throw std::invalid_argument("stream entry " + e.id + ": field \"" + name + "\" is not a number: " + text);
}

}  // namespace

void appendProgressFields(std::vector<std::string>& args, const RenderProgress& p, int64_t photons,
                          const server::MethodFigures& f) {
    for (std::string s : {std::string("pass"), std::to_string(p.pass), std::string("total_passes"),
                          std::to_string(p.totalPasses), std::string("photons_traced"), std::to_string(p.photonsTraced),
                          std::string("photons"), std::to_string(photons), std::string("mean_radius"),
                          exactly(p.meanRadius), std::string("elapsed"), exactly(p.elapsedSeconds), std::string("eta"),
                          exactly(p.etaSeconds), std::string("patches"), std::to_string(f.patches),
                          std::string("solver_iterations"), std::to_string(f.solverIterations),
                          std::string("solver_residual"), exactly(f.solverResidual), std::string("global_map_photons"),
                          std::to_string(f.globalMapPhotons), std::string("caustic_map_photons"),
                          std::to_string(f.causticMapPhotons), std::string("relative_error"), exactly(p.relativeError.value_or(-1)),
                          std::string("passes_to_target"), exactly(p.passesToTarget.value_or(-1))})
        args.push_back(std::move(s));
}

RenderProgress progressOfFields(const StreamEntry& e) {
    RenderProgress p;
    p.pass = numberOf<int>(e, "pass");
    p.totalPasses = numberOf<int>(e, "total_passes");
    p.photonsTraced = numberOf<int64_t>(e, "photons_traced");
    p.lastPass.photons = numberOf<int64_t>(e, "photons");
    p.meanRadius = numberOf<double>(e, "mean_radius");
    p.elapsedSeconds = numberOf<double>(e, "elapsed");
    p.etaSeconds = numberOf<double>(e, "eta");
    p.lastPass.patches = numberOf<int64_t>(e, "patches");
    p.lastPass.solverIterations = numberOf<int>(e, "solver_iterations");
    p.lastPass.solverResidual = numberOf<double>(e, "solver_residual");
    p.lastPass.globalMapPhotons = numberOf<int64_t>(e, "global_map_photons");
    p.lastPass.causticMapPhotons = numberOf<int64_t>(e, "caustic_map_photons");
    // -1: none (RenderProgress's optionals)
    if (const double v = numberOf<double>(e, "relative_error"); v >= 0) p.relativeError = v;
    if (const double v = numberOf<double>(e, "passes_to_target"); v >= 0) p.passesToTarget = v;
    return p;
}

}  // namespace photon::farm
