// An OpenGL context made current on this thread: headless through EGL (no display needed) or a
// GLFW window. Both ask for the newest core profile the driver gives, down to 3.3, or at most
// the version asked for (--force gl33 makes a 3.3 core context on any driver). --api gles makes
// the headless context an OpenGL ES 3.x one instead (EGL_OPENGL_ES_API: 3.2 down to 3.0).
#pragma once
#include <memory>
#include <string>

#include "context/epoxy_glx_probe.h"

struct GLFWwindow;

namespace oasis {

struct ContextInfo {
    std::string version, vendor, renderer, glslVersion;
    int major = 0, minor = 0;
    std::string summary() const;  // "4.5 (Core Profile) Mesa 22.3.6 on llvmpipe (...)"
};
ContextInfo queryContextInfo();

// Routes GL debug output (errors and warnings; notifications are dropped) to stderr.
void installDebugOutput();

// --gl-debug: contexts made after this deliver debug output synchronously (inside the call that
// caused it, so a debugger's stack shows the call), stop at the first GL error with the message
// and the debug group path it happened in (gl::debugGroupPath), and count performance warnings
// instead of printing them.
void setGlDebugMode(bool on);
bool glDebugMode();
struct GlDebugCounts {
    int errors = 0, performanceWarnings = 0, otherWarnings = 0;
};
GlDebugCounts glDebugCounts();
// "oasis: --gl-debug: 0 GL errors, 3 performance warnings (...), 0 other warnings": printed at the end.
std::string glDebugSummary();
// What --gl-debug does at the first error, after printing it: by default a SIGTRAP where a
// debugger is attached (it stops in the GL call's stack), else exit 1. Tests record instead.
using GlErrorStop = void (*)(const std::string& message);
void setGlErrorStop(GlErrorStop stop);

// The newest core version a context may have: {4, 6} by default, {3, 3} with --force gl33; `es`:
// an OpenGL ES 3.x context (--api gles; the version fields are then not used: the newest ES 3.x).
struct MaxGlVersion {
    int major = 4, minor = 6;
    bool es = false;
};

// Which EGL display the last HeadlessContext opened, and why: "surfaceless (...)" on Mesa, or
// "EGL device 1 of 2 (EGL_EXT_platform_device), EGL has no surfaceless platform" elsewhere.
std::string headlessDisplayDescription();

class HeadlessContext {
public:
    // Throws std::runtime_error naming what is missing when no context can be made.
    explicit HeadlessContext(MaxGlVersion max = {});
    ~HeadlessContext();
    HeadlessContext(const HeadlessContext&) = delete;
    HeadlessContext& operator=(const HeadlessContext&) = delete;

private:
    void makeEsContext(void* display);
    // First, so that libepoxy's first lookups (eglGetPlatformDisplayEXT on) already see it, and
    // last to go, after the context.
    NoGlxContextForEpoxy noGlx_;
    void* display_ = nullptr;
    void* context_ = nullptr;
};

class WindowContext {
public:
    // Throws std::runtime_error (with GLFW's reason) when no window can be opened.
    WindowContext(int width, int height, const std::string& title, MaxGlVersion max = {});
    ~WindowContext();
    WindowContext(const WindowContext&) = delete;
    WindowContext& operator=(const WindowContext&) = delete;
    GLFWwindow* window() const { return window_; }
    // Whether there is nothing to draw into: the window is iconified (X11 keeps its size then) or
    // its framebuffer is empty (other systems' minimise). `width` and `height` get the size.
    bool minimised(int& width, int& height) const;

    static bool displayAvailable();  // a display server to open a window on

private:
    GLFWwindow* window_ = nullptr;
};

}  // namespace oasis
