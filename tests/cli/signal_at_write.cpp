// Sends a signal to a command at the moment it starts writing a file: when a name containing
// ".tmp-" (oasis's temporaries, io/file_output.h) is created in a watched directory or in a
// directory made inside one (compare --driver's staging directory). With --after SECONDS instead, at
// that time after the start. Prints how the command ended; exit 0 if the signal ended it, 3 if the
// command ended first (no write was seen: not a failure of oasis, the caller decides), 4 if the
// signal was sent and the command still exited 0 (it came too late to matter: after the work, e.g.
// during a sanitizer's exit-time leak check, which runs with signals blocked; the caller decides),
// 1 otherwise.
//
// usage: oasis_signal_at_write SIGNAL (--at-temporary | --after SECONDS) DIR... -- COMMAND ARGS...
#include <signal.h>
#include <sys/inotify.h>
#include <sys/wait.h>
#include <poll.h>
#include <unistd.h>

#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <map>
#include <string>
#include <vector>

namespace {

int signalNumber(const std::string& name) {
    if (name == "INT") return SIGINT;
    if (name == "TERM") return SIGTERM;
    if (name == "HUP") return SIGHUP;
    return 0;
}

// Watches `dir` for new entries; remembers it for reporting.
void watch(int inotify, const std::string& dir, std::map<int, std::string>& watched) {
    int wd = inotify_add_watch(inotify, dir.c_str(), IN_CREATE | IN_ONLYDIR);
    if (wd >= 0) watched[wd] = dir;
}

}  // namespace

int main(int argc, char** argv) {
    std::vector<std::string> args(argv + 1, argv + argc);
    size_t separator = 0;
    while (separator < args.size() && args[separator] != "--") ++separator;
    if (args.size() < 4 || separator + 1 >= args.size() || !signalNumber(args[0])) {
        std::fprintf(stderr, "usage: oasis_signal_at_write INT|TERM|HUP (--at-temporary | --after S) DIR... -- CMD...\n");
        return 2;
    }
    int signal = signalNumber(args[0]);
    bool atTemporary = args[1] == "--at-temporary";
    double after = atTemporary ? 0.0 : std::atof(args[2].c_str());
    size_t firstDir = atTemporary ? 2 : 3;
    int inotify = inotify_init1(IN_NONBLOCK | IN_CLOEXEC);
    std::map<int, std::string> watched;
    for (size_t k = firstDir; k < separator; ++k) watch(inotify, args[k], watched);

    pid_t pid = fork();
    if (pid == 0) {
        std::vector<char*> command;
        for (size_t k = separator + 1; k < args.size(); ++k) command.push_back(args[k].data());
        command.push_back(nullptr);
        execvp(command[0], command.data());
        _exit(127);
    }
    auto start = std::chrono::steady_clock::now();
    bool sent = false;
    std::string sentAt;
    int status = 0;
    for (;;) {
        pid_t done = waitpid(pid, &status, WNOHANG);
        if (done == pid) break;
        if (!sent && !atTemporary &&
            std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count() >= after) {
            kill(pid, signal);
            sent = true;
            sentAt = "after " + args[2] + " s";
        }
        pollfd ready{inotify, POLLIN, 0};
        if (poll(&ready, 1, 2) <= 0) continue;
        alignas(inotify_event) char buffer[8192];
        ssize_t n = read(inotify, buffer, sizeof(buffer));
        for (ssize_t at = 0; at < n;) {
            const inotify_event* event = reinterpret_cast<const inotify_event*>(buffer + at);
            at += ssize_t(sizeof(inotify_event) + event->len);
            std::string name = event->len ? event->name : "";
            if (event->mask & IN_ISDIR) {
                watch(inotify, watched[event->wd] + "/" + name, watched);
                continue;
            }
            if (atTemporary && !sent && name.find(".tmp-") != std::string::npos) {
                kill(pid, signal);
                sent = true;
                sentAt = "at " + watched[event->wd] + "/" + name;
            }
        }
    }
    if (WIFSIGNALED(status)) {
        std::printf("signal_at_write: %s sent %s; the command ended by signal %d\n", args[0].c_str(), sentAt.c_str(),
                    WTERMSIG(status));
        return sent && WTERMSIG(status) == signal ? 0 : 1;
    }
    std::printf("signal_at_write: %s %s; the command exited with %d\n", args[0].c_str(),
                sent ? ("sent " + sentAt).c_str() : "not sent (no write seen before the end)", WEXITSTATUS(status));
    if (!sent) return 3;
    return WIFEXITED(status) && WEXITSTATUS(status) == 0 ? 4 : 1;
}
