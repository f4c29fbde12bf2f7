#include "worker_pool.h"

namespace photon::server {

WorkerPool::WorkerPool(JobQueue& queue, JobRunner& runner, int count) {
    for (int i = 0; i < count; ++i)
        threads_.emplace_back([&queue, &runner] {
            while (std::optional<std::string> id = queue.pop()) runner.run(*id);  // run() never throws
        });
}

WorkerPool::~WorkerPool() { join(); }

void WorkerPool::join() {
    for (std::thread& t : threads_)
        if (t.joinable()) t.join();
}

}  // namespace photon::server
