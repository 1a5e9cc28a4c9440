// EGL headless (surfaceless, or an EGL device) and GLFW contexts, context facts and debug output.
#include "context/gl_context.h"

#include <epoxy/egl.h>
#include <epoxy/gl.h>
#include <GLFW/glfw3.h>

#include "gl/objects.h"

#include <csignal>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <iterator>
#include <map>
#include <set>
#include <string>
#include <stdexcept>

namespace oasis {
namespace {

const std::pair<int, int> kVersionsToTry[] = {{4, 6}, {4, 5}, {4, 3}, {4, 2}, {4, 1}, {3, 3}};

bool allowed(MaxGlVersion max, int major, int minor) {
    return major < max.major || (major == max.major && minor <= max.minor);
}

// Mesa gives the newest core version whatever is asked for (a core context may be newer than
// requested); below 4.x its version overrides make the context really report the cap. Set before
// the driver is loaded, and never over a value the user set. Other drivers are capped by
// gl::Capabilities instead.
void capMesaVersion(MaxGlVersion max) {
    if (max.major >= 4) return;
    std::string gl = std::to_string(max.major) + "." + std::to_string(max.minor);
    std::string glsl = std::to_string(max.major * 100 + max.minor * 10);
    setenv("MESA_GL_VERSION_OVERRIDE", gl.c_str(), 0);
    setenv("MESA_GLSL_VERSION_OVERRIDE", glsl.c_str(), 0);
}

std::string glString(GLenum name) {
    const GLubyte* text = glGetString(name);
    return text ? reinterpret_cast<const char*>(text) : "";
}

bool gGlDebug = false;
GlDebugCounts gCounts;
std::map<GLuint, int> gPerformanceById;  // --gl-debug's performance warnings, by message id

bool debuggerAttached() {
    std::ifstream status("/proc/self/status");
    for (std::string line; std::getline(status, line);)
        if (line.rfind("TracerPid:", 0) == 0) return std::atoi(line.c_str() + 10) != 0;
    return false;
}

void stopAtError(const std::string&) {
    std::fflush(nullptr);
    if (debuggerAttached()) {
        std::raise(SIGTRAP);  // the debugger stops here, inside the GL call that failed; continue resumes
        return;
    }
    std::fprintf(stderr, "oasis: --gl-debug: stopped at the first GL error (under gdb it stops in the call)\n");
    std::_Exit(1);
}
GlErrorStop gStop = stopAtError;

// --gl-debug: errors stop the program, with the debug group path (synchronous output: the
// groups open now are those around the failing call); performance warnings are counted.
bool handleGlDebug(GLenum type, GLuint id, const GLchar* message) {
    if (!gGlDebug) return false;
    if (type == GL_DEBUG_TYPE_ERROR) {
        ++gCounts.errors;
        std::string text = "GL error in " + gl::debugGroupPath() + ": " + message;
        std::fprintf(stderr, "oasis: %s\n", text.c_str());
        gStop(text);
        return true;
    }
    if (type == GL_DEBUG_TYPE_PERFORMANCE) {
        ++gCounts.performanceWarnings;
        ++gPerformanceById[id];
        return true;
    }
    ++gCounts.otherWarnings;
    return false;
}

void GLAPIENTRY printDebugMessage(GLenum source, GLenum type, GLuint id, GLenum severity, GLsizei, const GLchar* message,
                                  const void*) {
    if (severity == GL_DEBUG_SEVERITY_NOTIFICATION) return;
    if (handleGlDebug(type, id, message)) return;
    // A shader that does not compile is reported by the shader library, with file:line.
    if (source == GL_DEBUG_SOURCE_SHADER_COMPILER) return;
    static std::set<GLuint> seen;  // each message once: a per-frame warning must not flood the console
    if (!seen.insert(id).second) return;
    std::fprintf(stderr, "oasis: GL %s: %s\n", type == GL_DEBUG_TYPE_ERROR ? "error" : "debug", message);
}

std::string glfwLastError() {
    const char* description = nullptr;
    glfwGetError(&description);
    return description ? description : "unknown GLFW error";
}

}  // namespace

std::string ContextInfo::summary() const { return version + " on " + renderer; }

ContextInfo queryContextInfo() {
    ContextInfo info;
    info.version = glString(GL_VERSION);
    info.vendor = glString(GL_VENDOR);
    info.renderer = glString(GL_RENDERER);
    info.glslVersion = glString(GL_SHADING_LANGUAGE_VERSION);
    glGetIntegerv(GL_MAJOR_VERSION, &info.major);
    glGetIntegerv(GL_MINOR_VERSION, &info.minor);
    return info;
}

void installDebugOutput() {
    bool es32 = !epoxy_is_desktop_gl() && epoxy_gl_version() >= 32;
    if (epoxy_gl_version() < 43 && !es32 && !epoxy_has_gl_extension("GL_KHR_debug")) {
        if (gGlDebug) std::fprintf(stderr, "oasis: --gl-debug: this context has no KHR_debug: no debug output\n");
        return;
    }
    glEnable(GL_DEBUG_OUTPUT);
    if (gGlDebug) {
        glEnable(GL_DEBUG_OUTPUT_SYNCHRONOUS);
        glDebugMessageControl(GL_DONT_CARE, GL_DONT_CARE, GL_DONT_CARE, 0, nullptr, GL_TRUE);
    }
    glDebugMessageCallback(printDebugMessage, nullptr);
}

void setGlDebugMode(bool on) { gGlDebug = on; }
bool glDebugMode() { return gGlDebug; }
GlDebugCounts glDebugCounts() { return gCounts; }
void setGlErrorStop(GlErrorStop stop) { gStop = stop ? stop : stopAtError; }

std::string glDebugSummary() {
    std::string ids;
    for (const auto& [id, count] : gPerformanceById)
        ids += (ids.empty() ? " (by message id: " : ", ") + std::to_string(id) + " x" + std::to_string(count);
    if (!ids.empty()) ids += ")";
    return "--gl-debug: " + std::to_string(gCounts.errors) + " GL errors, " +
           std::to_string(gCounts.performanceWarnings) + " performance warnings" + ids + ", " +
           std::to_string(gCounts.otherWarnings) + " other warnings (printed above)";
}

namespace {

std::string gHeadlessDisplay = "none yet";

EGLDisplay initialised(EGLDisplay display) {
    EGLint major = 0, minor = 0;
    if (display == EGL_NO_DISPLAY) return EGL_NO_DISPLAY;
    if (eglInitialize(display, &major, &minor)) return display;
    return EGL_NO_DISPLAY;
}

// EGL_EXT_platform_device's first hardware device, else its first (Mesa lists a software one).
EGLDisplay openDeviceDisplay(std::string& chosen) {
    if (!epoxy_has_egl_extension(EGL_NO_DISPLAY, "EGL_EXT_platform_device") ||
        !epoxy_has_egl_extension(EGL_NO_DISPLAY, "EGL_EXT_device_enumeration"))
        return EGL_NO_DISPLAY;
    EGLDeviceEXT devices[16];
    EGLint count = 0;
    if (!eglQueryDevicesEXT(16, devices, &count) || count < 1) return EGL_NO_DISPLAY;
    int pick = 0;
    for (int i = count - 1; i >= 0; --i) {
        const char* extensions = eglQueryDeviceStringEXT(devices[i], EGL_EXTENSIONS);
        if (!extensions || !std::strstr(extensions, "EGL_MESA_device_software")) pick = i;
    }
    const char* extensions = eglQueryDeviceStringEXT(devices[pick], EGL_EXTENSIONS);
    bool software = extensions && std::strstr(extensions, "EGL_MESA_device_software");
    chosen = "EGL device " + std::to_string(pick + 1) + " of " + std::to_string(count) +
             (software ? " (software)" : "") + " (EGL_EXT_platform_device)";
    return initialised(eglGetPlatformDisplayEXT(EGL_PLATFORM_DEVICE_EXT, devices[pick], nullptr));
}

// The headless display: the surfaceless platform (Mesa's; NVIDIA's 580 driver has it too), else an
// EGL device, for a driver whose headless contexts come only from EGL_EXT_platform_device.
// OASIS_EGL_PLATFORM=device skips surfaceless, so that path is tested on Mesa too.
EGLDisplay openHeadlessDisplay() {
    const char* asked = std::getenv("OASIS_EGL_PLATFORM");
    std::string platform = asked ? asked : "";
    if (!platform.empty() && platform != "surfaceless" && platform != "device") {
        std::string shown = platform.size() > 40 ? platform.substr(0, 40) + "..." : platform;
        throw std::runtime_error("OASIS_EGL_PLATFORM must be surfaceless or device, not '" + shown + "'");
    }
    bool hasSurfaceless = epoxy_has_egl_extension(EGL_NO_DISPLAY, "EGL_MESA_platform_surfaceless");
    if (platform != "device" && hasSurfaceless) {
        EGLDisplay display =
            initialised(eglGetPlatformDisplayEXT(EGL_PLATFORM_SURFACELESS_MESA, EGL_DEFAULT_DISPLAY, nullptr));
        if (display != EGL_NO_DISPLAY) {
            gHeadlessDisplay = "surfaceless (EGL_MESA_platform_surfaceless)";
            return display;
        }
    }
    std::string chosen;
    if (platform != "surfaceless") {
        if (EGLDisplay display = openDeviceDisplay(chosen); display != EGL_NO_DISPLAY) {
            gHeadlessDisplay = chosen + (platform == "device" ? ", as OASIS_EGL_PLATFORM asked"
                                                              : hasSurfaceless ? ", the surfaceless display failed"
                                                                               : ", EGL has no surfaceless platform");
            return display;
        }
    }
    throw std::runtime_error("cannot initialise a surfaceless EGL display" + std::string(
        hasSurfaceless ? "" : " (EGL has no EGL_MESA_platform_surfaceless: need Mesa's libegl-mesa0)") +
        (platform == "surfaceless" ? "" : ", nor an EGL device (EGL_EXT_platform_device)"));
}

}  // namespace

std::string headlessDisplayDescription() { return gHeadlessDisplay; }

HeadlessContext::HeadlessContext(MaxGlVersion max) {
    if (!max.es) capMesaVersion(max);
    EGLDisplay display = openHeadlessDisplay();
    display_ = display;
    if (max.es) {
        makeEsContext(display);
        return;
    }
    if (!eglBindAPI(EGL_OPENGL_API)) throw std::runtime_error("EGL cannot bind the desktop OpenGL API");
    EGLint configAttributes[] = {EGL_RENDERABLE_TYPE, EGL_OPENGL_BIT, EGL_NONE};
    EGLConfig config = nullptr;
    EGLint configCount = 0;
    eglChooseConfig(display, configAttributes, &config, 1, &configCount);
    bool noConfig = epoxy_has_egl_extension(display, "EGL_KHR_no_config_context");
    if (configCount < 1 && !noConfig) throw std::runtime_error("EGL has no OpenGL-renderable config");
    EGLConfig chosen = configCount ? config : EGL_NO_CONFIG_KHR;
    auto makeCurrentContext = [&](int glMajor, int glMinor) -> EGLContext {
        EGLint attributes[] = {EGL_CONTEXT_MAJOR_VERSION_KHR, glMajor, EGL_CONTEXT_MINOR_VERSION_KHR, glMinor,
                               EGL_CONTEXT_OPENGL_PROFILE_MASK_KHR, EGL_CONTEXT_OPENGL_CORE_PROFILE_BIT_KHR,
                               EGL_CONTEXT_FLAGS_KHR, EGL_CONTEXT_OPENGL_DEBUG_BIT_KHR, EGL_NONE};
        EGLContext context = eglCreateContext(display, chosen, EGL_NO_CONTEXT, attributes);
        if (context == EGL_NO_CONTEXT) return EGL_NO_CONTEXT;
        if (!eglMakeCurrent(display, EGL_NO_SURFACE, EGL_NO_SURFACE, context)) {
            eglDestroyContext(display, context);
            return EGL_NO_CONTEXT;
        }
        return context;
    };
    // The oldest version first: Mesa (like the other desktop drivers) answers a core request with
    // its newest core version, so one call gives the context, and a trace of the command (apitrace)
    // holds no refused eglCreateContext for its replay to stop at. Only a driver that gives exactly
    // the version asked for is then asked for the newer ones, newest first.
    auto [oldestMajor, oldestMinor] = kVersionsToTry[std::size(kVersionsToTry) - 1];
    EGLContext context = makeCurrentContext(oldestMajor, oldestMinor);
    if (context == EGL_NO_CONTEXT) {
        eglTerminate(display);
        throw std::runtime_error("EGL could not create an OpenGL 3.3+ core context on this driver");
    }
    GLint givenMajor = 0, givenMinor = 0;
    glGetIntegerv(GL_MAJOR_VERSION, &givenMajor);
    glGetIntegerv(GL_MINOR_VERSION, &givenMinor);
    if (givenMajor == oldestMajor && givenMinor == oldestMinor) {
        for (auto [glMajor, glMinor] : kVersionsToTry) {
            if (!allowed(max, glMajor, glMinor) || (glMajor == oldestMajor && glMinor == oldestMinor)) continue;
            if (EGLContext newer = makeCurrentContext(glMajor, glMinor); newer != EGL_NO_CONTEXT) {
                eglDestroyContext(display, context);
                context = newer;
                break;
            }
        }
        eglMakeCurrent(display, EGL_NO_SURFACE, EGL_NO_SURFACE, context);  // again where none newer was made
    }
    context_ = context;
    installDebugOutput();
}

// --api gles: an OpenGL ES context, 3.2 first (Mesa gives its newest ES 3.x for any 3.x request),
// then 3.1 and 3.0 for a driver that gives exactly what is asked for.
void HeadlessContext::makeEsContext(void* displayHandle) {
    auto display = static_cast<EGLDisplay>(displayHandle);
    if (!eglBindAPI(EGL_OPENGL_ES_API)) {
        eglTerminate(display);
        throw std::runtime_error("EGL cannot bind the OpenGL ES API (--api gles)");
    }
    EGLint configAttributes[] = {EGL_RENDERABLE_TYPE, EGL_OPENGL_ES3_BIT, EGL_NONE};
    EGLConfig config = nullptr;
    EGLint configCount = 0;
    eglChooseConfig(display, configAttributes, &config, 1, &configCount);
    bool noConfig = epoxy_has_egl_extension(display, "EGL_KHR_no_config_context");
    if (configCount < 1 && !noConfig) {
        eglTerminate(display);
        throw std::runtime_error("EGL has no OpenGL ES 3-renderable config (--api gles)");
    }
    EGLConfig chosen = configCount ? config : EGL_NO_CONFIG_KHR;
    for (int esMinor : {2, 1, 0}) {
        EGLint attributes[] = {EGL_CONTEXT_MAJOR_VERSION_KHR, 3, EGL_CONTEXT_MINOR_VERSION_KHR, esMinor,
                               EGL_CONTEXT_FLAGS_KHR, EGL_CONTEXT_OPENGL_DEBUG_BIT_KHR, EGL_NONE};
        EGLContext context = eglCreateContext(display, chosen, EGL_NO_CONTEXT, attributes);
        if (context == EGL_NO_CONTEXT) continue;
        if (!eglMakeCurrent(display, EGL_NO_SURFACE, EGL_NO_SURFACE, context)) {
            eglDestroyContext(display, context);
            continue;
        }
        context_ = context;
        installDebugOutput();
        return;
    }
    eglTerminate(display);
    throw std::runtime_error("EGL could not create an OpenGL ES 3.0+ context on this driver (--api gles)");
}

HeadlessContext::~HeadlessContext() {
    auto display = static_cast<EGLDisplay>(display_);
    eglMakeCurrent(display, EGL_NO_SURFACE, EGL_NO_SURFACE, EGL_NO_CONTEXT);
    if (context_) eglDestroyContext(display, static_cast<EGLContext>(context_));
    eglTerminate(display);
}

namespace {

// --api gles: an OpenGL ES 3.x window, or null. Its context comes from EGL (GLX makes ES contexts
// only by GLX_EXT_create_context_es2_profile; the headless ES context is EGL's too), 3.2 first as
// makeEsContext asks. Measured under Xvfb: llvmpipe gives ES 3.2 through EGL (and through GLX).
GLFWwindow* openEsWindow(int width, int height, const std::string& title) {
    for (int esMinor : {2, 1, 0}) {
        glfwDefaultWindowHints();
        glfwWindowHint(GLFW_CLIENT_API, GLFW_OPENGL_ES_API);
        glfwWindowHint(GLFW_CONTEXT_CREATION_API, GLFW_EGL_CONTEXT_API);
        glfwWindowHint(GLFW_CONTEXT_VERSION_MAJOR, 3);
        glfwWindowHint(GLFW_CONTEXT_VERSION_MINOR, esMinor);
        glfwWindowHint(GLFW_OPENGL_DEBUG_CONTEXT, GLFW_TRUE);
        if (GLFWwindow* window = glfwCreateWindow(width, height, title.c_str(), nullptr, nullptr)) return window;
    }
    return nullptr;
}

}  // namespace

bool WindowContext::displayAvailable() {
    const char* x11 = std::getenv("DISPLAY");
    const char* wayland = std::getenv("WAYLAND_DISPLAY");
    return (x11 && *x11) || (wayland && *wayland);
}

WindowContext::WindowContext(int width, int height, const std::string& title, MaxGlVersion max) {
    capMesaVersion(max);
    if (!glfwInit()) {
        std::string reason = glfwLastError();
        const char* x11 = std::getenv("DISPLAY");
        const char* wayland = std::getenv("WAYLAND_DISPLAY");
        // GLFW names the display variable of the platform it was built for; say what was found.
        if (!(x11 && *x11) && wayland && *wayland)
            reason += " (WAYLAND_DISPLAY is set to '" + std::string(wayland) + "' but DISPLAY is not: this GLFW "
                      "build opens X11 windows, so run under XWayland with DISPLAY set, or use a headless "
                      "command such as `oasis render`)";
        throw std::runtime_error("cannot open a window: " + reason);
    }
    if (max.es) window_ = openEsWindow(width, height, title);
    for (auto [glMajor, glMinor] : kVersionsToTry) {
        if (max.es || !allowed(max, glMajor, glMinor)) continue;
        glfwDefaultWindowHints();
        glfwWindowHint(GLFW_CONTEXT_VERSION_MAJOR, glMajor);
        glfwWindowHint(GLFW_CONTEXT_VERSION_MINOR, glMinor);
        glfwWindowHint(GLFW_OPENGL_PROFILE, GLFW_OPENGL_CORE_PROFILE);
        glfwWindowHint(GLFW_OPENGL_FORWARD_COMPAT, GLFW_TRUE);
        glfwWindowHint(GLFW_OPENGL_DEBUG_CONTEXT, GLFW_TRUE);
        window_ = glfwCreateWindow(width, height, title.c_str(), nullptr, nullptr);
        if (window_) break;
    }
    if (!window_) {
        std::string reason = glfwLastError();
        glfwTerminate();
        throw std::runtime_error(std::string(max.es ? "cannot open an OpenGL ES 3.0+ window (--api gles, EGL): "
                                                    : "cannot open an OpenGL 3.3+ core window: ") + reason);
    }
    glfwMakeContextCurrent(window_);
    glfwSwapInterval(0);
    installDebugOutput();
}

bool WindowContext::minimised(int& width, int& height) const {
    glfwGetFramebufferSize(window_, &width, &height);
    return glfwGetWindowAttrib(window_, GLFW_ICONIFIED) || width <= 0 || height <= 0;
}

WindowContext::~WindowContext() {
    if (window_) glfwDestroyWindow(window_);
    glfwTerminate();
}

}  // namespace oasis
