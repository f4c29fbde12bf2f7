// What GET /api/v1/jobs/{id}/image asks for (?format=, ?exposure=, ?size=, ?layer=, ?pass=), checked: a bad
// value is a 400 naming its parameter. And the names an answer gives its image: the ETag
// and the file name of Content-Disposition, which tell every variant apart.
#pragma once
#include <optional>
#include <string>
#include <photon/image_resize.h>
#include "server/image_format.h"
#include "server/image_variant.h"

namespace httplib {
struct Request;
}

namespace photon::api {

struct ImageQuery {
    server::ImageFormat format = server::ImageFormat::Png;
    std::optional<float> exposure;  // stops, PNG only
    std::optional<ImageSize> box;   // ?size=WxH: the box the image must fit in
    bool raw = false;               // ?layer=raw: the image before the denoiser
    bool errorMap = false;          // ?layer=error: the error heat map, a PNG
    std::optional<int> pass;        // ?pass=N: a kept earlier pass instead of the latest
};

ImageQuery parseImageQuery(const httplib::Request& req);

// "\"<id>-<pass>-<format><variant suffix>\"", e.g. "\"0123456789abcdef-4-png-256x192\"".
std::string imageEtag(const std::string& id, int pass, server::ImageFormat format,
                      const server::ImageVariant& variant);
// "inline; filename=\"<id>-pass<pass><variant suffix>.<format>\"": shown in the browser,
// and saved under a name that says which job, pass and variant it is.
std::string imageDisposition(const std::string& id, int pass, server::ImageFormat format,
                             const server::ImageVariant& variant);

}  // namespace photon::api
