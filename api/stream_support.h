// Shared by the long-lived streaming routes (events, image stream): the wait granularity
// and a guard that keeps exceptions out of httplib's writer loop, which runs a content
// provider outside any handler's try block (an escaping exception would end the process).
#pragma once
#include <httplib.h>
#include <spdlog/spdlog.h>
#include <atomic>
#include <chrono>
#include <condition_variable>
#include <mutex>
#include <memory>
#include <exception>

namespace photon::api {

// How long a stream waits for news before re-checking its connection and the server state.
constexpr std::chrono::milliseconds kStreamPoll{1000};

// Each open stream holds one HTTP thread for as long as it lasts. Capping them keeps threads
// free for ordinary requests: beyond the cap (--max-streams) a stream request gets 503 with
// Retry-After.
class StreamSlots {
public:
    explicit StreamSlots(int max) : max_(max) {}
    class Slot {
    public:
        explicit Slot(StreamSlots& owner) : owner_(owner) {}
        ~Slot() { --owner_.used_; }
        Slot(const Slot&) = delete;
        Slot& operator=(const Slot&) = delete;

    private:
        StreamSlots& owner_;
    };
    // Held until the returned handle (captured by the stream's provider) is destroyed;
    // throws ServiceError (Unavailable) when every slot is taken.
    std::shared_ptr<Slot> acquire();

    // Streams whose responses are still being written, to the last chunk. A stream counts
    // from this call until httplib calls the returned releaser, once the response is out
    // (pass it to set_chunked_content_provider).
    httplib::ContentProviderResourceReleaser countWriting();
    // Waits until no stream is being written, at most `timeout`; false if some still are.
    // Stopping the HTTP server cuts responses in flight, so the process stops it only once
    // the streams it has told to end have ended.
    bool waitUntilWritten(std::chrono::milliseconds timeout);

private:
    std::atomic<int> used_{0};
    const int max_;
    std::mutex writingMutex_;
    std::condition_variable written_;
    int writing_ = 0;
};

template <typename Step>
httplib::ContentProviderWithoutLength guardedProvider(Step step) {
    return [step = std::move(step)](size_t, httplib::DataSink& sink) mutable -> bool {
        try {
            return step(sink);
        } catch (const std::exception& e) {
            spdlog::warn("stream ended by error: {}", e.what());
        } catch (...) {
        }
        return false;  // ends the response; the client sees the connection close
    };
}

// Ends a stream. Its slot is freed before the final chunk goes out: httplib destroys the
// provider (and the slot it holds) only after the response is written, so a client that has
// seen the end could otherwise be refused a new stream for a moment.
inline void endStream(httplib::DataSink& sink, std::shared_ptr<StreamSlots::Slot>& slot) {
    slot.reset();
    sink.done();
}

inline bool writeAll(httplib::DataSink& sink, const std::string& bytes) {
    return bytes.empty() || sink.write(bytes.data(), bytes.size());
}

}  // namespace photon::api
