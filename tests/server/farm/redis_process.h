// Debian's redis-server as a child process for a test: on a free loopback port, nothing
// saved to disk, stopped (SIGTERM, then SIGKILL) when the object goes.
#pragma once
#include <sys/types.h>
#include <string>
#include "server/farm/redis_client.h"

namespace photon::test {

class RedisProcess {
public:
    // Starts it and waits until it answers PING; throws std::runtime_error if it cannot
    // (redis-server missing: scripts/install-deps.sh installs it). With `appendOnlyDir`, its
    // append-only file is kept there (and read again by restart()).
    explicit RedisProcess(std::string appendOnlyDir = "");
    ~RedisProcess();
    RedisProcess(const RedisProcess&) = delete;
    RedisProcess& operator=(const RedisProcess&) = delete;

    const farm::RedisAddress& address() const { return address_; }
    // Stops it (SIGTERM: it writes its data) and starts it again on the same port.
    void restart();

private:
    void start();
    void stop();

    pid_t pid_ = -1;
    farm::RedisAddress address_;
    std::string appendOnlyDir_;
};

}  // namespace photon::test

namespace photon::test {

// The photon-worker binary as a child process, stopped (SIGTERM, then SIGKILL) when the
// object goes; kill() is a crash.
class WorkerProcess {
public:
    WorkerProcess(const farm::RedisAddress& redis, const std::string& name, const std::string& binary,
                  const std::string& claimAfterSeconds = "30");
    ~WorkerProcess();
    WorkerProcess(const WorkerProcess&) = delete;
    WorkerProcess& operator=(const WorkerProcess&) = delete;
    void kill();
    pid_t pid() const { return pid_; }

private:
    pid_t pid_ = -1;
};

}  // namespace photon::test
