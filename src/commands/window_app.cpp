// The window loop: input, the ImGui panel, one frame, the chosen view, present.
//   Tab pipeline  1..7 views  0 overview  G layout  Z depth convention  R reload shaders
//   V plants  H hide/show the panel  O the frame-time overlay  Space pause  Esc quit;  free camera: W/S/A/D, arrows, Q/E
//   the inspector: the values under the cursor, click to pin probes (right click: unpin the last),
//   P prints the probe under the cursor as JSON, I the pins' (or the hovered pixel's) shading and
//   history, F freezes the pins' values; the view controls (channel, range, overlay, exposure)
//   C cycles the live comparison: split forward | deferred (drag the divider), split layout A | B,
//   the difference of either, off
// A switch whose programs do not build (a shader broken on disk, never built before) is undone:
// the last configuration that drew is drawn again and the error stays in the panel. Nothing is
// drawn while the window is minimised.
#include "commands/window_app.h"

#include <GLFW/glfw3.h>
#include <imgui.h>
#include <imgui_impl_glfw.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>

#include "cli/input_domains.h"
#include "commands/window_state.h"
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

// Prints the window's state changes once each, so a log (and the window tests) can follow them.
void noteMinimised(WindowState& state, bool& minimised, bool now) {
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
        RenderSession session(options);
        Renderer& renderer = *session.renderer;
        std::printf("oasis: window on %s; stencil view: %s\n", queryContextInfo().summary().c_str(),
                    session.stencilPathReason.c_str());
        std::printf("oasis: %s\n", describePlantAtlas(session).c_str());
        std::fflush(stdout);

        IMGUI_CHECKVERSION();
        ImGui::CreateContext();
        ImGui::GetIO().IniFilename = nullptr;
        ImGui_ImplGlfw_InitForOpenGL(window.window(), true);
        const bool esBackend = imguiGlBackendInit();  // the panel's GL backend: desktop, or ES (--api gles)

        WindowState state;
        state.fallbacks = session.fallbacks();
        state.chosen.pipeline = options.pipeline;
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

        struct Input { Renderer* renderer; WindowState* state; SceneSettings* scene; } input{&renderer, &state, &scene};
        glfwSetWindowUserPointer(window.window(), &input);
        glfwSetKeyCallback(window.window(), [](GLFWwindow* w, int key, int scancode, int action, int mods) {
            // Tab is the pipeline key: ImGui gets it only while a text field is being edited, or its
            // tabbing turns the panel's sliders into text fields, which then swallow every key.
            if (key != GLFW_KEY_TAB || ImGui::GetIO().WantTextInput)
                ImGui_ImplGlfw_KeyCallback(w, key, scancode, action, mods);
            auto* in = static_cast<Input*>(glfwGetWindowUserPointer(w));
            handleKeys(w, key, action, *in->renderer, *in->state, *in->scene);
        });

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
            if (!state.paused) scene.timeSeconds += seconds;
            if (state.freeCamera) moveFreeCamera(window.window(), *scene.camera, seconds);
            else *scene.camera = defaultCameraPath(scene.terrain, scene.timeSeconds);
            keepInsideDomains(scene, state);

            imguiGlBackendNewFrame(esBackend);
            ImGui_ImplGlfw_NewFrame();
            ImGui::NewFrame();
            state.inspector.sectionOpen = false;
            if (state.panelShown) drawPanel(renderer, scene, state);
            handleInspectorMouse(window.window(), state.inspector, state.comparison, state.draggingDivider);
            drawPinMarkers(window.window(), state.inspector);
            drawCompareLabels(window.window(), state.comparison);
            drawStatusOverlay(window.window(), state);
            nameImGuiObjects(*ImGui::GetBackgroundDrawList(), "ImGui panel");
            ImGui::Render();

            auto loopStart = std::chrono::steady_clock::now();
            if (drawChosen(session, scene, state, width, height)) {
                if (++state.counts.framesDrawn == 1) {  // scripts driving the window wait for this line
                    std::printf("oasis: first frame drawn (%dx%d)\n", width, height);
                    std::fflush(stdout);
                }
            } else {  // only the panel, over a neutral grey, until the shader is mended
                glBindFramebuffer(GL_FRAMEBUFFER, 0);
                glViewport(0, 0, width, height);
                glClearColor(0.2f, 0.2f, 0.2f, 1.0f);
                glClear(GL_COLOR_BUFFER_BIT);
            }
            {
                gl::DebugGroup group("UI (ImGui panel)");
                imguiGlBackendRender(esBackend, ImGui::GetDrawData());
            }
            glfwSwapBuffers(window.window());
            glFinish();
            reportNewCapture(state);
            std::string label = loopLabel(state);
            if (!state.counts.loopMs.count(label)) state.counts.loopOrder.push_back(label);
            state.counts.loopMs[label].push_back(
                std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - loopStart).count());
        }
        state.sideB.reset();  // its GL objects go before the context
        imguiGlBackendShutdown(esBackend);
        ImGui_ImplGlfw_Shutdown();
        ImGui::DestroyContext();
        const WindowCounts& counts = state.counts;
        std::printf("oasis: window closed: %ld frames drawn, %ld pipeline switches, %ld switches undone, "
                    "%ld resizes, minimised %ld times\n",
                    counts.framesDrawn, counts.pipelineSwitches, counts.switchesUndone, counts.resizes,
                    counts.minimised);
        std::printf("oasis: window loop ms (median): %s\n", loopSummary(counts).c_str());
        return 0;
    } catch (const std::exception& error) {
        std::fprintf(stderr, "oasis: %s\n", error.what());
        return 1;
    }
}

}  // namespace oasis