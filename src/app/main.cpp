// oasis's entry point: parse the command line, then run the window or a headless command.
#include <csignal>
#include <cstdio>
#include <string>
#include <vector>

#include "cli/options.h"
#include "commands/caps_command.h"
#include "commands/bench.h"
#include "commands/driver_compare.h"
#include "commands/headless_commands.h"
#include "commands/window_app.h"
#include "context/gl_context.h"
#include "gl/frame_capture.h"

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
        case Command::Window: return runWindowApp(options);
        case Command::Default:
            // The window has no OpenGL ES context: --api gles runs the main job headless.
            return WindowContext::displayAvailable() && options.scene.api != gl::Api::Gles ? runWindowApp(options)
                                                                                           : runMainJob(options);
    }
    return 2;
}
}  // namespace

int main(int argc, char** argv) {
    using namespace oasis;
    std::setvbuf(stdout, nullptr, _IOLBF, 0);  // progress reaches logs even if the window is killed
    // Past a file-size limit (ulimit -f) a write should fail with EFBIG and be reported as a file
    // that could not be written (exit 1), not kill the process with SIGXFSZ.
    std::signal(SIGXFSZ, SIG_IGN);
    ParseResult parsed = parseCommandLine(std::vector<std::string>(argv + 1, argv + argc));
    if (!parsed.ok) {
        std::fprintf(stderr, "oasis: %s\n", parsed.error.c_str());
        return 2;
    }
    for (const std::string& note : parsed.notes) std::fprintf(stderr, "oasis: %s\n", note.c_str());
    const Options& options = parsed.options;
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
        for (const std::string& path : captures) std::printf("oasis: RenderDoc capture: %s\n", path.c_str());
        if (captures.empty() && code == 0) {
            std::fprintf(stderr, "oasis: --capture: RenderDoc wrote no capture\n");
            return 1;
        }
    }
    return code;
}
