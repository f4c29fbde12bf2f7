// GET /api/v1/events: Server-Sent Events of every job's changes, for a list that stays
// current without polling: `changed` (submitted, started, priority), the job's own events
// (`progress`, `done`, `failed`, `cancelled`) with the job record, `deleted` with its id.
// It starts with `ready` (connect, then list the jobs: nothing is missed between the two);
// `reset` says changes were dropped for a client too far behind (list again). Event ids
// number the changes, so a reconnecting EventSource resumes with Last-Event-ID.
//
// GET /api/v1/jobs/{id}/events: Server-Sent Events. On connect the current state (a
// `progress` event, or the final event if the job has finished); then one `progress` per
// finished pass and a final `done`, `failed` or `cancelled`, after which the stream ends.
// Event ids are the job's event numbers, so a reconnecting EventSource resumes with
// Last-Event-ID instead of missing passes.
#include <httplib.h>
#include <memory>
#include <utility>
#include "api/errors.h"
#include "api/handlers.h"
#include "api/job_json.h"
#include "api/params.h"
#include "api/stream_support.h"

namespace photon::api {

namespace {

// A comment line now and then: proxies keep the connection, and a gone client is noticed
// because the write fails.
constexpr int kKeepAlivePolls = 15;

std::optional<uint64_t> lastEventId(const httplib::Request& req) {
    return parseWhole<uint64_t>(req.get_header_value("Last-Event-ID"));
}

std::string formatEvent(server::EventType type, uint64_t seq, const server::JobRecord& job) {
    return std::string("event: ") + server::toString(type) + "\nid: " + std::to_string(seq) +
           "\ndata: " + toJson(job).dump(-1, ' ', false, nlohmann::json::error_handler_t::replace) + "\n\n";
}

struct EventStream {
    std::shared_ptr<StreamSlots::Slot> slot;
    server::EventHub& hub;
    std::string id;
    std::optional<server::EventHub::Snapshot> initial;  // sent first unless resuming
    uint64_t afterSeq = 0;
    int idlePolls = 0;

    bool step(httplib::DataSink& sink) {
        if (initial) {
            server::EventType type = server::eventTypeFor(initial->job.status);
            bool ok = writeAll(sink, formatEvent(type, initial->seq, initial->job));
            initial.reset();
            if (ok && type != server::EventType::Progress) endStream(sink, slot);
            return ok;
        }
        server::EventHub::Wait wait = hub.waitAfter(id, afterSeq, kStreamPoll);
        if (wait.closed) {
            endStream(sink, slot);
            return true;
        }
        if (wait.events.empty()) {
            if (++idlePolls % kKeepAlivePolls != 0) return true;
            return writeAll(sink, ": keep-alive\n\n");
        }
        idlePolls = 0;
        for (const server::JobEvent& e : wait.events) {
            if (!writeAll(sink, formatEvent(e.type, e.seq, e.job))) return false;
            afterSeq = e.seq;
            if (e.type != server::EventType::Progress) {
                endStream(sink, slot);
                break;
            }
        }
        return true;
    }
};

std::string formatServiceEvent(const server::ServiceEvent& e) {
    nlohmann::json data = e.kind == server::ServiceEvent::Kind::Deleted ? nlohmann::json{{"id", e.job.id}} : toJson(e.job);
    const char* name = e.kind == server::ServiceEvent::Kind::Deleted ? "deleted"
                       : e.jobEvent                                   ? server::toString(*e.jobEvent)
                                                                      : "changed";
    return std::string("event: ") + name + "\nid: " + std::to_string(e.seq) +
           "\ndata: " + data.dump(-1, ' ', false, nlohmann::json::error_handler_t::replace) + "\n\n";
}

struct ServiceStream {
    std::shared_ptr<StreamSlots::Slot> slot;
    server::EventHub& hub;
    uint64_t afterSeq = 0;
    bool ready = true;  // "ready" is still to be sent
    int idlePolls = 0;

    bool step(httplib::DataSink& sink) {
        if (std::exchange(ready, false))
            return writeAll(sink, "event: ready\nid: " + std::to_string(afterSeq) + "\ndata: {}\n\n");
        server::EventHub::ServiceWait wait = hub.waitAnyAfter(afterSeq, kStreamPoll);
        if (wait.closed) {
            endStream(sink, slot);
            return true;
        }
        if (wait.missed) {
            afterSeq = wait.seq;
            return writeAll(sink, "event: reset\nid: " + std::to_string(wait.seq) + "\ndata: {}\n\n");
        }
        if (wait.events.empty()) {
            if (++idlePolls % kKeepAlivePolls != 0) return true;
            return writeAll(sink, ": keep-alive\n\n");
        }
        idlePolls = 0;
        for (const server::ServiceEvent& e : wait.events) {
            if (!writeAll(sink, formatServiceEvent(e))) return false;
            afterSeq = e.seq;
        }
        return true;
    }
};

}  // namespace

void serviceEvents(RouteContext& ctx, const httplib::Request& req, httplib::Response& res) {
    server::EventHub& hub = ctx.service.events();
    uint64_t now = hub.serviceSeq();
    auto stream = std::make_shared<ServiceStream>(ServiceStream{ctx.streams.acquire(), hub, now});
    // Resuming: from the client's last change (a number from before a restart is of no use).
    if (std::optional<uint64_t> last = lastEventId(req); last && *last <= now) {
        stream->afterSeq = *last;
        stream->ready = false;
    }
    res.set_header("Cache-Control", "no-cache");
    res.set_header("X-Accel-Buffering", "no");
    res.set_chunked_content_provider("text/event-stream",
                                     guardedProvider([stream](httplib::DataSink& sink) { return stream->step(sink); }),
                                     ctx.streams.countWriting());
}

void jobEvents(RouteContext& ctx, const httplib::Request& req, httplib::Response& res) {
    std::string id = pathId(req);
    std::optional<server::EventHub::Snapshot> snap = ctx.service.events().current(id);
    if (!snap) throw server::ServiceError(server::ErrorKind::NotFound, "no job " + id);
    std::optional<uint64_t> last = lastEventId(req);
    bool finished = server::isFinished(snap->job.status);
    if (last && finished && snap->seq > 0 && *last >= snap->seq) {
        res.status = 204;  // the client has seen the end: tells EventSource not to reconnect
        return;
    }
    auto stream =
        std::make_shared<EventStream>(EventStream{ctx.streams.acquire(), ctx.service.events(), id, snap, snap->seq});
    // Resume only if every event after the client's last one is still in the log.
    if (last && *last < snap->seq && *last + 1 >= snap->oldestSeq) {
        stream->initial.reset();
        stream->afterSeq = *last;
    }
    res.set_header("Cache-Control", "no-cache");
    res.set_header("X-Accel-Buffering", "no");  // nginx and friends: do not buffer the stream
    res.set_chunked_content_provider("text/event-stream",
                                     guardedProvider([stream](httplib::DataSink& sink) { return stream->step(sink); }),
                                     ctx.streams.countWriting());
}

}  // namespace photon::api
