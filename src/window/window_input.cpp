// The window's input: the keys (Tab, 1..7, 0, G, Z, R, V, H, O, P, I, F, M, C, F9, Space, Esc), the mouse
// over the frame (hover to probe, click to pin, drag the split's divider) and the free camera.
#include "window/window_state.h"

#include <GLFW/glfw3.h>
#include <imgui.h>

#include <algorithm>
#include <cmath>
#include <cstdio>

namespace oasis {
namespace window {

void handleKeys(GLFWwindow* window, int key, int action, Renderer& renderer, WindowState& state,
                SceneSettings& scene) {
    // Only a text field being edited keeps the keys: after a click on the panel (which focuses it)
    // the view and pipeline keys must still work.
    if (action != GLFW_PRESS || ImGui::GetIO().WantTextInput) return;
    const auto& views = debugViews();
    Configuration& chosen = state.chosen;
    if (key == GLFW_KEY_ESCAPE) glfwSetWindowShouldClose(window, GLFW_TRUE);
    if (key == GLFW_KEY_TAB)
        choosePipeline(state, chosen.pipeline == PipelineKind::Forward ? PipelineKind::Deferred : PipelineKind::Forward);
    if (key >= GLFW_KEY_1 && key < GLFW_KEY_1 + int(views.size())) chosen.view = views[size_t(key - GLFW_KEY_1)].name;
    if (key == GLFW_KEY_0) chosen.view = kOverviewName;
    if (key == GLFW_KEY_SPACE) {
        state.paused = !state.paused;
        // The clock moves the sun (without --hour) and the clouds: the time given here, with the
        // same scene options, renders the paused frame headless.
        if (state.paused) std::printf("oasis: paused at --time %.17g\n", scene.timeSeconds);
        else std::printf("oasis: clock running\n");
        std::fflush(stdout);
    }
    if (key == GLFW_KEY_R) reloadShaders(renderer, state);
    if (key == GLFW_KEY_G) chosen.layoutIndex = (chosen.layoutIndex + 1) % gbufferLayouts().size();
    if (key == GLFW_KEY_Z) chosen.depthIndex = (chosen.depthIndex + 1) % depthConventions().size();
    if (key == GLFW_KEY_V) scene.vegetation.enabled = !scene.vegetation.enabled;
    if (key == GLFW_KEY_H) state.panelShown = !state.panelShown;
    if (key == GLFW_KEY_O) state.overlayShown = !state.overlayShown;
    if (key == GLFW_KEY_P) state.inspector.printHovered = true;
    if (key == GLFW_KEY_I) state.inspector.deepRequested = true;
    if (key == GLFW_KEY_F) {  // the values printed when frozen are the ones printed when thawed
        Inspector& inspector = state.inspector;
        inspector.frozen = !inspector.frozen;
        inspector.frozenAt = scene.timeSeconds;
        printPins(inspector, inspector.frozen ? "pin frozen" : "pin thawed, it held");
    }
    if (key == GLFW_KEY_M)
        chosen.waterScene = chosen.waterScene == WaterScene::Direct ? WaterScene::Mirrored : WaterScene::Direct;
    if (key == GLFW_KEY_C) state.comparison.mode = CompareMode((int(state.comparison.mode) + 1) % kCompareModeCount);
    if (key == GLFW_KEY_F9) requestCapture(state);
}

namespace {

// The cursor's framebuffer pixel (0,0 top left) when it is over the frame and not over the panel.
std::optional<glm::ivec2> pixelUnderCursor(GLFWwindow* window) {
    if (ImGui::GetIO().WantCaptureMouse) return std::nullopt;
    double cx = 0.0, cy = 0.0;
    glfwGetCursorPos(window, &cx, &cy);
    int windowWidth = 0, windowHeight = 0, width = 0, height = 0;
    glfwGetWindowSize(window, &windowWidth, &windowHeight);
    glfwGetFramebufferSize(window, &width, &height);
    if (windowWidth <= 0 || windowHeight <= 0) return std::nullopt;
    int x = int(std::floor(cx * width / windowWidth)), y = int(std::floor(cy * height / windowHeight));
    if (x < 0 || y < 0 || x >= width || y >= height) return std::nullopt;
    return glm::ivec2(x, y);
}

}  // namespace

// Mouse: hover to probe, click to pin (numbered), right click to unpin the last.
void handleInspectorMouse(GLFWwindow* window, Inspector& inspector, WindowComparison& comparison, bool& dragging) {
    inspector.hovered = pixelUnderCursor(window);
    if (!ImGui::IsMouseDown(ImGuiMouseButton_Left)) dragging = false;
    if (!inspector.hovered) return;
    // In a split view a press near the divider drags it; anywhere else it pins a probe.
    int width = 0, height = 0;
    glfwGetFramebufferSize(window, &width, &height);
    bool split = comparison.mode == CompareMode::SplitPipelines || comparison.mode == CompareMode::SplitLayouts;
    if (split && ImGui::IsMouseClicked(ImGuiMouseButton_Left) &&
        std::abs(inspector.hovered->x - int(comparison.divider * float(width))) <= 8)
        dragging = true;
    if (dragging) {
        comparison.divider = std::clamp(float(inspector.hovered->x) / float(std::max(width, 1)), 0.0f, 1.0f);
        return;
    }
    if (ImGui::IsMouseClicked(ImGuiMouseButton_Left) && inspector.pinned.size() < Inspector::kMaxPins)
        inspector.pinned.push_back(*inspector.hovered);
    if (ImGui::IsMouseClicked(ImGuiMouseButton_Right) && !inspector.pinned.empty()) inspector.pinned.pop_back();
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

}  // namespace window
}  // namespace oasis
