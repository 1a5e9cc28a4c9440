// The native window's loop: a GLFW window and its context (context/gl_context.h), events, one
// WindowApp frame per iteration, the swap. Nothing is drawn while the window is minimised.
#include "window/window_app.h"

#include <epoxy/gl.h>
#include <GLFW/glfw3.h>

#include <chrono>
#include <cstdio>

#include "context/gl_context.h"

namespace oasis {
namespace {

// Prints the window's state changes once each, so a log (and the window tests) can follow them.
void noteMinimised(window::WindowState& state, bool& minimised, bool now) {
    if (now == minimised) return;
    minimised = now;
    if (now) ++state.counts.minimised;
    std::printf("oasis: window %s\n", now ? "minimised: drawing paused" : "restored: drawing again");
    std::fflush(stdout);
}

}  // namespace

int runWindowApp(const Options& options) {
    try {
        WindowContext window(options.scene.width, options.scene.height, "oasis", maxGlVersionFor(options.scene));
        WindowApp app(options, window.window());
        window::WindowState& state = app.state();
        auto last = std::chrono::steady_clock::now();
        bool minimised = false;
        int lastWidth = 0, lastHeight = 0;
        while (!glfwWindowShouldClose(window.window())) {
            glfwPollEvents();
            int width = 0, height = 0;
            noteMinimised(state, minimised, window.minimised(width, height));
            if (minimised) {  // nothing to draw into: wait for the next event
                glfwWaitEvents();
                last = std::chrono::steady_clock::now();
                continue;
            }
            if (lastWidth && (width != lastWidth || height != lastHeight)) ++state.counts.resizes;
            lastWidth = width;
            lastHeight = height;
            auto now = std::chrono::steady_clock::now();
            float seconds = std::chrono::duration<float>(now - last).count();
            last = now;
            app.frame(width, height, seconds);
            glfwSwapBuffers(window.window());
            glFinish();  // the loop's time holds the frame's work, not only its submission
            app.finishFrame();
        }
        app.printClosingCounts();
        return 0;
    } catch (const std::exception& error) {
        std::fprintf(stderr, "oasis: %s\n", error.what());
        return 1;
    }
}

}  // namespace oasis
