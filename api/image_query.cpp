#include "api/image_query.h"
#include <httplib.h>
#include <climits>
#include "api/errors.h"
#include "api/params.h"

namespace photon::api {

namespace {

const std::string kSizeExpected = "query parameter size: expected WIDTHxHEIGHT, each a whole number in [1, " +
                                  std::to_string(server::kMaxBoxSide) + "]";

int boxSide(const std::string& text) {
    std::optional<int64_t> value = parseWhole<int64_t>(text);
    if (!value || *value < 1 || *value > server::kMaxBoxSide) throwBadRequest(kSizeExpected);
    return static_cast<int>(*value);
}

std::optional<ImageSize> sizeParam(const httplib::Request& req) {
    std::optional<std::string> text = stringParam(req, "size");
    if (!text) return std::nullopt;
    size_t x = text->find('x');
    if (x == std::string::npos) throwBadRequest(kSizeExpected);
    return ImageSize{boxSide(text->substr(0, x)), boxSide(text->substr(x + 1))};
}

}  // namespace

ImageQuery parseImageQuery(const httplib::Request& req) {
    ImageQuery query;
    std::optional<server::ImageFormat> format = server::parseImageFormat(stringParam(req, "format").value_or("png"));
    if (!format) throwBadRequest("query parameter format: expected png or exr");
    query.format = *format;
    if (std::optional<double> ev = numberParam(req, "exposure", server::kMinExposure, server::kMaxExposure)) {
        if (query.format != server::ImageFormat::Png)
            throwBadRequest("query parameter exposure: applies to format=png only (the EXR is linear)");
        query.exposure = static_cast<float>(*ev) + 0.0f;  // -0 is 0 (one ETag for one image)
    }
    query.box = sizeParam(req);
    if (std::optional<std::string> layer = stringParam(req, "layer")) {
        if (*layer == "raw") {
            query.raw = true;
        } else if (*layer == "error") {
            if (query.format != server::ImageFormat::Png)
                throwBadRequest("query parameter layer: error is a PNG heat map (the EXR holds the channels error.sd, "
                                "error.relative and error.luminance)");
            if (query.exposure)
                throwBadRequest("query parameter exposure: does not apply to layer=error (its colours are a scale)");
            query.errorMap = true;
        } else {
            throwBadRequest("query parameter layer: expected raw or error");
        }
    }
    if (std::optional<std::string> text = stringParam(req, "pass")) {
        std::optional<int64_t> pass = parseWhole<int64_t>(*text);
        if (!pass || *pass < 1 || *pass > INT32_MAX) throwBadRequest("query parameter pass: expected a whole number >= 1");
        query.pass = int(*pass);
    }
    return query;
}

std::string imageEtag(const std::string& id, int pass, server::ImageFormat format,
                      const server::ImageVariant& variant) {
    return "\"" + id + "-" + std::to_string(pass) + "-" + server::toString(format) + server::variantSuffix(variant) +
           "\"";
}

std::string imageDisposition(const std::string& id, int pass, server::ImageFormat format,
                             const server::ImageVariant& variant) {
    // The id is hex and the suffix digits, "x", "-", "e", "v" and ".": nothing to quote.
    return "inline; filename=\"" + id + "-pass" + std::to_string(pass) + server::variantSuffix(variant) + "." +
           server::toString(format) + "\"";
}

}  // namespace photon::api
