#include "redis_process.h"
#include <arpa/inet.h>
#include <fcntl.h>
#include <netinet/in.h>
#include <signal.h>
#include <sys/socket.h>
#include <sys/wait.h>
#include <unistd.h>
#include <chrono>
#include <stdexcept>
#include <string>
#include <thread>

namespace photon::test {
namespace {

// A port the kernel just handed out on 127.0.0.1, free again once the socket closes.
int freeLoopbackPort() {
    int fd = socket(AF_INET, SOCK_STREAM, 0);
    sockaddr_in a{};
    a.sin_family = AF_INET;
    a.sin_addr.s_addr = htonl(INADDR_LOOPBACK);
    socklen_t length = sizeof a;
    if (bind(fd, reinterpret_cast<sockaddr*>(&a), sizeof a) != 0 ||
        getsockname(fd, reinterpret_cast<sockaddr*>(&a), &length) != 0) {
        close(fd);
        throw std::runtime_error("no free loopback port");
    }
    close(fd);
    return ntohs(a.sin_port);
}

}  // namespace

RedisProcess::RedisProcess(std::string appendOnlyDir) : appendOnlyDir_(std::move(appendOnlyDir)) {
    address_ = farm::RedisAddress{"127.0.0.1", freeLoopbackPort()};
    start();
}

void RedisProcess::restart() {
    stop();
    start();
}

void RedisProcess::start() {
    const std::string port = std::to_string(address_.port);
    const bool appendOnly = !appendOnlyDir_.empty();
    pid_ = fork();
    if (pid_ == 0) {
        int null = open("/dev/null", O_WRONLY);
        dup2(null, STDOUT_FILENO);
        if (appendOnly)
            execlp("redis-server", "redis-server", "--port", port.c_str(), "--bind", "127.0.0.1", "--save", "",
                   "--appendonly", "yes", "--dir", appendOnlyDir_.c_str(), nullptr);
        else
            execlp("redis-server", "redis-server", "--port", port.c_str(), "--bind", "127.0.0.1", "--save", "",
                   "--appendonly", "no", nullptr);
        _exit(127);
    }
    const auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(10);
    while (std::chrono::steady_clock::now() < deadline) {
        int status = 0;
        if (waitpid(pid_, &status, WNOHANG) == pid_) {
            pid_ = -1;
            throw std::runtime_error("redis-server did not start (is it installed? scripts/install-deps.sh)");
        }
        try {
            farm::RedisClient client(address_, std::chrono::milliseconds(200));
            if (client.command({"PING"}).string == "PONG") return;
        } catch (const farm::RedisError&) {
        }
        std::this_thread::sleep_for(std::chrono::milliseconds(20));
    }
    kill(pid_, SIGKILL);
    waitpid(pid_, nullptr, 0);
    pid_ = -1;
    throw std::runtime_error("redis-server did not answer on port " + port);
}

RedisProcess::~RedisProcess() { stop(); }

void RedisProcess::stop() {
    if (pid_ <= 0) return;
    kill(pid_, SIGTERM);
    for (int i = 0; i < 200; ++i) {
        if (waitpid(pid_, nullptr, WNOHANG) == pid_) {
            pid_ = -1;
            return;
        }
        std::this_thread::sleep_for(std::chrono::milliseconds(10));
    }
    kill(pid_, SIGKILL);
    waitpid(pid_, nullptr, 0);
    pid_ = -1;
}

}  // namespace photon::test

namespace photon::test {

WorkerProcess::WorkerProcess(const farm::RedisAddress& redis, const std::string& name, const std::string& binary,
                             const std::string& claimAfterSeconds) {
    const std::string url = redis.url();
    pid_ = fork();
    if (pid_ == 0) {
        int null = open("/dev/null", O_WRONLY);
        dup2(null, STDOUT_FILENO);
        execl(binary.c_str(), binary.c_str(), "--redis", url.c_str(), "--name", name.c_str(), "--threads", "1",
              "--claim-after", claimAfterSeconds.c_str(), nullptr);
        _exit(127);
    }
}

WorkerProcess::~WorkerProcess() {
    if (pid_ <= 0) return;
    ::kill(pid_, SIGTERM);
    for (int i = 0; i < 500; ++i) {
        if (waitpid(pid_, nullptr, WNOHANG) == pid_) return;
        std::this_thread::sleep_for(std::chrono::milliseconds(10));
    }
    kill();
}

void WorkerProcess::kill() {
    if (pid_ <= 0) return;
    ::kill(pid_, SIGKILL);
    waitpid(pid_, nullptr, 0);
    pid_ = -1;
}

}  // namespace photon::test
