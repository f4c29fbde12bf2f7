#include "api/upload_reader.h"
#include <httplib.h>
#include <algorithm>
#include <exception>
#include "api/errors.h"
#include "server/job_folders.h"
#include "server/service_limits.h"

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
    BodySink(server::StagedUpload& upload, const UploadLimits& limits, server::RequestDigest& digest)
        : upload_(upload), limits_(limits), digest_(digest) {}

    bool onPart(const httplib::MultipartFormData& part) {
        if (++parts_ > limits_.maxParts) {
            fail(std::make_exception_ptr(ServiceError(
                ErrorKind::PayloadTooLarge, "multipart upload has more than " + std::to_string(limits_.maxParts) +
                                                " parts, the server limit (" +
                                                server::optionOf(&server::Limits::maxUploadParts) + ")")));
            return false;  // stop reading: the sender is over the limit
        }
        // The part's identity, not the boundary (which a retry may choose afresh), is hashed.
        digest_.endField();
        for (const std::string* field : {&part.name, &part.filename}) {
            digest_.add(field->data(), field->size());
            digest_.endField();
        }
        return guard([&] {
            upload_.endAsset();
            endField();
            if (part.name == "scene") {
                if (sawScene_) throw ServiceError(ErrorKind::BadRequest, "more than one scene part");
                sawScene_ = true;
                std::optional<std::string> stored = server::JobFolders::sceneFileNameFor(part.filename);
                if (!stored)
                    throw ServiceError(ErrorKind::BadRequest, "scene part (file name \"" + part.filename +
                                                                  "\"): expected " +
                                                                  server::JobFolders::acceptedSceneFiles());
                upload_.setSceneFileName(*stored);
                target_ = Target::Scene;
                fields_.sceneFileName = part.filename;
            } else if (part.filename.empty() &&
                       (part.name == "name" || part.name == "label" || part.name == "camera" || part.name == "lenient")) {
                target_ = Target::Field;
                fieldName_ = part.name;
            } else if (!part.filename.empty()) {
                upload_.beginAsset(part.name, part.filename);
                target_ = Target::Asset;
            } else {
                throw ServiceError(ErrorKind::BadRequest, "form field \"" + part.name +
                                                              "\" is neither the scene, a file, \"name\", \"label\", \"camera\" "
                                                              "nor \"lenient\"");
            }
        });
    }

    bool onData(const char* data, size_t size) {
        received_ += size;
        if (received_ > limits_.maxBodyBytes) {
            fail(std::make_exception_ptr(ServiceError(ErrorKind::PayloadTooLarge, bodyTooLarge())));
            return false;  // stop reading: the sender is over the limit
        }
        digest_.add(data, size);
        if (target_ == Target::Scene) sceneBytes_ += size;  // counted on, to report the size
        return guard([&] {
            if (target_ == Target::Scene) appendScene(data, size);
            else if (target_ == Target::Asset) upload_.appendAsset(data, size);
            else if (target_ == Target::Field) appendField(data, size);
        });
    }

    void finish(bool readOk, int httplibStatus, bool multipart) {
        digest_.endField();
        if (sceneBytes_ > limits_.maxSceneBytes)
            server::checkLimit(ErrorKind::PayloadTooLarge, "the scene file's size in bytes", int64_t(sceneBytes_),
                               int64_t(limits_.maxSceneBytes), server::optionOf(&server::Limits::maxSceneBytes));
        if (failure_) std::rethrow_exception(failure_);
        if (!readOk && httplibStatus == 413) throw ServiceError(ErrorKind::PayloadTooLarge, bodyTooLarge());
        if (!readOk) throw ServiceError(ErrorKind::BadRequest, "could not read the request body");
        upload_.endAsset();
        endField();
        if (multipart && !sawScene_)
            throw ServiceError(ErrorKind::BadRequest, "multipart upload has no \"scene\" part");
    }

    void scenePlain() { target_ = Target::Scene; }
    UploadFields& fields() { return fields_; }

private:
    enum class Target { None, Scene, Asset, Field };

    // A name or label is short; past this it is cut, and found too long when checked.
    static constexpr size_t kMaxFieldBytes = 1024;
    void appendField(const char* data, size_t size) {
        field_.append(data, std::min(size, kMaxFieldBytes + 1 - std::min(field_.size(), kMaxFieldBytes + 1)));
    }
    void endField() {
        if (target_ != Target::Field) return;
        if (fieldName_ == "name") fields_.name = field_;
        else if (fieldName_ == "camera") fields_.camera = field_;
        else if (fieldName_ == "lenient") fields_.lenient = field_;
        else fields_.labels.push_back(field_);
        field_.clear();
        target_ = Target::None;
    }

    // Past the limit the scene is no longer kept, only counted: finish() reports its size.
    void appendScene(const char* data, size_t size) {
        if (sceneBytes_ <= limits_.maxSceneBytes) upload_.sceneText().append(data, size);
        else upload_.sceneText().clear();
    }
    std::string bodyTooLarge() const {
        return "the request body is larger than this server takes (" + std::to_string(limits_.maxBodyBytes) +
               " bytes); its administrator sets that limit with " + server::optionOf(&server::Limits::maxBodyBytes);
    }

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
    const UploadLimits& limits_;
    size_t parts_ = 0;
    server::RequestDigest& digest_;
    size_t received_ = 0;
    size_t sceneBytes_ = 0;
    Target target_ = Target::None;
    bool sawScene_ = false;
    std::string fieldName_, field_;
    UploadFields fields_;
    std::exception_ptr failure_;
};

}  // namespace

UploadFields readUpload(const httplib::Request& req, httplib::Response& res, const httplib::ContentReader& reader,
                        server::StagedUpload& upload, const UploadLimits& limits, server::RequestDigest& digest) {
    BodySink sink(upload, limits, digest);
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
    return std::move(sink.fields());
}

}  // namespace photon::api
