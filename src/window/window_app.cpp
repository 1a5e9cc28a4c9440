// One window's app, a frame at a time: input, the ImGui panel, one frame, the chosen view.
//   Tab pipeline  1..7 views  0 overview  G layout  Z depth convention  R reload shaders
//   V plants  H hide/show the panel  O the frame-time overlay  Space pause  Esc quit;  free camera: W/S/A/D, arrows, Q/E
//   the inspector: the values under the cursor, click to pin probes (right click: unpin the last),
//   P prints the probe under the cursor as JSON, I the pins' (or the hovered pixel's) shading and
//   history, F freezes the pins' values; the view controls (channel, range, overlay, exposure)
//   C cycles the live comparison: split forward | deferred (drag the divider), split layout A | B,
//   the difference of either, off
// A switch whose programs do not build (a shader broken on disk, never built before) is undone:
// the last configuration that drew is drawn again and the error stays in the panel. The loop that
// calls frame() is the native window's (window_loop.cpp) or the browser's (src/web/web_main.cpp).
#include "window/window_app.h"

#include <epoxy/gl.h>
#include <GLFW/glfw3.h>
#include <imgui.h>
#include <imgui_impl_glfw.h>

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "cli/input_domains.h"
#include "context/gl_context.h"
#include "debug/imgui_gl_backend.h"
#include "debug/imgui_gl_labels.h"

namespace oasis {
namespace {

using namespace window;

// The window's clock, keys and panel move the scene like the command line's values: keep what they
// set inside the same domains (cli/input_domains.h), saying so when one stops at an edge.
void keepInsideDomains(SceneSettings& scene, WindowState& state) {
    auto clampTo = [&](double& value, const char* name) {
        const InputDomain& domain = inputDomain(name);
        double inside = std::clamp(value, domain.low, domain.high);
        if (inside == value) return;
        value = inside;
        report(state, std::string(name) + " stops at the edge of its domain " + describeDomain(domain), false);
    };
    clampTo(scene.timeSeconds, "--time");
    CameraPose& pose = *scene.camera;
    clampTo(pose.position.x, "--camera X");
    clampTo(pose.position.y, "--camera Y");
    clampTo(pose.position.z, "--camera Z");
    // The yaw wraps, in double, as the parser's does.
    pose.yawDegrees = float(std::remainder(double(pose.yawDegrees), 360.0));
}

// The state the command line's options start the window in.
void startFromOptions(const Options& options, RenderSession& session, WindowState& state) {
    state.fallbacks = session.fallbacks();
    state.chosen.pipeline = options.pipeline;
    state.chosen.view = options.view.empty() ? "final" : options.view;
    state.chosen.waterScene = options.waterScene;
    state.paused = options.startPaused;
    for (size_t i = 0; i < gbufferLayouts().size(); ++i)
        if (gbufferLayouts()[i].name == options.scene.gbuffer) state.chosen.layoutIndex = i;
    for (size_t i = 0; i < depthConventions().size(); ++i)
        if (depthConventions()[i].name == options.scene.depth) state.chosen.depthIndex = i;
    SceneSettings& scene = session.scene;
    state.freeCamera = bool(options.scene.camera);
    scene.camera = options.scene.camera ? *options.scene.camera : defaultCameraPath(scene.terrain, scene.timeSeconds);
    if (state.paused) std::printf("oasis: paused at --time %.17g (--start-paused; Space runs the clock)\n", scene.timeSeconds);
}

}  // namespace

WindowApp::WindowApp(const Options& options, GLFWwindow* window) : window_(window), session_(options) {
    std::printf("oasis: window on %s; stencil view: %s\n", queryContextInfo().summary().c_str(),
                session_.stencilPathReason.c_str());
    std::printf("oasis: %s\n", describePlantAtlas(session_).c_str());
    std::fflush(stdout);

    IMGUI_CHECKVERSION();
    ImGui::CreateContext();
    ImGui::GetIO().IniFilename = nullptr;  // no imgui.ini written beside the user's files
    ImGui_ImplGlfw_InitForOpenGL(window_, true);
    esBackend_ = imguiGlBackendInit();
    startFromOptions(options, session_, state_);

    glfwSetWindowUserPointer(window_, this);
    glfwSetKeyCallback(window_, [](GLFWwindow* w, int key, int scancode, int action, int mods) {
        // Tab is the pipeline key: ImGui gets it only while a text field is being edited, or its
        // tabbing turns the panel's sliders into text fields, which then swallow every key.
        if (key != GLFW_KEY_TAB || ImGui::GetIO().WantTextInput)
            ImGui_ImplGlfw_KeyCallback(w, key, scancode, action, mods);
        auto* app = static_cast<WindowApp*>(glfwGetWindowUserPointer(w));
        handleKeys(w, key, action, *app->session_.renderer, app->state_, app->session_.scene);
    });
}

WindowApp::~WindowApp() {
    glfwSetKeyCallback(window_, nullptr);
    glfwSetWindowUserPointer(window_, nullptr);
    state_.sideB.reset();
    imguiGlBackendShutdown(esBackend_);
    ImGui_ImplGlfw_Shutdown();
    ImGui::DestroyContext();
}

void WindowApp::frame(int width, int height, float seconds) {
    Renderer& renderer = *session_.renderer;
    SceneSettings& scene = session_.scene;
    if (!state_.paused) scene.timeSeconds += seconds;
    if (state_.freeCamera) moveFreeCamera(window_, *scene.camera, seconds);
    else *scene.camera = defaultCameraPath(scene.terrain, scene.timeSeconds);
    keepInsideDomains(scene, state_);

    imguiGlBackendNewFrame(esBackend_);
    ImGui_ImplGlfw_NewFrame();
    ImGui::NewFrame();
    state_.inspector.sectionOpen = false;
    if (state_.panelShown) drawPanel(renderer, scene, state_);
    handleInspectorMouse(window_, state_.inspector, state_.comparison, state_.draggingDivider);
    drawPinMarkers(window_, state_.inspector);
    drawCompareLabels(window_, state_.comparison);
    drawStatusOverlay(window_, state_);
    nameImGuiObjects(*ImGui::GetBackgroundDrawList(), "ImGui panel");
    ImGui::Render();

    drawStart_ = std::chrono::steady_clock::now();
    if (drawChosen(session_, scene, state_, width, height)) {
        if (++state_.counts.framesDrawn == 1) {  // scripts driving the window wait for this line
            std::printf("oasis: first frame drawn (%dx%d)\n", width, height);
            std::fflush(stdout);
        }
    } else {  // only the panel, over a neutral grey, until the shader is mended
        glBindFramebuffer(GL_FRAMEBUFFER, 0);
        glViewport(0, 0, width, height);
        glClearColor(0.2f, 0.2f, 0.2f, 1.0f);
        glClear(GL_COLOR_BUFFER_BIT);
    }
    gl::DebugGroup group("UI (ImGui panel)");
    imguiGlBackendRender(esBackend_, ImGui::GetDrawData());
}

void WindowApp::finishFrame() {
    reportNewCapture(state_);
    std::string label = loopLabel(state_);
    if (!state_.counts.loopMs.count(label)) state_.counts.loopOrder.push_back(label);
    state_.counts.loopMs[label].push_back(
        std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - drawStart_).count());
}

void WindowApp::printClosingCounts() const {
    const WindowCounts& counts = state_.counts;
    std::printf("oasis: window closed: %ld frames drawn, %ld pipeline switches, %ld switches undone, "
                "%ld resizes, minimised %ld times\n",
                counts.framesDrawn, counts.pipelineSwitches, counts.switchesUndone, counts.resizes, counts.minimised);
    std::printf("oasis: window loop ms (median): %s\n", loopSummary(counts).c_str());
}

}  // namespace oasis
