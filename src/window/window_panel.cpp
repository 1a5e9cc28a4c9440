// The window's ImGui panel: pipeline, G-buffer, depth, view, time, camera and the scene's option
// sections (shadows, water, vegetation, frame work: widgets made from cli/option_table.h's rows).
#include "window/window_state.h"

#include <imgui.h>
#include <imgui_internal.h>  // the panel's measures (notePanelGeometry)

#include <algorithm>
#include <cstdio>
#include <map>

#include "cli/option_table.h"
#include "frame/encoding_error.h"

namespace oasis {
namespace window {

namespace {

constexpr float kPanelWidth = 340.0f;  // at first; the panel is resizable

// A slider whose value rebuilds scene content shows its drag here and applies it on release.
float& pendingValue(const char* flag, float value) {
    static std::map<std::string, float> pending;
    return pending.try_emplace(flag, value).first->second;
}

// The widgets of the option rows (cli/option_table.h) in one section of the panel, in the rows'
// order; they edit the scene as the options' own values, read and written through the rows.
void drawOptionWidgets(const char* section, SceneSettings& scene) {
    SceneOptions options = sceneOptionsOf(scene);
    std::vector<std::string> notes;
    std::string error;
    bool changed = false;
    Options parsed;
    auto set = [&](const OptionRow& row, const std::string& value) {
        parsed.scene = options;
        if (!readOption(row, value, parsed, notes, error)) return;
        options = parsed.scene;
        changed = true;
    };
    for (const OptionRow& row : optionTable()) {
        const OptionWidget& widget = row.widget;
        if (widget.kind == OptionWidgetKind::None || std::string(widget.section) != section) continue;
        std::string value = optionValue(row, options);
        if (widget.kind == OptionWidgetKind::Checkbox) {
            bool on = value == row.on;
            if (ImGui::Checkbox(widget.label, &on)) set(row, on ? row.on : row.off);
        } else if (widget.kind == OptionWidgetKind::Slider) {
            float& field = row.numberField(options);
            if (!widget.applyOnRelease) {
                changed |= ImGui::SliderFloat(widget.label, &field, widget.low, widget.high, widget.format);
                continue;
            }
            float& shown = pendingValue(row.flag, field);
            ImGui::SliderFloat(widget.label, &shown, widget.low, widget.high, widget.format);
            if (ImGui::IsItemDeactivatedAfterEdit()) {
                field = shown;
                changed = true;
            } else if (!ImGui::IsItemActive()) shown = field;  // follows the value set elsewhere
        } else if (widget.kind == OptionWidgetKind::Radios) {
            if (widget.label) ImGui::TextUnformatted(widget.label);
            for (const std::string& choice : row.choices()) {
                ImGui::SameLine();
                if (ImGui::RadioButton(choice.c_str(), value == choice)) set(row, choice);
            }
        }
    }
    if (changed) applySceneOptions(options, scene);
}

// Point lights: the count, the path (automatic or forced) and which path is active and why.
void drawLightsPanel(const Renderer& renderer, SceneSettings& scene) {
    if (!ImGui::CollapsingHeader("lights")) return;
    ImGui::SliderInt("point lights", &scene.lights.count, 0, kMaxLights);
    const char* choices[] = {"automatic", "ssbo", "ssbo-count", "ubo"};
    int choice = scene.lights.path ? 1 + int(*scene.lights.path) : 0;
    if (ImGui::Combo("light path", &choice, choices, 4))
        scene.lights.path = choice == 0 ? std::nullopt : std::optional<LightsPath>(LightsPath(choice - 1));
    ImGui::TextWrapped("active: %s", renderer.paths().lights.reason.c_str());
    ImGui::TextWrapped("%d lights drawn; ubo holds %d x %d", renderer.paths().lightsDrawn, renderer.paths().uboLights.blocks,
                renderer.paths().uboLights.capacity);
    if (renderer.paths().lightsDropped > 0)
        ImGui::TextColored(ImVec4(1.0f, 0.4f, 0.2f, 1.0f), "WARNING: %d lights dropped", renderer.paths().lightsDropped);
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
    if (renderer.paths().depthFellBack) ImGui::TextWrapped("depth: %s", renderer.paths().depthReason.c_str());
}

// Which scene the views show under the water (frame/view_fill.h), and what the view shows there.
void drawWaterSceneControl(const Renderer& renderer, Configuration& chosen) {
    int scene = chosen.waterScene == WaterScene::Direct ? 0 : 1;
    ImGui::TextUnformatted("under the water (M):");
    ImGui::SameLine();
    if (ImGui::RadioButton("direct", &scene, 0)) chosen.waterScene = WaterScene::Direct;
    ImGui::SameLine();
    if (ImGui::RadioButton("mirrored", &scene, 1)) chosen.waterScene = WaterScene::Mirrored;
    const ViewScene& shown = renderer.views().scene();
    if (const DebugView* view = findDebugView(chosen.view))
        ImGui::TextWrapped("%s", waterNote(*view, shown.description).c_str());
    else if (!shown.description.empty())
        ImGui::TextWrapped("the G-buffer, depth and error tiles under the water: %s", shown.description.c_str());
    if (!shown.reason.empty()) ImGui::TextWrapped("(%s)", shown.reason.c_str());
}

// Prints the panel's rectangle and how far its widest line reaches against what it shows, when
// they change: a line wider than the panel is cut off (the window tests read these lines).
void notePanelGeometry(WindowState& state) {
    const ImGuiWindow* panel = ImGui::GetCurrentWindow();
    const ImVec2 display = ImGui::GetIO().DisplaySize;
    char line[256];
    std::snprintf(line, sizeof(line), "panel %.0fx%.0f at %.0f,%.0f in a %.0fx%.0f window%s; widest line %.0f px of %.0f",
                  panel->Size.x, panel->Size.y, panel->Pos.x, panel->Pos.y, display.x, display.y,
                  panel->Collapsed ? " (collapsed)" : "", panel->DC.CursorMaxPos.x - panel->Pos.x,
                  panel->InnerClipRect.Max.x - panel->Pos.x);
    if (state.panelGeometry == line) return;
    state.panelGeometry = line;
    std::printf("oasis: %s\n", line);
    std::fflush(stdout);
}

}  // namespace

void drawPanel(Renderer& renderer, SceneSettings& scene, WindowState& state) {
    const ImVec2 display = ImGui::GetIO().DisplaySize;
    ImGui::SetNextWindowPos(ImVec2(10, 10), ImGuiCond_FirstUseEver);
    // Narrow enough to leave most of the frame (and a split's side A) in view; its lines wrap.
    // Never larger than the window: a smaller window shrinks the panel, which then scrolls.
    ImGui::SetNextWindowSize(ImVec2(kPanelWidth, display.y - 20.0f), ImGuiCond_FirstUseEver);
    ImGui::SetNextWindowSizeConstraints(ImVec2(160.0f, 60.0f), ImVec2(std::max(160.0f, display.x - 20.0f),
                                                                       std::max(60.0f, display.y - 20.0f)));
    ImGui::Begin("oasis (H hides)");
    // Widgets leave room for their labels (up to about 20 characters) on the right: a fixed share
    // of the width cut the longer ones off in a narrow panel.
    ImGui::PushItemWidth(-ImGui::CalcTextSize("divider (or drag it)").x - 4.0f);
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
    ImGui::TextWrapped("frame %.2f ms (avg %.2f), wall time around glFinish", state.frameMs, state.smoothedMs);
    drawComparePanel(state);

    const auto& layouts = gbufferLayouts();
    if (ImGui::BeginCombo("G-buffer (G)", layouts[chosen.layoutIndex].name.c_str())) {
        for (size_t i = 0; i < layouts.size(); ++i) {
            std::string label = layouts[i].name + " (" + std::to_string(layouts[i].bytesPerPixel()) + " B/px)";
            if (ImGui::Selectable(label.c_str(), i == chosen.layoutIndex)) chosen.layoutIndex = i;
        }
        ImGui::EndCombo();
    }
    if (renderer.paths().gbufferFellBack) ImGui::TextWrapped("G-buffer: %s", renderer.paths().gbufferReason.c_str());
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
    drawInspectorPanel(state, scene.timeSeconds);

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
        drawOptionWidgets("shadows", scene);
        const FrameSetup& frame = renderer.lastFrame().setup;
        ImGui::TextWrapped("%s", !scene.shadows.enabled ? "off" : frame.shadowsActive ? "drawn this frame" : "sun below the horizon: no shadow pass");
    }
    if (ImGui::CollapsingHeader("water")) {
        drawOptionWidgets("water", scene);
        ImGui::ColorEdit3("tint", &scene.water.tint.x);
    }
    if (ImGui::CollapsingHeader("vegetation")) {
        drawOptionWidgets("vegetation", scene);
        ImGui::SliderFloat("draw distance", &scene.vegetation.drawDistance, 50.0f, 1500.0f, "%.0f");
        ImGui::SliderFloat("thinning from", &scene.vegetation.thinningStart, 10.0f, 600.0f, "%.0f");
        ImGui::TextWrapped("%s", describeVegetation(renderer).c_str());
    }
    drawLightsPanel(renderer, scene);
    if (ImGui::CollapsingHeader("frame work")) {
        // Savings that keep the picture: switch one off to see what it saves (the pass times).
        drawOptionWidgets("frame work", scene);
    }
    ImGui::Separator();
    ImGui::Text("%dx%d, terrain %d triangles", renderer.targets().width(), renderer.targets().height(),
                renderer.parts().geometry.terrainTriangles());
    if (!state.fallbacks.empty() &&
        ImGui::CollapsingHeader("fallbacks (this driver or --force)", ImGuiTreeNodeFlags_DefaultOpen)) {
        for (const std::string& line : state.fallbacks) {
            ImGui::Bullet();
            ImGui::TextWrapped("%s", line.c_str());
        }
    }
    notePanelGeometry(state);
    ImGui::PopItemWidth();
    ImGui::End();
}

}  // namespace window
}  // namespace oasis
