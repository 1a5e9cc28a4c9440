// A child oasis process with a time limit (commands/child_process.h): spawned in its own process
// group, its stdout and stderr read through one pipe, stopped whole at the limit.
#include "commands/child_process.h"

#include <fcntl.h>
#include <poll.h>
#include <signal.h>
#include <spawn.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cerrno>
#include <chrono>
#include <csignal>
#include <cstring>
#include <stdexcept>

#include "io/interruption.h"

namespace oasis {
namespace {

// Reads the child's output until it closes the pipe, or until `limit` has passed since its start
// (then true). poll() returns early on a signal, which the caller checks.
bool readUntilClosed(int fd, std::string& output, std::chrono::steady_clock::time_point deadline) {
    char buffer[4096];
    for (;;) {
        if (heldSignal()) return false;
        auto left = std::chrono::duration_cast<std::chrono::milliseconds>(deadline - std::chrono::steady_clock::now());
        if (left.count() <= 0) return true;
        pollfd readable{fd, POLLIN, 0};
        int ready = poll(&readable, 1, int(std::min<long long>(left.count() + 1, 60000)));
        if (ready <= 0) continue;  // EINTR (checked above) or a slice of the limit passed
        ssize_t n = read(fd, buffer, sizeof(buffer));
        if (n == 0 || (n < 0 && errno != EINTR && errno != EAGAIN)) return false;
        if (n > 0) output.append(buffer, size_t(n));
    }
}

// Stops the child's process group: SIGTERM, so that oasis there removes its temporaries, and after
// a short grace SIGKILL for whatever is still running (a hung driver). Reaps the child.
void stopChildGroup(pid_t pid, int& status) {
    kill(-pid, SIGTERM);
    auto graceEnd = std::chrono::steady_clock::now() + std::chrono::seconds(2);
    while (std::chrono::steady_clock::now() < graceEnd) {
        pid_t done = waitpid(pid, &status, WNOHANG);
        if (done == pid || (done < 0 && errno != EINTR)) {
            kill(-pid, SIGKILL);  // what the child started and left in its group
            return;
        }
        usleep(20000);
    }
    kill(-pid, SIGKILL);
    while (waitpid(pid, &status, 0) < 0 && errno == EINTR) {}
}

}  // namespace

ChildResult runChild(const std::vector<std::string>& arguments, const std::vector<std::string>& environment,
                     double limitSeconds) {
    int pipeEnds[2];
    if (pipe2(pipeEnds, O_CLOEXEC) != 0) throw std::runtime_error(std::string("pipe: ") + std::strerror(errno));
    posix_spawn_file_actions_t actions;
    posix_spawn_file_actions_init(&actions);
    posix_spawn_file_actions_adddup2(&actions, pipeEnds[1], STDOUT_FILENO);
    posix_spawn_file_actions_adddup2(&actions, pipeEnds[1], STDERR_FILENO);
    posix_spawnattr_t attributes;
    posix_spawnattr_init(&attributes);
    posix_spawnattr_setflags(&attributes, POSIX_SPAWN_SETPGROUP);
    posix_spawnattr_setpgroup(&attributes, 0);  // the child's own pid as its group
    std::vector<char*> argv, envp;
    for (const std::string& argument : arguments) argv.push_back(const_cast<char*>(argument.c_str()));
    for (const std::string& entry : environment) envp.push_back(const_cast<char*>(entry.c_str()));
    argv.push_back(nullptr);
    envp.push_back(nullptr);
    auto deadline = std::chrono::steady_clock::now() +
                    std::chrono::duration_cast<std::chrono::steady_clock::duration>(std::chrono::duration<double>(limitSeconds));
    pid_t pid = 0;
    ChildResult result;
    int spawnError = 0;
    {
        InterruptionHeld holding;  // Ctrl-C no longer reaches the child's group: stop it, then end
        spawnError = posix_spawn(&pid, "/proc/self/exe", &actions, &attributes, argv.data(), envp.data());
        posix_spawn_file_actions_destroy(&actions);
        posix_spawnattr_destroy(&attributes);
        close(pipeEnds[1]);
        if (spawnError == 0) {
            result.timedOut = readUntilClosed(pipeEnds[0], result.output, deadline);
            if (result.timedOut || heldSignal()) {
                stopChildGroup(pid, result.status);
                // What it said while it was stopped (oasis check's children name the pass they were in).
                readUntilClosed(pipeEnds[0], result.output, std::chrono::steady_clock::now() + std::chrono::seconds(1));
            }
            else while (waitpid(pid, &result.status, 0) < 0 && errno == EINTR) {}
        }
        close(pipeEnds[0]);
    }
    endForHeldSignal();  // end as the signal asked, now that the child is gone (removing its files)
    if (spawnError != 0)
        throw std::runtime_error(std::string("cannot start /proc/self/exe: ") + std::strerror(spawnError));
    return result;
}


}  // namespace oasis
