// Fuzzes checkpoint restore with what a job's checkpoint file could hold after damage on
// disk. An input is not a checkpoint itself but edits to a valid one, made at start for a
// tiny render: which integrator, whether to cut it short, byte flips at chosen offsets,
// and whether to reseal it afterwards (a fresh CRC), so the checks behind the seal are
// reached too and not only the seal.
//
// Contract checked: restoreCheckpoint throws only CheckpointError; a refused checkpoint
// leaves the renderer untouched; an accepted one renders a further pass.
//   input: [flags] [cut: 2 bytes, if flags & 4] then triples [offset lo] [offset hi] [xor]
//   flags: bit 0 integrator (SPPM or path), bit 1 reseal, bit 2 cut
#include <cstdint>
#include <cstdlib>
#include <sstream>
#include <string>
#include "integrators/common/checkpoint.h"
#include <photon/render.h>
#include "integrators/integrator.h"
#include "scene/scene.h"
#include "scene/scene_loader.h"

namespace {

struct Subject {
    std::shared_ptr<const photon::Scene> scene;
    std::string sealed;  // the checkpoint after two passes
    std::string body;    // the same without its seal
};

Subject makeSubject(photon::IntegratorKind kind) {
    photon::SceneDescription d = photon::loadSceneFile(std::string(PHOTON_SOURCE_DIR) + "/scenes/cornell-box.json");
    d.camera.width = d.camera.height = 4;
    d.render.integrator = kind;
    d.render.passes = 4;
    d.render.photonsPerPass = 500;
    Subject s{photon::Scene::build(std::move(d)), {}, {}};
    photon::Renderer r(s.scene);
    photon::CancelToken cancel;
    r.renderPass(cancel);
    r.renderPass(cancel);
    std::ostringstream out;
    r.saveCheckpoint(out);
    s.sealed = out.str();
    s.body = std::string(photon::unsealCheckpoint(s.sealed));
    return s;
}

const Subject& subject(bool path) {
    static const Subject sppm = makeSubject(photon::IntegratorKind::Sppm);
    static const Subject pathTracer = makeSubject(photon::IntegratorKind::Path);
    return path ? pathTracer : sppm;
}

// The input's cut and byte flips, applied to `bytes`.
std::string edit(std::string bytes, const uint8_t* data, size_t size) {
    size_t at = 1;
    if ((data[0] & 4) && size >= 3) {
        bytes.resize((data[1] | size_t(data[2]) << 8) % (bytes.size() + 1));
        at = 3;
    }
    for (; at + 3 <= size && !bytes.empty(); at += 3)
        bytes[(data[at] | size_t(data[at + 1]) << 8) % bytes.size()] ^= static_cast<char>(data[at + 2]);
    return bytes;
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
    if (size == 0) return 0;
    const Subject& s = subject(data[0] & 1);
    const bool reseal = data[0] & 2;
    const std::string bytes = reseal ? photon::sealCheckpoint(edit(s.body, data, size)) : edit(s.sealed, data, size);
    photon::Renderer r(s.scene);
    std::istringstream in(bytes);
    try {
        r.restoreCheckpoint(in);
    } catch (const photon::CheckpointError&) {
        if (r.integrator().passesDone() != 0 || r.progress().photonsTraced != 0) std::abort();  // not untouched
        return 0;
    }
    photon::CancelToken cancel;
    r.renderPass(cancel);
    (void)r.snapshot();
    return 0;
}
