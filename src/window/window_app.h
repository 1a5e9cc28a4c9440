// The interactive window: the renderer in a GLFW window with a Dear ImGui panel, keys and the
// inspector. WindowApp is one window's app, whose frame() a loop calls once per iteration: the
// native loop (runWindowApp) and the browser's main loop (src/web/web_main.cpp) run the same one.
#pragma once
#include <chrono>

#include "cli/options.h"
#include "commands/session.h"
#include "window/window_state.h"

struct GLFWwindow;

namespace oasis {

class WindowApp {
public:
    // Starts on `window`, whose GL context is current: the session of `options`, the panel's
    // ImGui and the keys. Throws std::runtime_error when the session cannot start.
    WindowApp(const Options& options, GLFWwindow* window);
    ~WindowApp();  // the panel's GL objects and side B's renderer go while the context lives
    WindowApp(const WindowApp&) = delete;
    WindowApp& operator=(const WindowApp&) = delete;

    // One loop iteration into the window's framebuffer of `width` x `height`, `seconds` after the
    // last: the clock and the camera, the panel, the chosen frame (grey while a switch cannot
    // build), the panel over it. The caller shows it (swaps) and then calls finishFrame().
    void frame(int width, int height, float seconds);
    // After the frame was shown: the iteration's wall time (by what it showed) and a capture F9
    // asked for.
    void finishFrame();
    // "window closed: N frames drawn, ..." and the loop's medians (the window tests read them).
    void printClosingCounts() const;

    RenderSession& session() { return session_; }
    window::WindowState& state() { return state_; }

private:
    GLFWwindow* window_;
    RenderSession session_;
    window::WindowState state_;
    bool esBackend_ = false;  // the panel's GL backend: desktop, or ES (--api gles, the browser)
    std::chrono::steady_clock::time_point drawStart_;
};

// The native window's loop around WindowApp. Returns the exit code: 0 on a normal close, 1 when
// no window or context could be had.
int runWindowApp(const Options& options);

}  // namespace oasis
