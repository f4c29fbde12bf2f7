#include "api/upload_reader.h"
#include <httplib.h>
#include <exception>
#include "api/errors.h"

namespace photon::api {

namespace {

using server::ErrorKind;
using server::ServiceError;

// The body callbacks run inside httplib's parser: they must not throw through it. The first
// failure is kept and rethrown once reading ends. After a failure the rest of the body is
// still read and discarded (up to the size limit), so the client, which is still sending,
// receives our answer instead of a reset connection.
class BodySink {
public:
    BodySink(server::StagedUpload& upload, size_t maxBodyBytes) : upload_(upload), maxBodyBytes_(maxBodyBytes) {}

    bool onPart(const httplib::MultipartFormData& part) {
        return guard([&] {
            upload_.endAsset();
            if (part.name == "scene") {
                if (sawScene_) throw ServiceError(ErrorKind::BadRequest, "more than one scene part");
                sawScene_ = true;
                target_ = Target::Scene;
            } else if (!part.filename.empty()) {
                upload_.beginAsset(part.filename);
                target_ = Target::Asset;
            } else {
                throw ServiceError(ErrorKind::BadRequest,
                                   "form field \"" + part.name + "\" is neither the scene nor a file");
            }
        });
    }

    bool onData(const char* data, size_t size) {
        received_ += size;
        if (received_ > maxBodyBytes_) {
            fail(std::make_exception_ptr(ServiceError(
                ErrorKind::PayloadTooLarge, "request body exceeds " + std::to_string(maxBodyBytes_) + " bytes")));
            return false;  // stop reading: the sender is over the limit
        }
        return guard([&] {
            if (target_ == Target::Scene) upload_.sceneText().append(data, size);
            else if (target_ == Target::Asset) upload_.appendAsset(data, size);
        });
    }

    void finish(bool readOk, int httplibStatus, bool multipart) {
        if (failure_) std::rethrow_exception(failure_);
        if (!readOk && httplibStatus == 413)
            throw ServiceError(ErrorKind::PayloadTooLarge,
                               "request body exceeds " + std::to_string(maxBodyBytes_) + " bytes");
        if (!readOk) throw ServiceError(ErrorKind::BadRequest, "could not read the request body");
        upload_.endAsset();
        if (multipart && !sawScene_)
            throw ServiceError(ErrorKind::BadRequest, "multipart upload has no \"scene\" part");
    }

    void scenePlain() { target_ = Target::Scene; }

private:
    enum class Target { None, Scene, Asset };

    template <typename Fn>
    bool guard(Fn&& fn) {
        if (failure_) return true;  // discard
        try {
            fn();
        } catch (...) {
            fail(std::current_exception());
            target_ = Target::None;
        }
        return true;
    }
    void fail(std::exception_ptr e) {
        if (!failure_) failure_ = e;
    }

    server::StagedUpload& upload_;
    size_t maxBodyBytes_;
    size_t received_ = 0;
    Target target_ = Target::None;
    bool sawScene_ = false;
    std::exception_ptr failure_;
};

}  // namespace

void readUpload(const httplib::Request& req, httplib::Response& res, const httplib::ContentReader& reader,
                server::StagedUpload& upload, size_t maxBodyBytes) {
    BodySink sink(upload, maxBodyBytes);
    bool multipart = req.is_multipart_form_data();
    bool ok = false;
    if (multipart) {
        ok = reader([&](const httplib::MultipartFormData& part) { return sink.onPart(part); },
                    [&](const char* data, size_t size) { return sink.onData(data, size); });
    } else {
        sink.scenePlain();
        ok = reader([&](const char* data, size_t size) { return sink.onData(data, size); });
    }
    sink.finish(ok, res.status, multipart);
}

}  // namespace photon::api
