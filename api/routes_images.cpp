// GET /api/v1/jobs/{id}/image: the latest pass as PNG or EXR, at another exposure or size
// if asked (api/image_query.h), with ETag revalidation.
// GET /api/v1/jobs/{id}/stream: multipart/x-mixed-replace, one PNG frame per finished pass
// (a browser <img> shows it as a live picture), ending when the job finishes.
#include <httplib.h>
#include <algorithm>
#include <memory>
#include <sstream>
#include "api/errors.h"
#include "api/handlers.h"
#include "api/image_query.h"
#include "api/params.h"
#include "api/stream_support.h"

namespace photon::api {

namespace {

// If-None-Match holds "*" or a comma-separated list of (possibly weak) entity tags.
bool etagMatches(const std::string& header, const std::string& etag) {
    std::stringstream list(header);
    std::string tag;
    while (std::getline(list, tag, ',')) {
        size_t b = tag.find_first_not_of(" \t"), e = tag.find_last_not_of(" \t");
        if (b == std::string::npos) continue;
        tag = tag.substr(b, e - b + 1);
        if (tag.rfind("W/", 0) == 0) tag = tag.substr(2);
        if (tag == "*" || tag == etag) return true;
    }
    return false;
}

std::string frame(const server::EncodedImage& image) {
    return "--frame\r\nContent-Type: image/png\r\nContent-Length: " + std::to_string(image.bytes->size()) +
           "\r\nX-Photon-Pass: " + std::to_string(image.pass) + "\r\n\r\n" + *image.bytes + "\r\n";
}

struct FrameStream {
    std::shared_ptr<StreamSlots::Slot> slot;
    server::JobService& service;
    std::string id;
    uint64_t afterSeq = 0;
    bool finished = false;  // known at connect
    bool started = false;
    int lastPass = 0;  // frames are sent only for newer passes

    bool sendLatest(httplib::DataSink& sink) {
        std::optional<server::EncodedImage> image = service.image(id, server::ImageFormat::Png);
        if (!image || image->pass <= lastPass) return true;
        lastPass = image->pass;
        return writeAll(sink, frame(*image));
    }
    bool end(httplib::DataSink& sink) {
        if (!sendLatest(sink) || !writeAll(sink, "--frame--\r\n")) return false;
        endStream(sink, slot);
        return true;
    }

    bool step(httplib::DataSink& sink) {
        if (!started) {
            started = true;
            return finished ? end(sink) : sendLatest(sink);
        }
        server::EventHub::Wait wait = service.events().waitAfter(id, afterSeq, kStreamPoll);
        if (wait.closed) {
            endStream(sink, slot);
            return true;
        }
        if (wait.events.empty()) return true;
        afterSeq = wait.events.back().seq;
        // A slow reader skips passes: only the newest image matters for a live view.
        return wait.events.back().type == server::EventType::Progress ? sendLatest(sink) : end(sink);
    }
};

}  // namespace

void getImage(RouteContext& ctx, const httplib::Request& req, httplib::Response& res) {
    std::string id = pathId(req);
    ImageQuery query = parseImageQuery(req);
    const server::JobRecord job = ctx.service.get(id);
    const server::JobSettings& settings = job.settings;
    if (query.raw && !settings.denoise)
        throwBadRequest("query parameter layer: job " + id + " is not denoised, so its image is the raw one");
    const server::ImageVariant variant =
        server::variantFor(query.exposure, query.box, {settings.width, settings.height}, query.raw, query.errorMap);
    // The plain image is served as cached; a variant is made from the same pass's EXR, and
    // a kept earlier pass is an EXR on disk.
    server::ImageFormat source = variant.isDefault() ? query.format : server::ImageFormat::Exr;
    std::optional<server::EncodedImage> image;
    const bool kept = query.pass && std::binary_search(job.keptPasses.begin(), job.keptPasses.end(), *query.pass);
    if (query.pass && !kept && *query.pass == job.progress.pass) {
        // The latest pass asked for by its number: the latest image, if it is still that pass.
        image = ctx.service.image(id, source);
        if (image && image->pass != *query.pass) image = ctx.service.keptPass(id, *query.pass);  // moved on
    } else if (query.pass) {
        image = ctx.service.keptPass(id, *query.pass);  // NotFound, naming the kept ones
        source = server::ImageFormat::Exr;
    } else {
        image = ctx.service.image(id, source);
    }
    if (!image) throw server::ServiceError(server::ErrorKind::NotReady, "job " + id + " has no image yet");
    std::string etag = imageEtag(id, image->pass, query.format, variant);
    res.set_header("ETag", etag);
    res.set_header("X-Photon-Pass", std::to_string(image->pass));
    res.set_header("Cache-Control", "no-cache");  // revalidate: the image changes every pass
    if (etagMatches(req.get_header_value("If-None-Match"), etag)) {
        res.status = 304;
        return;
    }
    res.set_header("Content-Disposition", imageDisposition(id, image->pass, query.format, variant));
    // Serve the shared bytes without copying them into the response.
    std::shared_ptr<const std::string> bytes =
        source == query.format && variant.isDefault() ? image->bytes
                                                      : server::encodeVariant(*image->bytes, query.format, variant);
    res.status = 200;
    res.set_content_provider(bytes->size(), server::mimeType(query.format),
                             [bytes](size_t offset, size_t length, httplib::DataSink& sink) {
                                 return sink.write(bytes->data() + offset, length);
                             });
}

void streamImages(RouteContext& ctx, const httplib::Request& req, httplib::Response& res) {
    std::string id = pathId(req);
    std::optional<server::EventHub::Snapshot> snap = ctx.service.events().current(id);
    if (!snap) throw server::ServiceError(server::ErrorKind::NotFound, "no job " + id);
    auto stream = std::make_shared<FrameStream>(
        FrameStream{ctx.streams.acquire(), ctx.service, id, snap->seq, server::isFinished(snap->job.status)});
    res.set_header("Cache-Control", "no-cache");
    res.set_chunked_content_provider("multipart/x-mixed-replace; boundary=frame",
                                     guardedProvider([stream](httplib::DataSink& sink) { return stream->step(sink); }),
                                     ctx.streams.countWriting());
}

}  // namespace photon::api
