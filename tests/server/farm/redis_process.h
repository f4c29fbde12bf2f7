// Debian's redis-server as a child process for a test: on a free loopback port, nothing
// saved to disk, stopped (SIGTERM, then SIGKILL) when the object goes.
#pragma once
#include <sys/types.h>
#include "server/farm/redis_client.h"

namespace photon::test {

class RedisProcess {
public:
    // Starts it and waits until it answers PING; throws std::runtime_error if it cannot
    // (redis-server missing: scripts/install-deps.sh installs it).
    RedisProcess();
    ~RedisProcess();
    RedisProcess(const RedisProcess&) = delete;
    RedisProcess& operator=(const RedisProcess&) = delete;

    const farm::RedisAddress& address() const { return address_; }

private:
    pid_t pid_ = -1;
    farm::RedisAddress address_;
};

}  // namespace photon::test
