// How many threads the engine's parallel loops may use, for as long as the object lives
// (the process's default is one per core).
#pragma once
#include <cstddef>
#include <memory>

namespace photon {

class ThreadLimit {
public:
    explicit ThreadLimit(size_t threads);
    ~ThreadLimit();
    ThreadLimit(const ThreadLimit&) = delete;
    ThreadLimit& operator=(const ThreadLimit&) = delete;

    // The threads the engine's parallel loops may use now.
    static size_t active();

private:
    struct Control;
    std::unique_ptr<Control> control_;
};

}  // namespace photon
