// The browser app: a WebGL 2 canvas from emscripten's GLFW (an OpenGL ES 3.0 context; no EGL in
// the browser), the same RenderSession and Renderer calls as the native window, and a panel.
#include "web/web_app.h"

#include <emscripten.h>
#define GLFW_INCLUDE_ES3  // GLFW includes <GLES3/gl3.h>, not desktop <GL/gl.h>
#include <GLFW/glfw3.h>
#include <epoxy/gl.h>

#include <cstdio>
#include <stdexcept>

#include <imgui.h>
#include <imgui_impl_glfw.h>
#include "debug/imgui_gl_backend.h"

#include "context/gl_context.h"
#include "frame/encoding_error.h"
#include "frame/frame_readback.h"
#include "frame/pixel_probe.h"
#include "render/image.h"

namespace oasis::web {
namespace {
std::string jsonString(const std::string& text) {
    std::string out = "\"";
    for (char c : text) {
        if (c == '"' || c == '\\') out += '\\', out += c;
        else if (c == '\n') out += "\\n";
        else if (static_cast<unsigned char>(c) < 0x20) out += ' ';
        else out += c;
    }
    return out + "\"";
}
}  // namespace

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
    // The compact G-buffer's RG16 normal target is renderable on ES 3.0 only with EXT_texture_norm16,
    // which many WebGL 2 implementations (SwiftShader in Chromium among them) do not offer: the
    // standard layout (RGBA16F normal) is taken instead, and the report says so.
    if (options_.scene.gbuffer == "compact" && !epoxy_has_gl_extension("GL_EXT_texture_norm16") &&
        !epoxy_has_gl_extension("EXT_texture_norm16")) {
        options_.scene.gbuffer = "standard";
        webFallbacks_.push_back("gbuffer layout: standard (the compact layout's RG16 target needs EXT_texture_norm16, "
                                "absent in this browser's WebGL 2)");
    }
    try {
        session_ = std::make_unique<RenderSession>(options_);
    } catch (const std::exception& error) {
        showPageError(std::string("oasis could not start: ") + error.what());
        return false;
    }
    IMGUI_CHECKVERSION();
    ImGui::CreateContext();
    ImGui::GetIO().IniFilename = nullptr;  // no imgui.ini in the page's file system
    ImGui_ImplGlfw_InitForOpenGL(window_, true);
    imguiGlBackendInit();
    session_->scene.timeSeconds = options_.scene.timeSeconds;
    return true;
}

void WebApp::frame() {
    Renderer& renderer = *session_->renderer;
    int width = 0, height = 0;
    glfwGetFramebufferSize(window_, &width, &height);
    renderer.setPipeline(pipeline_);
    renderer.configure(width, height, renderer.targets().layout());
    renderer.renderFrame(session_->scene);
    renderer.views().render(view_);
    renderer.present(width, height);

    imguiGlBackendNewFrame(true);
    ImGui_ImplGlfw_NewFrame();
    ImGui::NewFrame();
    drawPanel();
    ImGui::Render();
    imguiGlBackendRender(true, ImGui::GetDrawData());
    if (++frames_ == 1)  // the page's and the test's time to first frame
        EM_ASM({ if (typeof oasisFirstFrame === 'function') oasisFirstFrame(); });
    if (!paused_) session_->scene.timeSeconds += 1.0 / 60.0;
}

void WebApp::drawPanel() {
    SceneSettings& scene = session_->scene;
    ImGui::SetNextWindowPos(ImVec2(8, 8), ImGuiCond_FirstUseEver);
    ImGui::SetNextWindowSize(ImVec2(370, 0), ImGuiCond_FirstUseEver);
    ImGui::Begin("oasis (WebGL 2)");
    int kind = pipeline_ == PipelineKind::Forward ? 0 : 1;
    ImGui::RadioButton("forward", &kind, 0);
    ImGui::SameLine();
    ImGui::RadioButton("deferred", &kind, 1);
    pipeline_ = kind == 0 ? PipelineKind::Forward : PipelineKind::Deferred;
    if (ImGui::BeginCombo("view", view_.c_str())) {
        for (const DebugView& view : debugViews())
            if (ImGui::Selectable(view.name.c_str(), view.name == view_)) view_ = view.name;
        if (ImGui::Selectable(kOverviewName, view_ == kOverviewName)) view_ = kOverviewName;
        ImGui::EndCombo();
    }
    float hour = float(scene.hour ? *scene.hour : hourAtTime(scene.timeSeconds));
    if (ImGui::SliderFloat("time of day (h)", &hour, 0.0f, 24.0f, "%.2f")) scene.hour = hour;
    if (scene.hour && ImGui::Button("follow the clock")) scene.hour.reset();
    ImGui::Checkbox("pause", &paused_);
    ImGui::Text("%.1f ms/frame", 1000.0f / std::max(ImGui::GetIO().Framerate, 0.001f));
    if (ImGui::CollapsingHeader("capabilities and paths")) {
        ContextInfo context = queryContextInfo();
        ImGui::TextWrapped("%s", context.summary().c_str());
        for (const std::string& line : webFallbacks_) ImGui::TextWrapped("fallback: %s", line.c_str());
        for (const gl::FeatureReport& feature : session_->features())
            ImGui::TextWrapped("%s %s: %s", feature.used ? "[used]" : "[    ]", feature.name.c_str(),
                               feature.reason.c_str());
    }
    ImGui::End();
}

SceneSettings WebApp::optionsScene() const {
    // The frame of the page's options (time, hour, camera), not of the live clock, as `render` draws it.
    SceneSettings scene = session_->scene;
    scene.timeSeconds = options_.scene.timeSeconds;
    scene.hour = options_.scene.hour;
    scene.camera = options_.scene.camera;
    return scene;
}

bool WebApp::writeFinalPng(PipelineKind kind, const std::string& path) {
    Renderer& renderer = *session_->renderer;
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
    Renderer& renderer = *session_->renderer;
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

std::string WebApp::capabilityJson() const {
    ContextInfo context = queryContextInfo();
    std::string json = "{\"version\":" + jsonString(context.version) + ",\"vendor\":" + jsonString(context.vendor) +
                       ",\"renderer\":" + jsonString(context.renderer) + ",\"glsl\":" + jsonString(context.glslVersion) +
                       ",\"features\":[";
    bool first = true;
    for (const gl::FeatureReport& feature : session_->features()) {
        json += std::string(first ? "" : ",") + "{\"name\":" + jsonString(feature.name) + ",\"used\":" +
                (feature.used ? "true" : "false") + ",\"available\":" + (feature.available ? "true" : "false") +
                ",\"reason\":" + jsonString(feature.reason) + "}";
        first = false;
    }
    json += "],\"gbuffer\":" + jsonString(options_.scene.gbuffer) + ",\"fallbacks\":[";
    first = true;
    std::vector<std::string> lines = webFallbacks_;
    for (const std::string& line : session_->fallbacks()) lines.push_back(line);
    for (const std::string& line : lines) {
        json += std::string(first ? "" : ",") + jsonString(line);
        first = false;
    }
    return json + "]}";
}

}  // namespace oasis::web
