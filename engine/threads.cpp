#include <photon/threads.h>
#include <tbb/global_control.h>

namespace photon {

struct ThreadLimit::Control {
    tbb::global_control control;
};

ThreadLimit::ThreadLimit(size_t threads)
    : control_(new Control{tbb::global_control(tbb::global_control::max_allowed_parallelism, threads)}) {}

ThreadLimit::~ThreadLimit() = default;

size_t ThreadLimit::active() { return tbb::global_control::active_value(tbb::global_control::max_allowed_parallelism); }

}  // namespace photon
