// The render workers: each takes the next job from the queue and renders it. A render
// already spreads over all cores through TBB, so more than one worker only helps when
// jobs are small; the default is one.
#pragma once
#include <thread>
#include <vector>
#include "job_queue.h"
#include "job_runner.h"

namespace photon::server {

class WorkerPool {
public:
    WorkerPool(JobQueue& queue, JobRunner& runner, int count);
    ~WorkerPool();  // joins; close the queue (and interrupt renders) first
    WorkerPool(const WorkerPool&) = delete;
    WorkerPool& operator=(const WorkerPool&) = delete;

    void join();

private:
    std::vector<std::thread> threads_;
};

}  // namespace photon::server
