// The window loop: input, the ImGui panel, one frame, the chosen view, present.
//   Tab pipeline  1..7 views  0 overview  G layout  Z depth convention  R reload shaders
//   V plants  H hide/show the panel  Space pause  Esc quit;  free camera: W/S/A/D, arrows, Q/E
//   the inspector: the values under the cursor, click to pin probes (right click: unpin the last),
//   P prints the probe under the cursor as JSON; the view controls (channel, range, overlay, exposure)
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
#include <map>
#include <stdexcept>

#include "cli/input_domains.h"
#include "commands/overview_overlay.h"
#include "commands/session.h"
#include "commands/window_compare.h"
#include "context/gl_context.h"
#include "gl/frame_capture.h"
#include "debug/error_image.h"
#include "debug/imgui_gl_backend.h"
#include "debug/imgui_gl_labels.h"
#include "debug/debug_views.h"
#include "debug/view_controls.h"
#include "render/encoding_error.h"
#include "render/pixel_probe.h"

namespace oasis {
namespace {

// What the window draws, as the keys and the panel choose it: everything that decides which
// shader programs a frame needs, so going back to a configuration that drew draws again.
struct Configuration {
    PipelineKind pipeline = PipelineKind::Deferred;
    size_t layoutIndex = 0;  // into gbufferLayouts()
    size_t depthIndex = 0;   // into depthConventions(): the one asked for
    std::string view = "final";
    WaterScene waterScene = WaterScene::Direct;  // what the views show at water pixels (M)
    // Scene settings that pick program variants: the light path's, the mirrored ones, the plants'.
    int lightCount = 0;
    std::optional<LightsPath> lightsPath;
    bool reflections = true;
    bool vegetation = true;

    bool operator==(const Configuration& o) const {
        return pipeline == o.pipeline && layoutIndex == o.layoutIndex && depthIndex == o.depthIndex &&
               view == o.view && waterScene == o.waterScene && lightCount == o.lightCount && lightsPath == o.lightsPath &&
               reflections == o.reflections && vegetation == o.vegetation;
    }
    bool operator!=(const Configuration& o) const { return !(*this == o); }
    std::string describe() const {
        return std::string(pipelineName(pipeline)) + ", " + gbufferLayouts()[layoutIndex].name + " G-buffer, " +
               depthConventions()[depthIndex].name + " depth, view " + view + ", " + std::to_string(lightCount) +
               " lights";
    }
};

// The inspector: the probe under the cursor and the pinned ones, and the view controls.
struct Inspector {
    std::optional<glm::ivec2> hovered;   // the framebuffer pixel under the cursor, 0,0 top left
    std::optional<PixelProbe> hoveredProbe;
    std::vector<glm::ivec2> pinned;      // numbered on screen in this order
    std::vector<PixelProbe> pinnedProbes;
    bool printHovered = false;           // P: print the next hovered probe
    int channelChoice = 0;               // 0: the view's own colours; else 1 + ViewChannel
    bool fitRange = true;
    float range[2] = {0.0f, 1.0f};
    bool overlayNan = true, overlayInfinity = true, overlayNegative = false;
    float exposureStops = 0.0f;
    std::optional<ValueStatistics> statistics;  // of the last single view drawn
    bool sectionOpen = false;  // the panel shows the inspector this frame: only then are counts read
    std::vector<std::string> overviewCounts;    // the overview's tiles' counts, while it is shown
    static constexpr size_t kMaxPins = 9;

    ViewControls controls() const {
        ViewControls c;
        if (channelChoice > 0) c.channel = ViewChannel(channelChoice - 1);
        if (channelChoice > 0 && !fitRange && range[0] < range[1]) c.range = std::pair{double(range[0]), double(range[1])};
        c.overlay = (overlayNan ? kOverlayNan : 0u) | (overlayInfinity ? kOverlayInfinity : 0u) |
                    (overlayNegative ? kOverlayNegative : 0u);
        return c;
    }
};

// What happened in the window, printed when it closes (the window tests read it).
struct WindowCounts {
    long framesDrawn = 0, pipelineSwitches = 0, resizes = 0, minimised = 0, switchesUndone = 0;
    // Wall ms of each whole loop iteration (frame(s), views, panel, swap, glFinish), by what it
    // showed: the cost of the comparison modes against single frames (docs/window_cost.sh).
    std::map<std::string, std::vector<double>> loopMs;
    std::vector<std::string> loopOrder;
};

std::string loopSummary(const WindowCounts& counts) {
    std::string text;
    for (const std::string& label : counts.loopOrder) {
        std::vector<double> v = counts.loopMs.at(label);
        std::sort(v.begin(), v.end());
        char part[128];
        std::snprintf(part, sizeof(part), "%s%s %.2f (%zu frames)", text.empty() ? "" : ", ", label.c_str(),
                      v.size() % 2 ? v[v.size() / 2] : 0.5 * (v[v.size() / 2 - 1] + v[v.size() / 2]), v.size());
        text += part;
    }
    return text.empty() ? "none" : text;
}

struct WindowState {
    Configuration chosen;                      // what the keys and the panel ask for
    std::optional<Configuration> lastDrawn;    // the last configuration whose frame was drawn
    bool paused = false;
    bool freeCamera = false;
    bool panelShown = true;
    double frameMs = 0.0, smoothedMs = 0.0;
    std::string message;  // last reload result or error, shown in the panel
    bool messageIsError = false;
    std::vector<std::string> fallbacks;  // the session's fallbacks (printed once at start-up too)
    Inspector inspector;
    WindowComparison comparison;
    std::unique_ptr<Renderer> sideB;  // the comparison's second renderer, made when first needed
    bool draggingDivider = false;
    std::string errorViewSummary;  // an encoding-error view's numbers, for the panel
    WindowCounts counts;
    std::optional<size_t> capturesBefore;  // F9: RenderDoc's capture count when the capture was asked for
};

std::string loopLabel(const WindowState& state) {
    const Configuration& shown = state.lastDrawn ? *state.lastDrawn : state.chosen;
    std::string label = state.comparison.mode == CompareMode::Off ? std::string(pipelineName(shown.pipeline))
                                                                 : compareModeName(state.comparison.mode);
    if (shown.view != "final") label += " view " + shown.view;
    if (state.inspector.sectionOpen) label += " inspector";
    return label;
}

// The chosen configuration with the scene's own settings in it, and back.
Configuration currentConfiguration(const WindowState& state, const SceneSettings& scene) {
    Configuration config = state.chosen;
    config.lightCount = scene.lights.count;
    config.lightsPath = scene.lights.path;
    config.reflections = scene.water.reflections;
    config.vegetation = scene.vegetation.enabled;
    return config;
}

void restoreConfiguration(const Configuration& config, WindowState& state, SceneSettings& scene) {
    state.chosen = config;
    scene.lights.count = config.lightCount;
    scene.lights.path = config.lightsPath;
    scene.water.reflections = config.reflections;
    scene.vegetation.enabled = config.vegetation;
}

void choosePipeline(WindowState& state, PipelineKind kind) {
    if (state.chosen.pipeline == kind) return;
    state.chosen.pipeline = kind;
    ++state.counts.pipelineSwitches;
}

std::vector<std::string> viewNames() {
    std::vector<std::string> names;
    for (const DebugView& view : debugViews()) names.push_back(view.name);
    names.push_back(kOverviewName);
    for (const EncodingErrorView& view : encodingErrorViews()) names.push_back(view.name);
    return names;
}

// Shows `message` in the panel and prints it (once, however many frames repeat it): errors to
// stderr, results to stdout, each line starting "oasis: ".
void report(WindowState& state, const std::string& message, bool isError) {
    if (message == state.message && isError == state.messageIsError) return;
    state.message = message;
    state.messageIsError = isError;
    std::fprintf(isError ? stderr : stdout, "oasis: %s\n", message.c_str());
    std::fflush(isError ? stderr : stdout);
}

void reloadShaders(Renderer& renderer, WindowState& state) {
    ShaderLibrary& shaders = renderer.shaders();
    std::vector<std::string> failures = shaders.reloadAll();
    state.message.clear();  // a reload always reports, even when it repeats the last message
    if (failures.empty()) {
        report(state, "shaders reloaded: " + std::to_string(shaders.programCount()) + " programs rebuilt from " +
                          shaders.directory(), false);
        return;
    }
    report(state, "reload: " + std::to_string(failures.size()) + " of " + std::to_string(shaders.programCount()) +
                      " programs failed and keep their previous version; the first: " + failures.front(), true);
    for (size_t i = 1; i < failures.size(); ++i) std::fprintf(stderr, "oasis: reload: %s\n", failures[i].c_str());
}

// F9 or the panel's button: RenderDoc captures the next presented frame (scene, view and panel);
// its path is reported once written. Without RenderDoc the panel says why nothing happens.
void requestCapture(WindowState& state) {
    std::string why;
    if (!gl::renderDocLoaded(&why)) {
        report(state, "capture: " + why, true);
        return;
    }
    state.capturesBefore = gl::renderDocCaptures().size();
    gl::triggerWindowCapture();
    report(state, "capture: RenderDoc captures the next frame", false);
}

void reportNewCapture(WindowState& state) {
    if (!state.capturesBefore) return;
    std::vector<std::string> captures = gl::renderDocCaptures();
    if (captures.size() <= *state.capturesBefore) return;
    report(state, "RenderDoc capture: " + captures.back(), false);
    state.capturesBefore.reset();
}

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
    if (key == GLFW_KEY_P) state.inspector.printHovered = true;
    if (key == GLFW_KEY_M)
        chosen.waterScene = chosen.waterScene == WaterScene::Direct ? WaterScene::Mirrored : WaterScene::Direct;
    if (key == GLFW_KEY_C) state.comparison.mode = CompareMode((int(state.comparison.mode) + 1) % kCompareModeCount);
    if (key == GLFW_KEY_F9) requestCapture(state);
}

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

// The pinned probes' numbers over the frame, at their pixels.
void drawPinMarkers(GLFWwindow* window, const Inspector& inspector) {
    int windowWidth = 0, windowHeight = 0, width = 0, height = 0;
    glfwGetWindowSize(window, &windowWidth, &windowHeight);
    glfwGetFramebufferSize(window, &width, &height);
    if (width <= 0 || height <= 0) return;
    ImDrawList* draw = ImGui::GetForegroundDrawList();
    for (size_t i = 0; i < inspector.pinned.size(); ++i) {
        ImVec2 at((float(inspector.pinned[i].x) + 0.5f) * float(windowWidth) / float(width),
                  (float(inspector.pinned[i].y) + 0.5f) * float(windowHeight) / float(height));
        draw->AddCircle(at, 6.0f, IM_COL32(255, 0, 255, 255), 12, 2.0f);
        std::string number = std::to_string(i + 1);
        draw->AddRectFilled(ImVec2(at.x + 7, at.y - 16), ImVec2(at.x + 9 + 7.0f * float(number.size()), at.y - 2),
                            IM_COL32(0, 0, 0, 200));
        draw->AddText(ImVec2(at.x + 8, at.y - 16), IM_COL32(255, 255, 255, 255), number.c_str());
    }
}

// The sides' names over the frame: at the top of each half of a split, or over the difference.
void drawCompareLabels(GLFWwindow* window, const WindowComparison& c) {
    if (c.mode == CompareMode::Off) return;
    int windowWidth = 0, windowHeight = 0;
    glfwGetWindowSize(window, &windowWidth, &windowHeight);
    ImDrawList* draw = ImGui::GetForegroundDrawList();
    auto label = [&](float x, const std::string& text) {
        ImVec2 size = ImGui::CalcTextSize(text.c_str());
        x = std::clamp(x, 4.0f, float(windowWidth) - size.x - 8.0f);
        draw->AddRectFilled(ImVec2(x - 3, 4), ImVec2(x + size.x + 3, 8 + size.y), IM_COL32(0, 0, 0, 200));
        draw->AddText(ImVec2(x, 6), IM_COL32(255, 255, 255, 255), text.c_str());
    };
    if (showsDifference(c.mode)) {
        label(float(windowWidth) * 0.5f - 100.0f, "|" + c.a.label + " - " + c.b.label + "|");
        return;
    }
    float dividerX = c.divider * float(windowWidth);
    label(dividerX - 12.0f - 7.0f * float(c.a.label.size() + 4), "A: " + c.a.label);
    label(dividerX + 12.0f, "B: " + c.b.label);
}

// The live comparison's section of the panel: mode, sides, times, the displayed frame's difference.
void drawComparePanel(WindowState& state) {
    WindowComparison& c = state.comparison;
    if (!ImGui::CollapsingHeader("compare (live A/B)", ImGuiTreeNodeFlags_DefaultOpen)) return;
    int mode = int(c.mode);
    if (ImGui::BeginCombo("mode", compareModeName(c.mode))) {
        for (int m = 0; m < kCompareModeCount; ++m)
            if (ImGui::Selectable(compareModeName(CompareMode(m)), m == mode)) c.mode = CompareMode(m);
        ImGui::EndCombo();
    }
    if (c.mode == CompareMode::Off) return;
    const auto& layouts = gbufferLayouts();
    if (comparesLayouts(c.mode) && ImGui::BeginCombo("layout B", layouts[c.layoutB].name.c_str())) {
        for (size_t i = 0; i < layouts.size(); ++i)
            if (ImGui::Selectable(layouts[i].name.c_str(), i == c.layoutB)) c.layoutB = i;
        ImGui::EndCombo();
    }
    if (!showsDifference(c.mode)) ImGui::SliderFloat("divider (or drag it)", &c.divider, 0.0f, 1.0f, "%.2f");
    ImGui::Checkbox("per-pass times", &c.passTimes);
    if (c.passTimes && c.clock) ImGui::TextWrapped("pass clock: %s", c.clock->describe().c_str());
    ImGui::Text("A %-24s median %7.2f ms", c.a.label.c_str(), c.msA.median());
    ImGui::Text("B %-24s median %7.2f ms", c.b.label.c_str(), c.msB.median());
    ImGui::TextDisabled("medians of the last %zu frames each; reset when a setting changes", c.msA.count());
    ImGui::Text("displayed: PSNR %.2f dB%s, max abs %d, RMSE %.4f (8-bit RGB)", c.difference.psnrDb,
                c.difference.psnrDb >= kPsnrIdentical ? " (identical)" : "", c.difference.maxAbs, c.difference.rmse);
    if (showsDifference(c.mode)) {
        // The heat map's scale: black 0, red, yellow, white at 16 levels of 255 or more.
        ImDrawList* draw = ImGui::GetWindowDrawList();
        ImVec2 at = ImGui::GetCursorScreenPos();
        float width = ImGui::GetContentRegionAvail().x, height = 12.0f;
        for (int i = 0; i < 32; ++i) {
            uint8_t left[3], right[3];
            differenceHeatColour(float(i) / 32.0f, left);
            differenceHeatColour(float(i + 1) / 32.0f, right);
            ImU32 l = IM_COL32(left[0], left[1], left[2], 255), r = IM_COL32(right[0], right[1], right[2], 255);
            draw->AddRectFilledMultiColor(ImVec2(at.x + width * float(i) / 32.0f, at.y),
                                          ImVec2(at.x + width * float(i + 1) / 32.0f + 1.0f, at.y + height), l, r, r, l);
        }
        ImGui::Dummy(ImVec2(width, height));
        ImGui::Text("0");
        ImGui::SameLine(width * 0.5f);
        ImGui::Text("8");
        ImGui::SameLine(width - 24.0f);
        ImGui::Text("16+");
    }
    if (c.passTimes && (!c.passesA.empty() || !c.passesB.empty()) &&
        ImGui::BeginTable("passes", 4, ImGuiTableFlags_RowBg | ImGuiTableFlags_SizingStretchProp)) {
        ImGui::TableSetupColumn("A pass");
        ImGui::TableSetupColumn("ms");
        ImGui::TableSetupColumn("B pass");
        ImGui::TableSetupColumn("ms");
        ImGui::TableHeadersRow();
        for (size_t i = 0; i < std::max(c.passesA.size(), c.passesB.size()); ++i) {
            ImGui::TableNextRow();
            for (const auto* passes : {&c.passesA, &c.passesB}) {
                ImGui::TableNextColumn();
                if (i < passes->size()) ImGui::TextUnformatted((*passes)[i].first.c_str());
                ImGui::TableNextColumn();
                if (i < passes->size()) ImGui::Text("%.2f", (*passes)[i].second);
            }
        }
        ImGui::EndTable();
    }
}

// One line of a probe for the pinned list.
std::string probeSummary(const PixelProbe& p) {
    char line[256];
    if (p.sky)
        std::snprintf(line, sizeof(line), "%d,%d sky; final %d %d %d; stencil %d", p.x, p.y, p.final.r, p.final.g,
                      p.final.b, p.stencil);
    else
        std::snprintf(line, sizeof(line), "%d,%d %s; final %d %d %d; depth %.4g; n %.3f %.3f %.3f; lights %d; sun %.2f (cascade %d)",
                      p.x, p.y, p.stencilMeaning.c_str(), p.final.r, p.final.g, p.final.b, p.depthEyeDistance, p.normal.x,
                      p.normal.y, p.normal.z, p.lightsReaching, double(p.shadowLit), p.shadowCascade);
    return line;
}

void drawOverlayChoices(Inspector& inspector) {
    ImGui::Checkbox("NaN", &inspector.overlayNan);
    ImGui::SameLine();
    ImGui::Checkbox("+-Inf", &inspector.overlayInfinity);
    ImGui::SameLine();
    ImGui::Checkbox("negative (overlay)", &inspector.overlayNegative);
}

// The inspector's section of the panel: view controls, value counts, the probes.
void drawInspectorPanel(WindowState& state) {
    Inspector& inspector = state.inspector;
    inspector.sectionOpen = ImGui::CollapsingHeader("inspector (hover, click to pin, P prints)", ImGuiTreeNodeFlags_DefaultOpen);
    if (!inspector.sectionOpen) return;
    const DebugView* view = findDebugView(state.chosen.view);
    if (view) {
        std::vector<std::string> choices = {"the view's colours"};
        for (int c = 0; c <= int(ViewChannel::Luminance); ++c)
            choices.push_back(viewHasChannel(*view, ViewChannel(c)) ? "values: " + describeChannel(*view, ViewChannel(c))
                                                                    : std::string());
        if (inspector.channelChoice > 0 && choices[size_t(inspector.channelChoice)].empty()) inspector.channelChoice = 0;
        if (ImGui::BeginCombo("channel", choices[size_t(inspector.channelChoice)].c_str())) {
            for (size_t i = 0; i < choices.size(); ++i)
                if (!choices[i].empty() && ImGui::Selectable(choices[i].c_str(), int(i) == inspector.channelChoice))
                    inspector.channelChoice = int(i);
            ImGui::EndCombo();
        }
        if (inspector.channelChoice > 0) {
            ImGui::Checkbox("fit the range to the frame", &inspector.fitRange);
            if (!inspector.fitRange) ImGui::DragFloat2("range", inspector.range, 0.01f);
        }
        drawOverlayChoices(inspector);
        if (view->remapDefine == "VIEW_HDR") ImGui::SliderFloat("exposure (stops)", &inspector.exposureStops, -20.0f, 20.0f);
        if (inspector.statistics) {
            const ValueStatistics& s = *inspector.statistics;
            ImGui::TextWrapped("values: NaN %ld, +Inf %ld, -Inf %ld, negative %ld of %ld; finite %.4g .. %.4g", s.nan,
                               s.positiveInfinity, s.negativeInfinity, s.negative, s.values, s.min, s.max);
        }
    } else if (state.chosen.view == kOverviewName) {
        drawOverlayChoices(inspector);
        for (const std::string& line : inspector.overviewCounts) ImGui::TextWrapped("%s", line.c_str());
    }
    if (inspector.hoveredProbe) {
        if (ImGui::TreeNodeEx("under the cursor", ImGuiTreeNodeFlags_DefaultOpen)) {
            ImGui::TextUnformatted(probeText(*inspector.hoveredProbe).c_str());
            ImGui::TreePop();
        }
    } else {
        ImGui::TextDisabled("move the cursor over the frame to probe it");
    }
    for (size_t i = 0; i < inspector.pinnedProbes.size(); ++i) {
        std::string label = "#" + std::to_string(i + 1) + " " + probeSummary(inspector.pinnedProbes[i]);
        if (ImGui::TreeNode(label.c_str())) {
            ImGui::TextUnformatted(probeText(inspector.pinnedProbes[i]).c_str());
            ImGui::TreePop();
        }
    }
    if (!inspector.pinned.empty() && ImGui::Button("unpin all")) inspector.pinned.clear();
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
    if (!ImGui::CollapsingHeader("lights")) return;
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
    size_t& chosen = state.chosen.depthIndex;
    if (ImGui::BeginCombo("depth (Z)", conventions[chosen].name.c_str())) {
        for (size_t i = 0; i < conventions.size(); ++i) {
            std::string label = conventions[i].name + " (" + std::to_string(conventions[i].depthStencil.bytesPerPixel) + " B/px)";
            if (ImGui::Selectable(label.c_str(), i == chosen)) chosen = i;
        }
        ImGui::EndCombo();
    }
    if (renderer.depthFellBack()) ImGui::TextWrapped("depth: %s", renderer.depthConventionReason().c_str());
}

// Which scene the views show under the water (render/view_fill.h), and what the view shows there.
void drawWaterSceneControl(const Renderer& renderer, Configuration& chosen) {
    int scene = chosen.waterScene == WaterScene::Direct ? 0 : 1;
    ImGui::TextUnformatted("under the water (M):");
    ImGui::SameLine();
    if (ImGui::RadioButton("direct", &scene, 0)) chosen.waterScene = WaterScene::Direct;
    ImGui::SameLine();
    if (ImGui::RadioButton("mirrored", &scene, 1)) chosen.waterScene = WaterScene::Mirrored;
    const ViewScene& shown = renderer.viewScene();
    if (const DebugView* view = findDebugView(chosen.view))
        ImGui::TextWrapped("%s", waterNote(*view, shown.description).c_str());
    else if (!shown.description.empty())
        ImGui::TextWrapped("the G-buffer, depth and error tiles under the water: %s", shown.description.c_str());
    if (!shown.reason.empty()) ImGui::TextWrapped("(%s)", shown.reason.c_str());
}

void drawPanel(Renderer& renderer, SceneSettings& scene, WindowState& state) {
    ImGui::SetNextWindowPos(ImVec2(10, 10), ImGuiCond_FirstUseEver);
    // Wide enough for the probe's lines, as tall as the window allows (the sections collapse).
    ImGui::SetNextWindowSize(ImVec2(480.0f, std::max(200.0f, ImGui::GetIO().DisplaySize.y - 20.0f)), ImGuiCond_FirstUseEver);
    ImGui::Begin("oasis");
    // The reload result first: a shader error must be seen without scrolling a small window.
    if (ImGui::Button("reload shaders (R)")) reloadShaders(renderer, state);
    ImGui::SameLine();
    if (ImGui::Button("capture next frame (F9)")) requestCapture(state);
    if (state.messageIsError) ImGui::PushStyleColor(ImGuiCol_Text, ImVec4(1.0f, 0.4f, 0.2f, 1.0f));
    if (!state.message.empty()) ImGui::TextWrapped("%s", state.message.c_str());
    if (state.messageIsError) ImGui::PopStyleColor();
    Configuration& chosen = state.chosen;
    int pipeline = chosen.pipeline == PipelineKind::Forward ? 0 : 1;
    if (ImGui::RadioButton("forward", &pipeline, 0)) choosePipeline(state, PipelineKind::Forward);
    ImGui::SameLine();
    if (ImGui::RadioButton("deferred", &pipeline, 1)) choosePipeline(state, PipelineKind::Deferred);
    ImGui::SameLine();
    ImGui::TextDisabled("(Tab)");
    ImGui::Text("frame %.2f ms (avg %.2f), wall time around glFinish", state.frameMs, state.smoothedMs);
    drawComparePanel(state);

    const auto& layouts = gbufferLayouts();
    if (ImGui::BeginCombo("G-buffer (G)", layouts[chosen.layoutIndex].name.c_str())) {
        for (size_t i = 0; i < layouts.size(); ++i) {
            std::string label = layouts[i].name + " (" + std::to_string(layouts[i].bytesPerPixel()) + " B/px)";
            if (ImGui::Selectable(label.c_str(), i == chosen.layoutIndex)) chosen.layoutIndex = i;
        }
        ImGui::EndCombo();
    }
    drawDepthCombo(renderer, state);
    if (ImGui::BeginCombo("view", chosen.view.c_str())) {
        for (const std::string& name : viewNames())
            if (ImGui::Selectable(name.c_str(), name == chosen.view)) chosen.view = name;
        ImGui::EndCombo();
    }
    if (const DebugView* view = findDebugView(chosen.view)) ImGui::TextWrapped("%s", view->legend.c_str());
    if (const EncodingErrorView* view = findEncodingErrorView(chosen.view)) {
        ImGui::TextWrapped("%s (deferred, this layout against full; ramp from 0 to the frame's largest error, "
                           "dark grey: no common surface)", view->legend.c_str());
        if (!state.errorViewSummary.empty()) ImGui::TextWrapped("%s", state.errorViewSummary.c_str());
    }
    if (chosen.view != "final" && chosen.pipeline == PipelineKind::Forward)
        ImGui::TextWrapped("(forward draws no G-buffer; G-buffer views come from the deferred geometry passes)");
    drawWaterSceneControl(renderer, chosen);
    drawInspectorPanel(state);

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

    if (ImGui::CollapsingHeader("shadows")) {
        ShadowSettings& shadows = scene.shadows;
        ImGui::Checkbox("sun shadows", &shadows.enabled);
        for (const ShadowQuality& quality : shadowQualities()) {
            ImGui::SameLine();
            if (ImGui::RadioButton(quality.name, shadows.quality == quality.name)) shadows.quality = quality.name;
        }
        const FrameSetup& frame = renderer.lastFrame();
        ImGui::Text("%s", !shadows.enabled ? "off" : frame.shadowsActive ? "drawn this frame" : "sun below the horizon: no shadow pass");
    }
    if (ImGui::CollapsingHeader("water")) {
        WaterSettings& water = scene.water;
        ImGui::Checkbox("reflections", &water.reflections);
        ImGui::Checkbox("reflection bounded to the visible water", &water.reflectionBounds);
        ImGui::TextUnformatted("reflection resolution");
        for (const ReflectionResolution& resolution : kReflectionResolutions) {
            ImGui::SameLine();
            if (ImGui::RadioButton(resolution.name, water.reflectionDivisor == resolution.divisor))
                water.reflectionDivisor = resolution.divisor;
        }
        ImGui::SliderFloat("level", &water.level, -20.0f, 30.0f);
        ImGui::ColorEdit3("tint", &water.tint.x);
        ImGui::SliderFloat("absorption", &water.absorption, 0.0f, 0.5f);
        ImGui::SliderFloat("ripples", &water.rippleStrength, 0.0f, 4.0f);
    }
    if (ImGui::CollapsingHeader("vegetation")) {
        VegetationSettings& vegetation = scene.vegetation;
        ImGui::Checkbox("plants (V)", &vegetation.enabled);
        // Density re-places every chunk when released, so it is applied on release, not per drag step.
        static float density = vegetation.density;
        ImGui::SliderFloat("density", &density, 0.0f, VegetationSettings::kMaxDensity, "%.2f");
        if (ImGui::IsItemDeactivatedAfterEdit()) vegetation.density = density;
        ImGui::SliderFloat("wind", &vegetation.windStrength, 0.0f, VegetationSettings::kMaxWindStrength);
        ImGui::SliderFloat("draw distance", &vegetation.drawDistance, 50.0f, 1500.0f, "%.0f");
        ImGui::SliderFloat("thinning from", &vegetation.thinningStart, 10.0f, 600.0f, "%.0f");
        ImGui::Checkbox("billboards trimmed to the drawn plant", &vegetation.trimmedBillboards);
        ImGui::TextWrapped("%s", describeVegetation(renderer).c_str());
    }
    drawLightsPanel(renderer, scene);
    if (ImGui::CollapsingHeader("frame work")) {
        // Savings that keep the picture: switch one off to see what it saves (the pass times).
        ImGui::Checkbox("tone map fused into the last colour passes", &scene.work.fuseToneMap);
        ImGui::Checkbox("compact: lighting reads depth in place", &scene.work.depthReadInPlace);
        ImGui::TextUnformatted("reflected plants culled on dry land:");
        for (const MirroredPlantCullMode& mode : kMirroredPlantCullModes) {
            ImGui::SameLine();
            if (ImGui::RadioButton(mode.name, scene.work.mirroredPlantCull == mode.mode))
                scene.work.mirroredPlantCull = mode.mode;
        }
    }
    ImGui::Separator();
    ImGui::Text("%dx%d, terrain %d triangles", renderer.targets().width(), renderer.targets().height(),
                renderer.geometry().terrainTriangles());
    if (!state.fallbacks.empty() &&
        ImGui::CollapsingHeader("fallbacks (this driver or --force)", ImGuiTreeNodeFlags_DefaultOpen)) {
        for (const std::string& line : state.fallbacks) ImGui::BulletText("%s", line.c_str());
    }
    ImGui::End();
}

// P: the probe under the cursor as one JSON line (scripts and the window tests read it).
void printHoveredProbe(Inspector& inspector) {
    if (!inspector.printHovered || !inspector.hoveredProbe) return;
    std::printf("oasis: probe %s\n", probeJson(*inspector.hoveredProbe).c_str());
    std::fflush(stdout);
    inspector.printHovered = false;
}

// After a view is drawn: its values through the view controls (and the overlay where any value
// needs it) into Display, and the probes of the pixels hovered and pinned.
// An encoding-error view as the window's frame: the layout's deferred frame against full's (two
// more frames), on the depth ramp from 0 to the largest error, as `oasis render` draws it.
void showEncodingError(Renderer& renderer, const SceneSettings& scene, const EncodingErrorView& view,
                       WindowState& state) {
    if (renderer.targets().layout().name == "full") {
        state.errorViewSummary = view.name + " compares a layout against full: choose standard or compact (G)";
        renderer.renderView("final");
        return;
    }
    EncodingError error = measureEncodingError(renderer, scene, renderer.targets().layout());
    const std::vector<float>& values = error.*(view.values);
    ErrorSummary summary = summarizeError(values);
    char line[256];
    std::snprintf(line, sizeof(line), "%s against full: median %.4g, 99%% %.4g, max %.4g over %ld surface pixels",
                  error.layout.c_str(), summary.median, summary.p99, summary.max, summary.count);
    state.errorViewSummary = line;
    renderer.showImage(encodingErrorPicture(values, error.width, error.height, 0.0, summary.max > 0.0 ? summary.max : 1.0));
}

void inspectFrame(Renderer& renderer, const Configuration& config, Inspector& inspector) {
    inspector.statistics.reset();
    const DebugView* view = findDebugView(config.view);
    ViewControls controls = inspector.controls();
    // The values pass and its full-frame float read-back cost a frame's worth of bandwidth: only
    // while someone looks at the counts or asks for the values.
    if (view && (inspector.sectionOpen || controls.showValues())) {
        std::vector<float> values = renderer.readViewValues(view->name);
        ViewChannel channel = controls.channel.value_or(defaultChannel(*view));
        ValueStatistics statistics = valueStatistics(values, channel);
        const FrameTargets& targets = renderer.targets();
        if (controls.showValues()) {
            renderer.showImage(mapViewValues(values, targets.width(), targets.height(), channel,
                                             rangeInUse(controls, statistics), controls.overlay));
        } else if (((controls.overlay & kOverlayNan) && statistics.nan) ||
                   ((controls.overlay & kOverlayInfinity) && (statistics.positiveInfinity || statistics.negativeInfinity)) ||
                   ((controls.overlay & kOverlayNegative) && statistics.negative)) {
            Image image = renderer.readDisplay();
            paintOverlay(image, values, channel, controls.overlay);
            renderer.showImage(image);
        }
        inspector.statistics = statistics;
    }
    // The overview's tiles get their overlays too, while the inspector section is open (13 reads).
    inspector.overviewCounts.clear();
    if (config.view == kOverviewName && inspector.sectionOpen && controls.overlay) {
        Image image = renderer.readDisplay();
        inspector.overviewCounts = overlayOverviewTiles(image, renderer, controls.overlay);
        renderer.showImage(image);
    }
    auto inside = [&](glm::ivec2 p) { return p.x < renderer.targets().width() && p.y < renderer.targets().height(); };
    // Probing a forward frame fills its G-buffer first: only while the panel shows the probes, or P asks.
    inspector.hoveredProbe.reset();
    if (inspector.hovered && inside(*inspector.hovered) && (inspector.sectionOpen || inspector.printHovered))
        inspector.hoveredProbe = probePixel(renderer, inspector.hovered->x, inspector.hovered->y);
    inspector.pinnedProbes.clear();
    for (glm::ivec2 pin : inspector.pinned)
        if (inside(pin) && inspector.sectionOpen) inspector.pinnedProbes.push_back(probePixel(renderer, pin.x, pin.y));
    printHoveredProbe(inspector);
}

// One frame of `config` into the window's framebuffer (not yet swapped). Throws ShaderBuildError
// when a program it needs does not build; the scene must already hold the config's settings.
// What the comparison's medians were measured for: the configuration, the size and the scene's
// settings (the clock and the camera's flight are not changes: they move every frame).
std::string comparisonKey(const Configuration& config, const SceneSettings& scene, int width, int height,
                          const WindowComparison& c) {
    char key[512];
    std::snprintf(key, sizeof(key), "%s|%dx%d|%d %zu %d|%g %d %g %g|%d %g %g|%g", config.describe().c_str(), width,
                  height, int(c.mode), c.layoutB, int(c.passTimes), scene.water.level, int(scene.water.reflections),
                  scene.water.rippleStrength, scene.water.absorption, int(scene.vegetation.enabled),
                  scene.vegetation.density, scene.vegetation.windStrength, scene.hour ? *scene.hour : -1.0);
    return key;
}

// Both sides of the live comparison, each on its own renderer (no reallocation between them),
// timed, then shown split or as their difference; the probes read side A.
void drawComparison(RenderSession& session, const Configuration& config, const SceneSettings& scene, int width,
                    int height, WindowState& state) {
    WindowComparison& c = state.comparison;
    if (!state.sideB) state.sideB = session.makeRenderer();
    c.chooseSides(config.pipeline, config.layoutIndex);
    c.noteSettings(comparisonKey(config, scene, width, height, c));
    Renderer* renderers[2] = {session.renderer.get(), state.sideB.get()};
    const CompareSide* sides[2] = {&c.a, &c.b};
    RollingMedian* medians[2] = {&c.msA, &c.msB};
    std::vector<std::pair<std::string, double>>* passes[2] = {&c.passesA, &c.passesB};
    PassTimerQueries* queries[2] = {&c.queriesA, &c.queriesB};
    if (c.passTimes && !c.clock) c.clock = session.timingClock();  // once: a few frames of each clock
    Image images[2];
    state.frameMs = 0.0;
    for (int s = 0; s < 2; ++s) {
        Renderer& renderer = *renderers[s];
        renderer.setPipeline(sides[s]->pipeline);
        renderer.setDepthConvention(depthConventions()[config.depthIndex]);
        renderer.configure(width, height, gbufferLayouts()[sides[s]->layoutIndex]);
        renderer.setViewExposure(state.inspector.exposureStops);
        renderer.setViewWaterScene(config.waterScene);
        glFinish();
        auto start = std::chrono::steady_clock::now();
        if (c.passTimes && c.clock->gpuTimers) {
            // Queries read a few frames later, never waited for: the table lags by those frames.
            queries[s]->timeFrame(renderer, scene);
            glFinish();
            *passes[s] = queries[s]->latest();
        } else if (c.passTimes) {
            *passes[s] = renderer.renderFrameTimingPasses(scene);
        } else {
            renderer.renderFrame(scene);
            glFinish();
        }
        double ms = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
        medians[s]->add(ms);
        state.frameMs += ms;
        // The comparison shows the table's views; an encoding-error view is a comparison of its own.
        renderer.renderView(findEncodingErrorView(config.view) ? std::string("final") : config.view);
        images[s] = renderer.readDisplay();
    }
    state.smoothedMs = state.smoothedMs == 0.0 ? state.frameMs : 0.9 * state.smoothedMs + 0.1 * state.frameMs;
    c.difference = compareImages(images[0], images[1]);
    Renderer& shown = *renderers[0];
    shown.showImage(showsDifference(c.mode) ? differenceHeatmap(images[0], images[1])
                                            : splitImage(images[0], images[1], int(std::lround(c.divider * float(width)))));
    Inspector& inspector = state.inspector;
    inspector.statistics.reset();
    inspector.hoveredProbe.reset();
    inspector.pinnedProbes.clear();
    auto inside = [&](glm::ivec2 p) { return p.x < width && p.y < height; };
    if (inspector.hovered && inside(*inspector.hovered) && (inspector.sectionOpen || inspector.printHovered))
        inspector.hoveredProbe = probePixel(shown, inspector.hovered->x, inspector.hovered->y);
    for (glm::ivec2 pin : inspector.pinned)
        if (inside(pin) && inspector.sectionOpen) inspector.pinnedProbes.push_back(probePixel(shown, pin.x, pin.y));
    printHoveredProbe(inspector);
    shown.present(width, height);
}

void drawConfiguration(RenderSession& session, const Configuration& config, const SceneSettings& scene, int width,
                       int height, WindowState& state) {
    if (state.comparison.mode != CompareMode::Off) {
        drawComparison(session, config, scene, width, height, state);
        return;
    }
    Renderer& renderer = *session.renderer;
    renderer.setPipeline(config.pipeline);
    renderer.setDepthConvention(depthConventions()[config.depthIndex]);
    renderer.configure(width, height, gbufferLayouts()[config.layoutIndex]);
    auto start = std::chrono::steady_clock::now();
    renderer.renderFrame(scene);
    glFinish();
    state.frameMs = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
    state.smoothedMs = state.smoothedMs == 0.0 ? state.frameMs : 0.9 * state.smoothedMs + 0.1 * state.frameMs;
    renderer.setViewExposure(state.inspector.exposureStops);
    renderer.setViewWaterScene(config.waterScene);
    if (const EncodingErrorView* errorView = findEncodingErrorView(config.view))
        showEncodingError(renderer, scene, *errorView, state);
    else
        renderer.renderView(config.view);
    inspectFrame(renderer, config, state.inspector);
    renderer.present(width, height);
}

// Draws the chosen configuration; when a program it needs does not build, says why, goes back to
// the last configuration that drew and draws that. False when nothing could be drawn. On the
// first frame there is nothing to go back to: the error ends the window (exit 1).
bool drawChosen(RenderSession& session, SceneSettings& scene, WindowState& state, int width, int height) {
    const Configuration wanted = currentConfiguration(state, scene);
    try {
        drawConfiguration(session, wanted, scene, width, height, state);
        state.lastDrawn = wanted;
        return true;
    } catch (const ShaderBuildError& error) {
        if (!state.lastDrawn) throw;
        if (wanted == *state.lastDrawn) {  // the scene itself changed (e.g. the camera rose out of the water)
            report(state, "cannot draw " + wanted.describe() + ": " + error.what(), true);
            return false;
        }
        report(state, "cannot switch to " + wanted.describe() + "; drawing " + state.lastDrawn->describe() +
                          " instead: " + error.what(), true);
        ++state.counts.switchesUndone;
        restoreConfiguration(*state.lastDrawn, state, scene);
    }
    try {
        drawConfiguration(session, *state.lastDrawn, scene, width, height, state);
        return true;
    } catch (const ShaderBuildError& error) {
        report(state, "cannot draw " + state.lastDrawn->describe() + ": " + error.what(), true);
        return false;
    }
}

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
        for (size_t i = 0; i < gbufferLayouts().size(); ++i)
            if (gbufferLayouts()[i].name == options.scene.gbuffer) state.chosen.layoutIndex = i;
        for (size_t i = 0; i < depthConventions().size(); ++i)
            if (depthConventions()[i].name == options.scene.depth) state.chosen.depthIndex = i;
        SceneSettings& scene = session.scene;
        state.freeCamera = bool(options.scene.camera);
        scene.camera = options.scene.camera ? *options.scene.camera : defaultCameraPath(scene.terrain, scene.timeSeconds);

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
