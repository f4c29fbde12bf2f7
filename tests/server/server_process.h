// Runs the photon-server binary as a child process for a test: starts it with the given
// arguments, reads the "listening on" line for the port, and stops it (SIGTERM, then
// SIGKILL if it does not exit in time).
#pragma once
#include <sys/types.h>
#include <string>
#include <vector>

namespace photon::test {

class ServerProcess {
public:
    ServerProcess() = default;
    ~ServerProcess() { stop(); }
    ServerProcess(const ServerProcess&) = delete;
    ServerProcess& operator=(const ServerProcess&) = delete;

    // Starts `PHOTON_SERVER_BINARY --host 127.0.0.1 --port 0 <args>` and waits for its
    // start line. Throws std::runtime_error if it does not print one within a few seconds.
    void start(const std::vector<std::string>& args);
    // SIGTERM and wait; returns the exit status (or -1 if it had to be killed).
    int stop();
    // SIGKILL and wait: a crash, with no chance to save anything.
    void kill();
    int port() const { return port_; }
    pid_t pid() const { return pid_; }
    bool running() const { return pid_ > 0; }

private:
    pid_t pid_ = -1;
    int port_ = 0;
};

// Runs the binary with `args` to completion and returns what it printed (stdout and stderr).
std::string runServerBinary(const std::vector<std::string>& args);

}  // namespace photon::test
