// oasis's entry point: parse the command line, then run the window or a headless command.
#include <fcntl.h>
#include <unistd.h>

#include <cerrno>
#include <csignal>
#include <cstdio>
#include <cstring>
#include <string>
#include <vector>

#include "cli/options.h"
#include "commands/caps_command.h"
#include "check/check.h"
#include "bench/bench.h"
#include "commands/driver_compare.h"
#include "commands/headless_commands.h"
#include "window/window_app.h"
#include "context/gl_context.h"
#include "context/runtime_dir.h"
#include "gl/frame_capture.h"
#include "io/interruption.h"
#include "io/printable_text.h"

namespace {
int runCommand(const oasis::Options& options) {
    using namespace oasis;
    switch (options.command) {
        case Command::Render: return runRenderCommand(options);
        case Command::Compare:
            return options.comparesDrivers() ? runDriverCompare(options) : runCompareCommand(options);
        case Command::Caps: return runCapsCommand(options);
        case Command::Bench: return runBenchCommand(options);
        case Command::Probe: return runProbeCommand(options);
        case Command::Check: return runCheckCommand(options);
        case Command::Window: return runWindowApp(options);
        case Command::Default:
            return WindowContext::displayAvailable() ? runWindowApp(options) : runMainJob(options);
    }
    return 2;
}

// A closed standard output or error would hand its descriptor number to the next file oasis opens,
// and the report would be written into that file. Each closed one gets /dev/null opened read-only
// in its place: writes to it fail (EBADF), so a lost stdout is still reported as one.
void keepStandardDescriptorsTaken() {
    for (int fd : {STDOUT_FILENO, STDERR_FILENO}) {
        if (fcntl(fd, F_GETFD) != -1 || errno != EBADF) continue;
        int placeholder = open("/dev/null", O_RDONLY);
        if (placeholder >= 0 && placeholder != fd) {
            dup2(placeholder, fd);
            close(placeholder);
        }
    }
}

// What oasis printed must have reached standard output: a full disk or a closed pipe is a failure
// (exit 1), not a success with the output lost.
int checkStandardOutput(int code) {
    if (std::fflush(stdout) == 0 && !std::ferror(stdout)) return code;
    // stdio keeps no reason for an earlier failed write (errno has moved on since): one more byte
    // written straight to the descriptor fails again for the same reason (a full device, a closed
    // pipe or descriptor), and the end of a line is all it can add where the failure has passed.
    ssize_t written = write(STDOUT_FILENO, "\n", 1);
    std::string why = written < 0 ? std::strerror(errno) : "a write failed (the reason has passed)";
    std::fprintf(stderr, "oasis: cannot write stdout: %s\n", why.c_str());
    return code == 0 ? 1 : code;
}

// `oasis serve [--dir DIR] [--port N] [--host H]` is oasis-serve (src/serve/, built beside oasis): the web
// build's page server, a program of its own so that serving needs no GL. Returns only when it
// cannot be started.
int runServe(char** argv) {
    char self[4096];
    ssize_t length = readlink("/proc/self/exe", self, sizeof(self) - 1);
    std::string server = "oasis-serve";
    if (length > 0) {
        std::string path(self, size_t(length));
        server = path.substr(0, path.rfind('/') + 1) + "oasis-serve";
    }
    argv[1] = const_cast<char*>(server.c_str());
    execv(server.c_str(), argv + 1);
    std::fprintf(stderr, "oasis: serve: cannot run %s (%s); it is built beside oasis (docs/web.md)\n", server.c_str(),
                 std::strerror(errno));
    return 1;
}

int runParsed(const oasis::Options& options) {
    using namespace oasis;
    if (options.help) {
        std::fputs(usage(options.command).c_str(), stdout);
        return 0;
    }
    std::string why;
    if (options.capture && !gl::renderDocLoaded(&why)) {  // said before anything is rendered or written
        std::fprintf(stderr, "oasis: --capture: %s\n", why.c_str());
        return 1;
    }
    setGlDebugMode(options.glDebug);
    int code = runCommand(options);
    if (options.glDebug) std::fprintf(stderr, "oasis: %s\n", glDebugSummary().c_str());
    if (options.capture) {
        std::vector<std::string> captures = gl::renderDocCaptures();
        for (const std::string& path : captures) std::fprintf(stderr, "oasis: RenderDoc capture: %s\n", path.c_str());  // a log line
        if (captures.empty() && code == 0) {
            std::fprintf(stderr, "oasis: --capture: RenderDoc wrote no capture\n");
            return 1;
        }
    }
    return code;
}
}  // namespace

int main(int argc, char** argv) {
    using namespace oasis;
    keepStandardDescriptorsTaken();
    installInterruptionCleanup();
    std::setvbuf(stdout, nullptr, _IOLBF, 0);  // progress reaches logs even if the window is killed
    // Past a file-size limit (ulimit -f) a write should fail with EFBIG and be reported as a file
    // that could not be written (exit 1), not kill the process with SIGXFSZ.
    std::signal(SIGXFSZ, SIG_IGN);
    if (argc > 1 && std::string(argv[1]) == "serve") return runServe(argv);
    ParseResult parsed = parseCommandLine(std::vector<std::string>(argv + 1, argv + argc));
    if (!parsed.ok) {
        // The arguments are echoed in it (a file name may hold any byte): escaped, never raw.
        std::fprintf(stderr, "oasis: %s\n", printableText(parsed.error).c_str());
        return 2;
    }
    for (const std::string& note : parsed.notes) std::fprintf(stderr, "oasis: %s\n", printableText(note).c_str());
    PrivateRuntimeDir runtimeDir;  // before any context: zink's WSI reads XDG_RUNTIME_DIR
    return checkStandardOutput(runParsed(parsed.options));
}
