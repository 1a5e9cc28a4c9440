// The window loop: input, the ImGui panel, one frame, the chosen view, present.
//   Tab pipeline  1..7 views  0 overview  G layout  R reload shaders  Space pause  Esc quit
//   free camera: W/S/A/D move, arrows turn, Q/E down/up
#include "commands/window_app.h"

#include <GLFW/glfw3.h>
#include <imgui.h>
#include <imgui_impl_glfw.h>
#include <imgui_impl_opengl3.h>

#include <chrono>
#include <cmath>
#include <cstdio>
#include <stdexcept>

#include "commands/session.h"
#include "context/gl_context.h"
#include "debug/debug_views.h"

namespace oasis {
namespace {

struct WindowState {
    std::string view = "final";
    bool paused = false;
    bool freeCamera = false;
    double frameMs = 0.0, smoothedMs = 0.0;
    std::string message;  // last reload result or error, shown in the panel
    std::vector<std::string> fallbacks;  // the session's fallbacks (printed once at start-up too)
    size_t layoutIndex = 0;
    size_t depthIndex = 0;  // into depthConventions(): the one asked for
};

std::vector<std::string> viewNames() {
    std::vector<std::string> names;
    for (const DebugView& view : debugViews()) names.push_back(view.name);
    names.push_back(kOverviewName);
    return names;
}

void reloadShaders(Renderer& renderer, WindowState& state) {
    std::vector<std::string> failures = renderer.shaders().reloadAll();
    state.message = failures.empty() ? "shaders reloaded" : failures.front();
    for (const std::string& failure : failures) std::fprintf(stderr, "oasis: %s\n", failure.c_str());
}

void handleKeys(GLFWwindow* window, int key, int action, Renderer& renderer, WindowState& state,
                SceneSettings& scene) {
    if (action != GLFW_PRESS || ImGui::GetIO().WantCaptureKeyboard) return;
    const auto& views = debugViews();
    if (key == GLFW_KEY_ESCAPE) glfwSetWindowShouldClose(window, GLFW_TRUE);
    if (key == GLFW_KEY_TAB)
        renderer.setPipeline(renderer.pipeline() == PipelineKind::Forward ? PipelineKind::Deferred : PipelineKind::Forward);
    if (key >= GLFW_KEY_1 && key < GLFW_KEY_1 + int(views.size())) state.view = views[size_t(key - GLFW_KEY_1)].name;
    if (key == GLFW_KEY_0) state.view = kOverviewName;
    if (key == GLFW_KEY_SPACE) state.paused = !state.paused;
    if (key == GLFW_KEY_R) reloadShaders(renderer, state);
    if (key == GLFW_KEY_G) state.layoutIndex = (state.layoutIndex + 1) % gbufferLayouts().size();
    if (key == GLFW_KEY_V) scene.vegetation.enabled = !scene.vegetation.enabled;
}

void moveFreeCamera(GLFWwindow* window, CameraPose& pose, float seconds) {
    if (ImGui::GetIO().WantCaptureKeyboard) return;
    auto down = [&](int key) { return glfwGetKey(window, key) == GLFW_PRESS ? 1.0f : 0.0f; };
    float speed = 40.0f * seconds * (1.0f + 4.0f * down(GLFW_KEY_LEFT_SHIFT));
    glm::vec3 forward = pose.forward();
    glm::vec3 right = glm::normalize(glm::cross(forward, glm::vec3(0, 1, 0)));
    glm::vec3 move = forward * (down(GLFW_KEY_W) - down(GLFW_KEY_S)) + right * (down(GLFW_KEY_D) - down(GLFW_KEY_A)) +
                     glm::vec3(0, 1, 0) * (down(GLFW_KEY_E) - down(GLFW_KEY_Q));
    pose.position += glm::dvec3(move * speed);
    pose.yawDegrees += 60.0f * seconds * (down(GLFW_KEY_RIGHT) - down(GLFW_KEY_LEFT));
    pose.pitchDegrees = glm::clamp(pose.pitchDegrees + 45.0f * seconds * (down(GLFW_KEY_UP) - down(GLFW_KEY_DOWN)),
                                   -89.0f, 89.0f);
}

// Point lights: the count, the path (automatic or forced) and which path is active and why.
void drawLightsPanel(const Renderer& renderer, SceneSettings& scene) {
    if (!ImGui::CollapsingHeader("lights", ImGuiTreeNodeFlags_DefaultOpen)) return;
    ImGui::SliderInt("point lights", &scene.lights.count, 0, kMaxLights);
    const char* choices[] = {"automatic", "ssbo", "ssbo-count", "ubo"};
    int choice = scene.lights.path ? 1 + int(*scene.lights.path) : 0;
    if (ImGui::Combo("light path", &choice, choices, 4))
        scene.lights.path = choice == 0 ? std::nullopt : std::optional<LightsPath>(LightsPath(choice - 1));
    ImGui::TextWrapped("active: %s", renderer.lightsPathReason().c_str());
    ImGui::Text("%d lights drawn; ubo holds %d x %d", renderer.lightsDrawn(), renderer.uboLights().blocks,
                renderer.uboLights().capacity);
    if (renderer.lightsDropped() > 0)
        ImGui::TextColored(ImVec4(1.0f, 0.4f, 0.2f, 1.0f), "WARNING: %d lights dropped", renderer.lightsDropped());
}

// The depth convention asked for; the one in use and why when it differs (no clip control).
void drawDepthCombo(const Renderer& renderer, WindowState& state) {
    const auto& conventions = depthConventions();
    if (ImGui::BeginCombo("depth", conventions[state.depthIndex].name.c_str())) {
        for (size_t i = 0; i < conventions.size(); ++i) {
            std::string label = conventions[i].name + " (" + std::to_string(conventions[i].depthStencil.bytesPerPixel) + " B/px)";
            if (ImGui::Selectable(label.c_str(), i == state.depthIndex)) state.depthIndex = i;
        }
        ImGui::EndCombo();
    }
    if (renderer.depthFellBack()) ImGui::TextWrapped("depth: %s", renderer.depthConventionReason().c_str());
}

void drawPanel(Renderer& renderer, SceneSettings& scene, WindowState& state) {
    ImGui::SetNextWindowPos(ImVec2(10, 10), ImGuiCond_FirstUseEver);
    ImGui::Begin("oasis");
    int pipeline = renderer.pipeline() == PipelineKind::Forward ? 0 : 1;
    if (ImGui::RadioButton("forward", &pipeline, 0)) renderer.setPipeline(PipelineKind::Forward);
    ImGui::SameLine();
    if (ImGui::RadioButton("deferred", &pipeline, 1)) renderer.setPipeline(PipelineKind::Deferred);
    ImGui::SameLine();
    ImGui::TextDisabled("(Tab)");

    const auto& layouts = gbufferLayouts();
    if (ImGui::BeginCombo("G-buffer", layouts[state.layoutIndex].name.c_str())) {
        for (size_t i = 0; i < layouts.size(); ++i) {
            std::string label = layouts[i].name + " (" + std::to_string(layouts[i].bytesPerPixel()) + " B/px)";
            if (ImGui::Selectable(label.c_str(), i == state.layoutIndex)) state.layoutIndex = i;
        }
        ImGui::EndCombo();
    }
    drawDepthCombo(renderer, state);
    if (ImGui::BeginCombo("view", state.view.c_str())) {
        for (const std::string& name : viewNames())
            if (ImGui::Selectable(name.c_str(), name == state.view)) state.view = name;
        ImGui::EndCombo();
    }
    if (const DebugView* view = findDebugView(state.view)) ImGui::TextWrapped("%s", view->legend.c_str());
    if (state.view != "final" && renderer.pipeline() == PipelineKind::Forward)
        ImGui::TextWrapped("(forward draws no G-buffer; G-buffer views come from the deferred geometry passes)");

    float hour = float(scene.hour ? *scene.hour : hourAtTime(scene.timeSeconds));
    if (ImGui::SliderFloat("time of day (h)", &hour, 0.0f, 24.0f, "%.2f")) scene.hour = hour;
    if (scene.hour && ImGui::Button("follow the clock")) scene.hour.reset();
    ImGui::Checkbox("pause (Space)", &state.paused);
    ImGui::Text("time %.1f s", scene.timeSeconds);

    ImGui::Checkbox("free camera (WASD, arrows, Q/E)", &state.freeCamera);
    CameraPose& pose = *scene.camera;
    float position[3] = {float(pose.position.x), float(pose.position.y), float(pose.position.z)};
    if (ImGui::DragFloat3("camera", position, 1.0f)) {
        pose.position = glm::dvec3(position[0], position[1], position[2]);
        state.freeCamera = true;
    }
    if (ImGui::SliderFloat("yaw", &pose.yawDegrees, -180.0f, 360.0f)) state.freeCamera = true;
    if (ImGui::SliderFloat("pitch", &pose.pitchDegrees, -89.0f, 89.0f)) state.freeCamera = true;

    if (ImGui::CollapsingHeader("water", ImGuiTreeNodeFlags_DefaultOpen)) {
        WaterSettings& water = scene.water;
        ImGui::Checkbox("reflections", &water.reflections);
        ImGui::SliderFloat("level", &water.level, -20.0f, 30.0f);
        ImGui::ColorEdit3("tint", &water.tint.x);
        ImGui::SliderFloat("absorption", &water.absorption, 0.0f, 0.5f);
        ImGui::SliderFloat("ripples", &water.rippleStrength, 0.0f, 4.0f);
    }
    if (ImGui::CollapsingHeader("vegetation", ImGuiTreeNodeFlags_DefaultOpen)) {
        VegetationSettings& vegetation = scene.vegetation;
        ImGui::Checkbox("plants (V)", &vegetation.enabled);
        // Density re-places every chunk when released, so it is applied on release, not per drag step.
        static float density = vegetation.density;
        ImGui::SliderFloat("density", &density, 0.0f, VegetationSettings::kMaxDensity, "%.2f");
        if (ImGui::IsItemDeactivatedAfterEdit()) vegetation.density = density;
        ImGui::SliderFloat("wind", &vegetation.windStrength, 0.0f, VegetationSettings::kMaxWindStrength);
        ImGui::SliderFloat("draw distance", &vegetation.drawDistance, 50.0f, 1500.0f, "%.0f");
        ImGui::SliderFloat("thinning from", &vegetation.thinningStart, 10.0f, 600.0f, "%.0f");
        ImGui::TextWrapped("%s", describeVegetation(renderer).c_str());
    }
    drawLightsPanel(renderer, scene);
    ImGui::Separator();
    ImGui::Text("frame %.2f ms (avg %.2f), wall time around glFinish", state.frameMs, state.smoothedMs);
    ImGui::Text("%dx%d, terrain %d triangles", renderer.targets().width(), renderer.targets().height(),
                renderer.geometry().terrainTriangles());
    if (!state.fallbacks.empty() &&
        ImGui::CollapsingHeader("fallbacks (this driver or --force)", ImGuiTreeNodeFlags_DefaultOpen)) {
        for (const std::string& line : state.fallbacks) ImGui::BulletText("%s", line.c_str());
    }
    if (ImGui::Button("reload shaders (R)")) reloadShaders(renderer, state);
    if (!state.message.empty()) ImGui::TextWrapped("%s", state.message.c_str());
    ImGui::End();
}

}  // namespace

int runWindowApp(const Options& options) {
    try {
        WindowContext window(options.scene.width, options.scene.height, "oasis", maxGlVersionFor(options.scene));
        RenderSession session(options);
        Renderer& renderer = *session.renderer;
        renderer.setPipeline(options.pipeline);
        std::printf("oasis: window on %s; stencil view: %s\n", queryContextInfo().summary().c_str(),
                    session.stencilPathReason.c_str());
        std::printf("oasis: %s\n", describePlantAtlas(session).c_str());

        IMGUI_CHECKVERSION();
        ImGui::CreateContext();
        ImGui::GetIO().IniFilename = nullptr;
        ImGui_ImplGlfw_InitForOpenGL(window.window(), true);
        ImGui_ImplOpenGL3_Init("#version 330 core");

        WindowState state;
        state.fallbacks = session.fallbacks();
        for (size_t i = 0; i < gbufferLayouts().size(); ++i)
            if (gbufferLayouts()[i].name == options.scene.gbuffer) state.layoutIndex = i;
        for (size_t i = 0; i < depthConventions().size(); ++i)
            if (depthConventions()[i].name == options.scene.depth) state.depthIndex = i;
        SceneSettings& scene = session.scene;
        state.freeCamera = bool(options.scene.camera);
        scene.camera = options.scene.camera ? *options.scene.camera : defaultCameraPath(scene.terrain, scene.timeSeconds);

        struct Input { Renderer* renderer; WindowState* state; SceneSettings* scene; } input{&renderer, &state, &scene};
        glfwSetWindowUserPointer(window.window(), &input);
        glfwSetKeyCallback(window.window(), [](GLFWwindow* w, int key, int scancode, int action, int mods) {
            ImGui_ImplGlfw_KeyCallback(w, key, scancode, action, mods);
            auto* in = static_cast<Input*>(glfwGetWindowUserPointer(w));
            handleKeys(w, key, action, *in->renderer, *in->state, *in->scene);
        });

        auto last = std::chrono::steady_clock::now();
        while (!glfwWindowShouldClose(window.window())) {
            glfwPollEvents();
            int width = 0, height = 0;
            glfwGetFramebufferSize(window.window(), &width, &height);
            if (width <= 0 || height <= 0) {  // minimised: nothing to draw, wait for the next event
                glfwWaitEvents();
                last = std::chrono::steady_clock::now();
                continue;
            }
            auto now = std::chrono::steady_clock::now();
            float seconds = std::chrono::duration<float>(now - last).count();
            last = now;
            if (!state.paused) scene.timeSeconds += seconds;
            if (state.freeCamera) moveFreeCamera(window.window(), *scene.camera, seconds);
            else *scene.camera = defaultCameraPath(scene.terrain, scene.timeSeconds);

            ImGui_ImplOpenGL3_NewFrame();
            ImGui_ImplGlfw_NewFrame();
            ImGui::NewFrame();
            drawPanel(renderer, scene, state);
            ImGui::Render();

            renderer.setDepthConvention(depthConventions()[state.depthIndex]);
            renderer.configure(width, height, gbufferLayouts()[state.layoutIndex]);
            auto start = std::chrono::steady_clock::now();
            renderer.renderFrame(scene);
            glFinish();
            state.frameMs = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
            state.smoothedMs = state.smoothedMs == 0.0 ? state.frameMs : 0.9 * state.smoothedMs + 0.1 * state.frameMs;
            renderer.renderView(state.view);
            renderer.present(width, height);
            ImGui_ImplOpenGL3_RenderDrawData(ImGui::GetDrawData());
            glfwSwapBuffers(window.window());
        }
        ImGui_ImplOpenGL3_Shutdown();
        ImGui_ImplGlfw_Shutdown();
        ImGui::DestroyContext();
        return 0;
    } catch (const std::exception& error) {
        std::fprintf(stderr, "oasis: %s\n", error.what());
        return 1;
    }
}

}  // namespace oasis
