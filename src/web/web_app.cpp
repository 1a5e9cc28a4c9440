// The browser app: a WebGL 2 canvas from emscripten's GLFW (an OpenGL ES 3.0 context; no EGL in
// the browser) and the native window's WindowApp on it: the same panel, keys, inspector and
// comparison, a frame per call of the page's main loop.
#include "web/web_app.h"

#include <emscripten.h>
#define GLFW_INCLUDE_ES3  // GLFW includes <GLES3/gl3.h>, not desktop <GL/gl.h>
#include <GLFW/glfw3.h>
#include <epoxy/gl.h>

#include <cstdio>
#include <stdexcept>

#include "context/gl_context.h"
#include "frame/encoding_error.h"
#include "frame/frame_readback.h"
#include "frame/pixel_probe.h"
#include "render/image.h"
#include "io/json_text.h"

namespace oasis::web {

void showPageError(const std::string& message) {
    std::fprintf(stderr, "oasis: %s\n", message.c_str());
    EM_ASM({ if (typeof oasisPageError === 'function') oasisPageError(UTF8ToString($0)); }, message.c_str());
}

bool WebApp::start() {
    if (!glfwInit()) {
        showPageError("GLFW could not start in this page");
        return false;
    }
    glfwWindowHint(GLFW_CLIENT_API, GLFW_OPENGL_ES_API);
    glfwWindowHint(GLFW_CONTEXT_VERSION_MAJOR, 3);
    glfwWindowHint(GLFW_CONTEXT_VERSION_MINOR, 0);
    window_ = glfwCreateWindow(options_.scene.width, options_.scene.height, "oasis", nullptr, nullptr);
    if (!window_) {
        showPageError("this browser gives no WebGL 2 context: oasis needs WebGL 2 (OpenGL ES 3.0)");
        return false;
    }
    glfwMakeContextCurrent(window_);
    // The G-buffer's RGBA16F/RGBA32F targets are renderable in WebGL 2 only with this extension.
    if (!epoxy_has_gl_extension("GL_EXT_color_buffer_float") && !epoxy_has_gl_extension("EXT_color_buffer_float")) {
        showPageError("this browser's WebGL 2 lacks EXT_color_buffer_float: the G-buffer's float targets cannot be drawn");
        return false;
    }
    try {
        app_ = std::make_unique<WindowApp>(options_, window_);
    } catch (const std::exception& error) {
        showPageError(std::string("oasis could not start: ") + error.what());
        return false;
    }
    last_ = std::chrono::steady_clock::now();
    return true;
}

void WebApp::frame() {
    int width = 0, height = 0;
    glfwGetFramebufferSize(window_, &width, &height);
    if (width <= 0 || height <= 0) return;  // a canvas of no size: nothing to draw into
    auto now = std::chrono::steady_clock::now();
    float seconds = std::chrono::duration<float>(now - last_).count();
    last_ = now;
    long before = framesDrawn();
    app_->frame(width, height, seconds);
    app_->finishFrame();  // the browser shows the canvas when this iteration returns
    if (before == 0 && framesDrawn() == 1)  // the page's and the test's time to first frame
        EM_ASM({ if (typeof oasisFirstFrame === 'function') oasisFirstFrame(); });
}

void WebApp::setPipeline(PipelineKind kind) { window::choosePipeline(app_->state(), kind); }

bool WebApp::setView(const std::string& view) {
    for (const std::string& name : window::viewNames())
        if (name == view) {
            app_->state().chosen.view = view;
            return true;
        }
    return false;
}

std::string WebApp::windowStateJson() {
    const window::WindowState& state = app_->state();
    const window::Configuration& chosen = state.chosen;
    return std::string("{\"pipeline\":") + jsonString(pipelineName(chosen.pipeline)) +
           ",\"gbuffer\":" + jsonString(gbufferLayouts()[chosen.layoutIndex].name) + ",\"view\":" + jsonString(chosen.view) +
           ",\"paused\":" + (state.paused ? "true" : "false") + ",\"panel\":" + (state.panelShown ? "true" : "false") +
           ",\"compare\":" + jsonString(compareModeName(state.comparison.mode)) +
           ",\"pins\":" + std::to_string(state.inspector.pinned.size()) + "}";
}

SceneSettings WebApp::optionsScene() {
    // The frame of the page's options (time, hour, camera), not of the live clock, as `render` draws it.
    SceneSettings scene = session().scene;
    scene.timeSeconds = options_.scene.timeSeconds;
    scene.hour = options_.scene.hour;
    scene.camera = options_.scene.camera;
    return scene;
}

bool WebApp::writeFinalPng(PipelineKind kind, const std::string& path) {
    Renderer& renderer = *session().renderer;
    renderer.setPipeline(kind);
    renderer.configure(options_.scene.width, options_.scene.height, renderer.targets().layout());
    renderer.renderFrame(optionsScene());
    renderer.views().render("final");
    Image image = readDisplay(renderer);
    std::string error;
    if (!writePng(path, image, error)) {
        std::fprintf(stderr, "oasis: %s\n", error.c_str());
        return false;
    }
    return true;
}

std::string WebApp::probeJson(PipelineKind kind, int x, int y) {
    // What `oasis probe --at X,Y --json` does: the layout's encoding error, then the frame asked for.
    Renderer& renderer = *session().renderer;
    renderer.configure(options_.scene.width, options_.scene.height, renderer.targets().layout());
    SceneSettings scene = optionsScene();
    std::optional<EncodingError> error;
    if (renderer.targets().layout().name != "full") error = measureEncodingError(renderer, scene, renderer.targets().layout());
    renderer.setPipeline(kind);
    renderer.renderFrame(scene);
    PixelProbe probe = probePixel(renderer, x, y);
    if (error) addEncodingError(probe, *error);
    return oasis::probeJson(probe);
}

std::string WebApp::capabilityJson() {
    ContextInfo context = queryContextInfo();
    std::string json = "{\"version\":" + jsonString(context.version) + ",\"vendor\":" + jsonString(context.vendor) +
                       ",\"renderer\":" + jsonString(context.renderer) + ",\"glsl\":" + jsonString(context.glslVersion) +
                       ",\"features\":[";
    bool first = true;
    for (const gl::FeatureReport& feature : session().features()) {
        json += std::string(first ? "" : ",") + "{\"name\":" + jsonString(feature.name) + ",\"used\":" +
                (feature.used ? "true" : "false") + ",\"available\":" + (feature.available ? "true" : "false") +
                ",\"reason\":" + jsonString(feature.reason) + "}";
        first = false;
    }
    // The layout drawn (the renderer's fallback may have replaced the one asked for): the web test
    // renders the native frame with it.
    json += "],\"gbuffer\":" + jsonString(session().renderer->targets().layout().name) + ",\"fallbacks\":[";
    first = true;
    for (const std::string& line : session().fallbacks()) {
        json += std::string(first ? "" : ",") + jsonString(line);
        first = false;
    }
    return json + "]}";
}

}  // namespace oasis::web
