// SPPM camera pass: a jittered path per pixel, followed through delta bounces to the
// first vertex with a diffuse lobe, where the visible point is stored. Direct light is
// gathered on the way by shadow rays (or left to photons, per render.direct). With
// render.adaptive_camera_paths a pixel may trace more paths, for their direct light alone
// (camera_paths.h).
#include "integrators/common/direct_lighting.h"
#include "integrators/common/pixel_loop.h"
#include "integrators/sppm/sppm.h"
#include "materials/fresnel.h"
#include <numeric>

namespace photon {

void SppmIntegrator::cameraPass(const CancelToken& cancel) {
    const RngStream stream(settings_.seed, static_cast<uint64_t>(passIndex_), StreamPurpose::Camera);
    // Counted by row: each row is one thread's, so no thread-local look-up per pixel.
    const int endRow = std::min(height_, bandFirstRow_ + bandRows_);
    std::vector<int64_t> rowRays(static_cast<size_t>(endRow - bandFirstRow_), 0), rowPaths(rowRays.size(), 0);
    forEachPixelOfRows(width_, bandFirstRow_, endRow, stream, cancel, [&](int, int y, size_t index, Rng& rng) {
        const CameraWork work =
            settings_.lightweight ? CameraWork{tracePixelLightweight(index, rng), 1} : tracePixel(index, rng);
        rowRays[static_cast<size_t>(y - bandFirstRow_)] += work.rays;
        rowPaths[static_cast<size_t>(y - bandFirstRow_)] += work.paths;
    });
    stats_.cameraRays += std::accumulate(rowRays.begin(), rowRays.end(), int64_t(0));
    stats_.cameraPaths += std::accumulate(rowPaths.begin(), rowPaths.end(), int64_t(0));
}

// Starting radius from the pixel's footprint at its first visible point: the footprint
// grows with the distance travelled, and is widened so that a pass's photons, spread over
// the image, put render.auto_radius_photons (8 unless set) in each disc: photons spread
// evenly over P pixels put k in a disc of pi r^2 pixels when r = sqrt(k P / (pi photons)).
// With radii that follow the light (adaptive_radius) a disc may start wider, up to
// kFlatDiscPixels, to hold up to kFlatPhotons: where the light is flat it keeps that radius,
// where it is not the radius shrinks to what its photons show. On the Bitterli Cornell box
// at 256² (200k photons: 8 a disc at 0.91 pixels, so 1.5, the least) 2.5 pixels left 0.78
// of the noise at 30 s, and 0.90 of the RMSE (1.5: 0.0148, 0.0226; 2: 0.0128; 2.5: 0.0115,
// 0.0203; 3: 0.0118, 0.0210). At 64², where a disc of 1.5 pixels already holds hundreds
// of photons, 2.5 pixels cost a fifth of the passes and left more noise (0.0078 against
// 0.0066); kFlatPhotons keeps such discs where they are. Wide discs over fine geometry
// biased coffee (k = 32: +1.7% in the mean), whose discs the cap leaves as they are (3.2
// pixels). The glass Cornell box at 256²: 0.75 of the noise; the textured mesh at 512²
// (1.8 pixels before): 0.94. docs/sppm.md#wider-starts-where-radii-follow-the-light.
float SppmIntegrator::autoRadius(float pathLength, bool inMedium) const {
    const float pixels = static_cast<float>(width_) * static_cast<float>(height_);
    auto discPixels = [&](float photons) {
        return std::sqrt(photons * pixels / (kPi * static_cast<float>(settings_.photonsPerPass)));
    };
    float disc = std::clamp(discPixels(settings_.autoRadiusPhotons), 1.5f, 16.0f);
    // A ball in a medium shrinks by alpha's schedule whatever the light (its photons' spread
    // is not read: PhotonSpread), so it starts as it always did.
    if (adaptsRadius_ && !inMedium) disc = std::max(disc, std::min(kFlatDiscPixels, discPixels(kFlatPhotons)));
    return scene_->camera().pixelFootprint(pathLength) * disc;
}

Camera::PixelSample SppmIntegrator::startPixel(size_t index, PathSampler& sampler) {
    discs_[index - bandOffset_] = GatherDisc{};
    visible_[index - bandOffset_] = VisiblePoint{};
    return cameraRay(index, sampler);
}

PathSampler SppmIntegrator::pathSampler(size_t index, Rng& rng, int path) const {
    return PathSampler::of(settings_.sampler == SamplerKind::Sobol, rng, settings_.seed, passIndex_, index,
                           static_cast<uint64_t>(path));
}

Camera::PixelSample SppmIntegrator::cameraRay(size_t index, PathSampler& sampler) const {
    const Vec2 uFilm = sampler.get2D();
    const Vec2 uLens = scene_->camera().hasLens() ? sampler.get2D() : Vec2{0.5f, 0.5f};
    return scene_->camera().samplePixel(static_cast<int>(index % width_), static_cast<int>(index / width_), uFilm, uLens);
}

SppmIntegrator::CameraWork SppmIntegrator::tracePixel(size_t index, Rng& rng) {
    Color direct(0.0f);
    LobeChoiceRecord choice;
    PathSampler sampler = pathSampler(index, rng, 0);
    CameraWork work{tracePath(index, startPixel(index, sampler), sampler, true, direct, choice), 1};
    double squares = luminance(direct) * luminance(direct);
    const float paths =
        adaptsCameraPaths_
            ? cameraPaths_.pathsAt(index, [&](size_t j) { return luminance(pixels_[j].directSum); })
            : 1.0f;
    if (paths > 1) {
        // A whole number of paths of mean `paths` (the random draw only where it is not one,
        // so that pixels that trace one path draw what they always did).
        const float whole = std::floor(paths);
        work.paths = static_cast<int>(whole) + (rng.uniform() < paths - whole ? 1 : 0);
        const Color first = direct;
        for (int k = 1; k < work.paths; ++k) {
            Color more(0.0f);
            LobeChoiceRecord unused;
            PathSampler extraSampler = pathSampler(index, rng, k);
            work.rays += tracePath(index, cameraRay(index, extraSampler), extraSampler, false, more, unused);
            direct += more;
            squares += luminance(more) * luminance(more);
        }
        direct /= static_cast<float>(work.paths);
        // The lobe choice learns from the pass's luminance less the light found before the
        // choice (lobe_choice.h): what the first path's choice brought stays so with the
        // paths' mean in the pass.
        if (choice.made())
            choice = LobeChoiceRecord::of(choice.others(), choice.probability(),
                                          choice.directBeforeChoice() + luminance(direct) - luminance(first));
    }
    PassResult& out = result(index);
    out.direct = SharedExponentColor::of(direct, rng.uniform());  // the pixel's last draw
    out.choice = choice;
    out.extraPaths = static_cast<uint8_t>(work.paths - 1);
    out.squares = toBfloat16(static_cast<float>(squares));
    return work;
}

int SppmIntegrator::tracePath(size_t index, const Camera::PixelSample& start, PathSampler& sampler, bool first,
                              Color& direct, LobeChoiceRecord& choice) {
    const Scene& scene = *scene_;
    const bool directBySampling = settings_.direct == DirectLighting::LightSampling;
    Ray ray = start.ray;
    Color beta(start.weight);
    // Area light is counted where no shadow ray could have found it (after delta bounces);
    // the environment is shared between shadow rays and BSDF samples (BounceSampling).
    BounceSampling bounce;
    float pathLength = 0;
    // render.lobe_choice: the first choice between a diffuse base and other lobes (lobe_choice.h).
    int rays = 0;  // a light sample's shadow ray counted as one whether or not it is cast
    int32_t medium = scene.description().camera.medium;
    // Paths scatter in media that scatter and estimate the light of media that emit (one
    // number a segment in them); elsewhere they draw what they always did.
    PathInMedia inMedia{sampler, {}};
    PathInMedia* media = scene.hasScatteringMedia() || scene.hasEmittingMedia() ? &inMedia : nullptr;
    inMedia.seesAhead = first && gathersInMedia();  // for the ball of the visible point it may leave
    inMedia.lightAlongContinues = !gathersInMedia();  // a volume point ends the path (sampleDirectLightInMedium)
    // Whether the light the next ray lands on was counted already, by the look-up along the
    // same direction at the vertex it leaves.
    bool lightCounted = false;
    int walkEvents = 0;  // scattering events under surfaces (walksUnderSurface)
    for (int depth = 0; depth < settings_.maxDepth; ++depth) {
        SurfaceHit hit;
        ++rays;
        Color counted(0.0f);
        // A point the ray scatters at takes a light sample, unless photons bring its direct light.
        inMedia.lightAlong = !gathersInMedia() || directBySampling ? &direct : nullptr;
        const RayEnd end = traceCameraRay(scene, ray, beta, medium, bounce, hit, lightCounted ? counted : direct, media);
        lightCounted = false;
        if (end == RayEnd::Left) break;
        pathLength += hit.t;
        Vec3 wo = -ray.d;
        if (end == RayEnd::Scattered) {
            // A vertex in the medium. With volume photons the path ends at its first one:
            // its light sample brings single scattering (unless photons bring direct light),
            // the photons gathered around it the rest.
            // (Not under a surface, where the path walks on: no photons are left there.)
            if (gathersInMedia() && !scene.medium(medium).subsurface) {
                if (directBySampling)
                    direct += beta * sampleDirectLightInMedium(scene, hit.p, wo, medium, sampler, false, &inMedia.segment), ++rays;
                if (first) storeVolumePoint(index, hit.p, wo, beta, medium, pathLength, inMedia.behind, inMedia.ahead);
                break;
            }
            // Else its light sample, and the phase function's direction, whose ray at the
            // last vertex is traced only for the light it shares with the light sample.
            // Under a surface the walk takes no light samples (walksUnderSurface).
            const bool underSurface = walksUnderSurface(scene, medium, walkEvents);
            if (!underSurface)
                direct += beta * sampleDirectLightInMedium(scene, hit.p, wo, medium, sampler, true, &inMedia.segment), ++rays;
            ray = underSurface ? stepUnderSurface(scene, hit.p, wo, medium, inMedia, bounce)
                               : scatterInMedium(scene, hit.p, wo, medium, sampler.get2D(), bounce);
            inMedia.boundaryNormal = Vec3(0.0f);
            if (underSurface) {
                --depth;  // the walk is no vertex: the next event has this depth too
            } else if (depth == settings_.maxDepth - 1) {
                traceCameraRay(scene, ray, beta, medium, bounce, hit, direct), ++rays;
                break;
            }
            if ((depth >= 3 || walkEvents >= 3) && maxComponent(beta) < 1.0f && !survivesRoulette(beta, sampler.get1D()))
                break;
            continue;
        }
        ShadingPoint sp = makeShadingPoint(scene, hit, wo);
        const Material& m = *sp.material;
        // The visible point goes on the first surface with a diffuse lobe (or any non-delta
        // one at the last vertex). A material with other lobes beside the diffuse one
        // (plastic's coat) stops on the diffuse lobe with probability pd and otherwise
        // follows the others by sampling, so photons are never gathered through a sharp
        // highlight, where they would show as fireflies.
        const bool lastVertex = depth == settings_.maxDepth - 1;
        const bool storesHere = m.hasDiffuse() || (!m.isDeltaOnly() && lastVertex);
        const unsigned others = m.lobes() & ~kDiffuseLobe;
        const bool splits = m.hasDiffuse() && others && !lastVertex;
        const Vec3 woLocal = sp.frame.toLocal(wo);
        float pd = splits ? m.diffuseShare(woLocal, sp.inputs) : 1.0f;
        const bool firstChoice = splits && !choice.made();
        if (firstChoice && learnsLobeChoice_) pd = 1.0f - lobeChoice_.othersProbability(index, 1.0f - pd);
        // At the last vertex a material with lobes beside the diffuse one also traces one
        // BSDF sample, only for the light it shares with the light sample (as the path tracer
        // does): a narrow highlight found by light samples alone is mostly noise.
        const bool lastLookup = storesHere && lastVertex && others;
        // What the path samples after the light sample: everything where it does not stop
        // (or looks up the light at the last vertex), the other lobes where it splits (drawn
        // every time, for the light they find; below), nothing where it stops.
        const BsdfContinuation next = !storesHere || lastLookup ? BsdfContinuation{kAllLobes, 1.0f}
                                      : splits                  ? BsdfContinuation{others, 1.0f}
                                                                : BsdfContinuation{};
        if (!m.isDeltaOnly() && (directBySampling || !storesHere || m.alignsToTangent()))
            direct += beta * sampleDirectLight(scene, sp, wo, sampler, kAllLobes, next, medium), ++rays;
        else if (splits)  // photons bring direct light through the diffuse lobe only
            direct += beta * sampleDirectLight(scene, sp, wo, sampler, others, next, medium), ++rays;
        // Where it splits, the other lobes' sample is drawn whether or not the path follows
        // it, and the light it finds counted in full (weighted against the light sample): a
        // narrow coat's highlight then comes in every pass instead of, at 1 / (1 - pd) of
        // its weight, in the few where the path follows the coat, which then leaves out the
        // light its ray lands on. Coffee renders 20-22 passes in 30 s against 24-26, with 8%
        // less RGB noise and 4% lower RMSE (docs/sppm.md, "What coffee's noise is made of").
        std::optional<BSDFSample> othersSample;
        if (splits) {
            const Vec2 u = sampler.get2D();
            const float uOthers = sampler.get1D();
            othersSample = m.sample(woLocal, uOthers, u, sp.inputs, TransportMode::Radiance, others);
            if (othersSample) rays += lookUpLight(scene, hit, sp, *othersSample, beta, medium, direct);
        }
        const float reflectance =
            learnsLobeChoice_ && !choice.made() && !storesHere ? smoothDielectricReflectance(m, woLocal) : 0.0f;
        const bool learnedDielectricChoice = reflectance > 0 && reflectance < 1;
        // Draws only what the path uses: a path that stops on a plain diffuse surface (most
        // of them) draws none here. A choice whose probability was learned from earlier
        // passes draws from the pixel's independent stream: a Sobol number is stratified
        // against those passes' numbers, so it would not fall below the learned probability
        // with that probability, and the choice's weight would be wrong.
        const bool learnedChoice = (firstChoice && learnsLobeChoice_) || learnedDielectricChoice;
        const float uLobe = storesHere && !splits ? 0.0f : learnedChoice ? sampler.rng().uniform() : sampler.get1D();
        if (firstChoice) choice = LobeChoiceRecord::of(uLobe >= pd, uLobe >= pd ? 1.0f - pd : pd, luminance(direct));
        if (storesHere) {
            if (uLobe >= pd) {
                const std::optional<BSDFSample>& s = othersSample;
                if (!s) break;
                lightCounted = true;
                beta *= s->weight / (1.0f - pd);
                bounce = bounceFrom(sp, *s);
                ray = spawnRay(hit.p, hit.ng, sp.frame.toWorld(s->wi));
                leaveSurface(scene, hit, ray.d, medium, inMedia);
                continue;
            }
            // A fibre's scattering needs its tangent, which a visible point does not keep: a
            // path that ends on one (at the last vertex) keeps only its light sample and lookup.
            if (first && !m.alignsToTangent())
                storeVisiblePoint(index, sp, wo, beta / pd, splits ? kDiffuseLobe : kAllLobes, pathLength);
            if (lastLookup) {
                const float uLast = sampler.get1D();
                const Vec2 u = sampler.get2D();
                if (std::optional<BSDFSample> s = m.sample(woLocal, uLast, u, sp.inputs, TransportMode::Radiance))
                    rays += lookUpLight(scene, hit, sp, *s, beta, medium, direct);
            }
            break;
        }
        const Vec2 u = sampler.get2D();
        std::optional<BSDFSample> s;
        if (learnedDielectricChoice) {
            // The first choice between a smooth dielectric's reflection and refraction is
            // learned as a coat's is (lobe_choice.h): reflection with probability q instead
            // of F, so the sample's weight F / q or (1 - F) / (1 - q) (its pdf being F or 1 - F).
            const float q = lobeChoice_.othersProbability(index, reflectance);
            const bool reflects = uLobe < q;
            s = m.sample(woLocal, reflects ? 0.5f * reflectance : 0.5f * (1.0f + reflectance), u, sp.inputs,
                         TransportMode::Radiance);
            if (s) s->weight *= s->pdf / (reflects ? q : 1.0f - q);
            choice = LobeChoiceRecord::of(reflects, reflects ? q : 1.0f - q, luminance(direct));
        } else {
            s = m.sample(woLocal, uLobe, u, sp.inputs, TransportMode::Radiance);
        }
        if (!s) break;
        beta *= s->weight;
        // Russian roulette past the third vertex, as the path tracer, where the path has lost
        // light: a path through dark hair (Material::alignsToTangent) loses most of it at each
        // fibre and would otherwise go on to render.max_depth. A path that keeps all of it
        // (through clear glass) draws no number, so its samples stay as they were.
        if (depth >= 3 && maxComponent(beta) < 1.0f && !survivesRoulette(beta, sampler.get1D())) break;
        bounce = bounceFrom(sp, *s);
        ray = spawnRay(hit.p, hit.ng, sp.frame.toWorld(s->wi));
        const int32_t before = medium;
        leaveSurface(scene, hit, ray.d, medium, inMedia);
        if (reflectsUnderSurface(scene, hit, before, medium, walkEvents)) --depth;
        entersUnderSurface(scene, hit, before, medium, inMedia);
    }
    return rays + inMedia.raysAlong;
}

void SppmIntegrator::leaveSurface(const Scene& scene, const SurfaceHit& hit, Vec3 d, int32_t& medium, PathInMedia& inMedia) {
    medium = scene.mediumToward(hit, d, medium);
    if (!scene.hasScatteringMedia()) return;
    // A refracting ball's glass bounds the medium the path goes on in, seen from in or out.
    inMedia.boundaryNormal = boundsMediumToward(scene, hit, -d, medium) ? hit.ng : Vec3(0.0f);
}

// F at a smooth dielectric boundary seen along woLocal; 0 for any other material.
float SppmIntegrator::smoothDielectricReflectance(const Material& m, Vec3 woLocal) {
    const std::optional<Material::SmoothSpecular> smooth = m.smoothSpecular();
    return smooth && smooth->ior > 0 ? fresnelDielectric(woLocal.z, smooth->ior) : 0.0f;
}

bool SppmIntegrator::lookUpLight(const Scene& scene, const SurfaceHit& at, const ShadingPoint& sp, const BSDFSample& s,
                                 Color beta, int32_t medium, Color& direct) {
    const Ray ray = spawnRay(sp.hit.p, sp.hit.ng, sp.frame.toWorld(s.wi));
    if (!scene.mayFindLight(ray)) return false;
    beta *= s.weight;
    SurfaceHit hit;
    int32_t next = scene.mediumToward(at, ray.d, medium);
    traceCameraRay(scene, ray, beta, next, bounceFrom(sp, s), hit, direct);
    return true;
}

float SppmIntegrator::passRadiusSquared(size_t index, float pathLength, float extinction) const {
    // Only the render thread writes pixels_ (in updateStatistics), so reading here is safe.
    // The guide's training passes start from the first pass's radii, whatever pass follows.
    float r2 = global() || guidePass_ >= 0 ? 0.0f : pixels_[index].r2;
    if (r2 == 0) {
        float r = settings_.initialRadius > 0 ? settings_.initialRadius : autoRadius(pathLength, extinction > 0);
        // In a medium photons scatter about once in a mean free path 1 / sigma_t of the way
        // they travel, so where a disc of radius r_s would hold k photons on a surface the
        // same flux puts about sigma_t k (4/3 pi r^3) / (pi r_s^2) in a ball: r^3 = 3 r_s^2 /
        // (4 sigma_t) keeps k. In a white furnace of fog (extinction 1, 2 and 4) after 256
        // passes of 1,000 photons the auto radius of a disc (0.054) left the ball's estimate
        // 8-16% low, most balls gathering no photon; this one (0.10) within 1%.
        if (extinction > 0 && settings_.initialRadius <= 0) r = std::cbrt(0.75f * r * r / extinction);
        r2 = r * r;
        if (global()) r2 *= globalShrink_;
    }
    return r2;
}

void SppmIntegrator::storeVolumePoint(size_t index, Vec3 p, Vec3 wo, Color beta, int32_t medium, float pathLength,
                                      const CuttingPlane& behind, const CuttingPlane& ahead) {
    // In a medium of varying density, its coefficients where the point is.
    const MediumDescription& m = scene_->medium(medium);
    const float density = m.densityAt(p);
    const Color sigmaT = m.extinction() * density;
    const float r2 = passRadiusSquared(index, pathLength, (sigmaT.x + sigmaT.y + sigmaT.z) / 3);
    const size_t local = index - bandOffset_;
    discs_[local] = GatherDisc{p, r2};
    // Photons arrive where they scatter with flux whose density per unit volume and solid
    // angle is sigma_s L_i (free_flight.h), so sum(p Phi) / (4/3 pi r^3) estimates sigma_s
    // times the in-scattered radiance, and the path's throughput is divided by sigma_s. The
    // factor 3 / (4 r) turns the ball's volume into the disc's area, pi r^2, by which the
    // statistics divide every pass's flux; the radius then shrinks by the disc's rule, still
    // consistent in a volume for alpha > 1/3 (Knaus & Zwicker 2011, sec. 4.3: a pass's
    // variance grows as r^-3, and r^2 falls as i^(alpha - 1)).
    // Photons arriving in a medium of varying density count over the density where they
    // scattered (addPhoton), so the point's weight is over the medium's sigma_s alone.
    const Color sigmaS = m.scattering;
    Color weight;
    for (int c = 0; c < 3; ++c) weight[c] = sigmaS[c] > 0 ? beta[c] / sigmaS[c] : 0.0f;
    weight *= 0.75f / std::sqrt(r2);
    // Photons scatter only inside the medium: a ball that reaches past its boundary holds
    // them over the part inside, which is what the estimate divides by. The boundary is
    // taken as the planes of the surface the path entered by (or last turned at, inside)
    // and of the one its ray would have gone on to: beyond each a cap of the ball is
    // missing (math/ball_in_half_spaces.h). Without the first a ball of fog behind glass
    // in a white sky came out 3-6% dark at 1,024 passes; without the second fog over a
    // mirror seen from above 2% dark at 256 (docs/sppm.md, "Volume photons").
    // In a gap much thinner than the ball the share is small and the few photons there
    // count many times over: at most tenfold.
    const float share = ballShareInside(behind, ahead, std::sqrt(r2));
    if (share < 1.0f) weight /= std::max(share, 0.1f);
    VisiblePoint& vp = visible_[local];
    vp = VisiblePoint{};
    vp.n = OctahedralVector(wo);
    vp.beta = weight;
    vp.material = static_cast<uint32_t>(medium);
    vp.inMedium = 1;
    if (guidePass_ >= 0) vp.setGuideWeight(guideWeight(index));
}

void SppmIntegrator::storeVisiblePoint(size_t index, const ShadingPoint& sp, Vec3 wo, Color beta, unsigned lobes,
                                       float pathLength) {
    OctahedralVector n(sp.hit.ns);
    Frame frame = Frame::fromNormal(n.decode());  // the frame photons will see
    const float r2 = passRadiusSquared(index, pathLength);
    const size_t local = index - bandOffset_;
    discs_[local] = GatherDisc{sp.hit.p, r2};
    Vec3 woLocal = frame.toLocal(wo);
    // Seen from below its (quantised) normal a surface reflects nothing: leave that to eval().
    const bool lambertian = sp.material->lambertian() && woLocal.z > 0;
    visible_[local] = VisiblePoint{n, OctahedralVector(woLocal), lambertian ? beta * sp.inputs.tint * kInvPi : beta,
                                   sp.hit.uv, scene_->materialIndex(sp.hit), lobes, lambertian, sp.material->transmits()};
    if (guidePass_ >= 0) visible_[local].setGuideWeight(guideWeight(index));
}

}  // namespace photon
