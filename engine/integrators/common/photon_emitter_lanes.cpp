// Photons eight at a time: the light is picked lane by lane, then every photon that
// leaves a triangle mesh (the usual area light) is placed and aimed in SIMD, exactly as
// MeshAreaLight::emitPhoton and PhotonEmitter::emitFrom do for one.
#include "scene/scene.h"
#include "lights/emission_triangles.h"
#include "integrators/common/photon_emitter.h"

namespace photon {

namespace {

// Lanes waiting for a point on a mesh light: the light's triangles and the photon's flux.
struct TriangleLanes {
    const EmissionTriangles* triangles[kLanes];
    const EmissionTriangles* shared;  // the lanes' triangles when all are the same light's, else null
    Color beta[kLanes];
    alignas(32) int32_t waiting[kLanes];
    // The emission guide's cell: number d becomes min(offset[d] + u * scale, limit[d])
    // (EmissionGuide::cellBounds; unguided 0, 1 and the last float below 1: u itself).
    alignas(32) float offset[4][kLanes];
    alignas(32) float limit[4][kLanes];
    float scale = 1;
};

PHOTON_LANES_INLINE void emitFromTrianglesLanes(const TriangleLanes& in, PhotonEmitter::Lanes& out) {
    const IntLanes waiting = loadLanes<int32_t, IntLanes>(in.waiting);
    // The position's two numbers, then the direction's (PhotonEmitter::emitFrom).
    // Moved into each lane's guide cell (EmissionGuide::remap).
    const FloatLanes scale = broadcast<FloatLanes>(in.scale);
    auto guided = [&](int d) PHOTON_LANES_LAMBDA {
        const FloatLanes v = loadLanes<float, FloatLanes>(in.offset[d]) + uniformLanes(out.state, out.increment, waiting) * scale;
        const FloatLanes limit = loadLanes<float, FloatLanes>(in.limit[d]);
        return select(v < limit, v, limit);
    };
    FloatLanes u1 = guided(0), u2 = guided(1);
    FloatLanes u3 = guided(2), u4 = guided(3);
    using T = EmissionTriangles::Triangle;
    const EmissionTriangles::Triangle* tri[kLanes];
    IntLanes picked{};
    const bool fewTriangles = in.shared && in.shared->size() <= EmissionTriangles::kFewTriangles;
    if (fewTriangles) {
        // One light of a few triangles (the usual quad): each lane's triangle index by
        // comparisons with the CDF, each field by selects among the triangles' values.
        const EmissionTriangles& tris = *in.shared;
        for (size_t k = 0; k < tris.size(); ++k) picked -= broadcast<FloatLanes>(tris.cdfUpper(k)) <= u1;
        picked = select(picked > static_cast<int32_t>(tris.size() - 1), IntLanes{} + static_cast<int32_t>(tris.size() - 1), picked);
    } else {
        for (int i = 0; i < kLanes; ++i) tri[i] = &in.triangles[i]->triangleAt(waiting[i] ? u1[i] : 0.0f);
    }
    // Field by field, built in registers (lanes written one by one to memory and read back
    // as a vector stall the load).
    auto field = [&](auto value) PHOTON_LANES_LAMBDA {
        if (fewTriangles) {
            const EmissionTriangles& tris = *in.shared;
            FloatLanes v = broadcast<FloatLanes>(value(tris[0]));
            for (size_t k = 1; k < tris.size(); ++k)
                v = select(picked == static_cast<int32_t>(k), broadcast<FloatLanes>(value(tris[k])), v);
            return v;
        }
        return FloatLanes{value(*tri[0]), value(*tri[1]), value(*tri[2]), value(*tri[3]),
                          value(*tri[4]), value(*tri[5]), value(*tri[6]), value(*tri[7])};
    };
    Vec3Lanes p0{field([](const T& t) { return t.p0.x; }), field([](const T& t) { return t.p0.y; }),
                 field([](const T& t) { return t.p0.z; })};
    Vec3Lanes e1{field([](const T& t) { return t.e1.x; }), field([](const T& t) { return t.e1.y; }),
                 field([](const T& t) { return t.e1.z; })};
    Vec3Lanes e2{field([](const T& t) { return t.e2.x; }), field([](const T& t) { return t.e2.y; }),
                 field([](const T& t) { return t.e2.z; })};
    Vec3Lanes s{field([](const T& t) { return t.frame.s.x; }), field([](const T& t) { return t.frame.s.y; }),
                field([](const T& t) { return t.frame.s.z; })};
    Vec3Lanes t{field([](const T& t) { return t.frame.t.x; }), field([](const T& t) { return t.frame.t.y; }),
                field([](const T& t) { return t.frame.t.z; })};
    Vec3Lanes n{field([](const T& t) { return t.frame.n.x; }), field([](const T& t) { return t.frame.n.y; }),
                field([](const T& t) { return t.frame.n.z; })};
    FloatLanes cdfLow = field([](const T& t) { return t.cdfLow; });
    FloatLanes inverseWidth = field([](const T& t) { return t.inverseWidth; });
    FloatLanes b0, b1;
    uniformTriangle(EmissionTriangles::reuse(u1, cdfLow, inverseWidth), u2, b0, b1);
    FloatLanes b2 = 1.0f - b0 - b1;
    Vec3Lanes p = p0 + e1 * b1 + e2 * b2;
    FloatLanes lx, ly, lz;
    cosineHemisphere(u3, u4, lx, ly, lz);
    Vec3Lanes d = s * lx + t * ly + n * lz;
    // spawnRay: off the light's surface, on the side the photon heads to.
    FloatLanes eps = rayOffsetDistance(p.x, p.y, p.z);
    Vec3Lanes offset = n * eps;
    Vec3Lanes o = select(dot(d, n) >= 0.0f, p + offset, p - offset);
    for (int i = 0; i < kLanes; ++i) {
        if (!waiting[i]) continue;
        out.ox[i] = o.x[i], out.oy[i] = o.y[i], out.oz[i] = o.z[i];
        out.dx[i] = d.x[i], out.dy[i] = d.y[i], out.dz[i] = d.z[i];
        out.betaR[i] = in.beta[i].x, out.betaG[i] = in.beta[i].y, out.betaB[i] = in.beta[i].z;
        out.emitted[i] = -1;
    }
}
PHOTON_LANES_KERNEL(emitFromTriangles, emitFromTrianglesLanes, (const TriangleLanes& in, PhotonEmitter::Lanes& out),
                    (in, out))

// Every lane's stream, Rng(stream, index[i]) eight at a time, and its first number (the
// light's). Lanes not wanted are seeded too, and ignored.
PHOTON_LANES_INLINE void seedLanesBody(uint64_t streamKey, const int64_t* index, PhotonEmitter::Lanes& out, float* uLight) {
    Uint64Lanes state, increment;
    seedPcg32<Uint64Lanes>(Uint64Lanes{} + streamKey, loadLanes<int64_t, Uint64Lanes>(index), state, increment);
    storeLanes(out.state, state);
    storeLanes(out.increment, increment);
    storeLanes(uLight, uniformLanes(out.state, out.increment, ~IntLanes{}));
}
PHOTON_LANES_KERNEL(seedLanes, seedLanesBody, (uint64_t streamKey, const int64_t* index, PhotonEmitter::Lanes& out, float* uLight),
                    (streamKey, index, out, uLight))

}  // namespace

void PhotonEmitter::emitLanes(const RngStream& stream, const int64_t* index, const int32_t* want, Lanes& out) const {
    TriangleLanes fromTriangles;
    bool anyTriangles = false;
    alignas(32) float uLight[kLanes];
    seedLanes(stream.key(), index, out, uLight);
    if (guide_) fromTriangles.scale = guide_->scale();
    for (int i = 0; i < kLanes; ++i) {
        out.emitted[i] = 0;
        out.cell[i] = 0;
        fromTriangles.waiting[i] = 0;
        fromTriangles.triangles[i] = nullptr;
        for (int d = 0; d < 4; ++d) fromTriangles.offset[d][i] = 0, fromTriangles.limit[d][i] = 0x1.fffffep-1f;
        if (!want[i]) continue;
        const LightChoice choice = pickLight(uLight[i]);
        out.cell[i] = choice.cell;
        out.light[i] = int32_t(choice.light);
        if (choice.picked && laneTriangles_[choice.light]) {
            fromTriangles.triangles[i] = laneTriangles_[choice.light];
            fromTriangles.beta[i] = laneFlux_[choice.light];
            if (guide_) {
                fromTriangles.beta[i] *= choice.weight;
                float offset[4], limit[4];
                guide_->cellBounds(choice.cell, offset, limit);
                for (int d = 0; d < 4; ++d) fromTriangles.offset[d][i] = offset[d], fromTriangles.limit[d][i] = limit[d];
            }
            fromTriangles.waiting[i] = -1;
            anyTriangles = true;
            continue;
        }
        Rng rng = Rng::resume(out.state[i], out.increment[i]);
        float u[4];
        for (float& x : u) x = rng.uniform();
        out.state[i] = rng.state();
        out.increment[i] = rng.increment();
        std::optional<EmittedPhoton> e = emitFrom(choice, u);
        if (!e) continue;
        out.ox[i] = e->ray.o.x, out.oy[i] = e->ray.o.y, out.oz[i] = e->ray.o.z;
        out.dx[i] = e->ray.d.x, out.dy[i] = e->ray.d.y, out.dz[i] = e->ray.d.z;
        out.betaR[i] = e->beta.x, out.betaG[i] = e->beta.y, out.betaB[i] = e->beta.z;
        out.emitted[i] = -1;
    }
    if (!anyTriangles) return;
    // Lanes that wait for no triangle read any waiting lane's (and keep their own results).
    const EmissionTriangles* some = nullptr;
    for (int i = 0; i < kLanes && !some; ++i) some = fromTriangles.triangles[i];
    fromTriangles.shared = some;
    for (int i = 0; i < kLanes; ++i) {
        if (!fromTriangles.triangles[i]) fromTriangles.triangles[i] = some;
        if (fromTriangles.triangles[i] != some) fromTriangles.shared = nullptr;
    }
    emitFromTriangles(fromTriangles, out);
}

}  // namespace photon
