// The panel's inspector and live-comparison sections, and what is drawn over the frame for them:
// the pinned probes' numbers and the comparison sides' names.
#include "window/window_state.h"

#include <GLFW/glfw3.h>
#include <imgui.h>

#include <algorithm>
#include <cstdio>

namespace oasis {
namespace window {

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

// The small overlay that stays when the panel hides (H): the pipeline or the comparison's sides,
// the frame time, and what holds still (the clock, the pins).
void drawStatusOverlay(GLFWwindow* window, const WindowState& state) {
    if (!state.overlayShown) return;  // O: the frame alone (screenshots compared pixel for pixel)
    int windowWidth = 0, windowHeight = 0;
    glfwGetWindowSize(window, &windowWidth, &windowHeight);
    const Configuration& shown = state.lastDrawn ? *state.lastDrawn : state.chosen;
    const WindowComparison& c = state.comparison;
    char line[256];
    if (c.mode == CompareMode::Off)
        std::snprintf(line, sizeof(line), "%s %.2f ms (avg %.2f)", pipelineName(shown.pipeline), state.frameMs,
                      state.smoothedMs);
    else {
        SampleStats a = c.msA.stats(), b = c.msB.stats();
        RatioStats ratio = c.bOverA();
        std::snprintf(line, sizeof(line), "A %.2f ms %s, B %.2f ms %s (medians, 95%%), B/A %.2fx %s", a.median,
                      intervalText(a.low, a.high).c_str(), b.median, intervalText(b.low, b.high).c_str(), ratio.ratio,
                      ratio.hasInterval() ? intervalText(ratio.low, ratio.high).c_str() : "(no interval yet)");
    }
    std::string text = line;
    if (state.paused) text += ", paused";
    if (state.inspector.frozen && !state.inspector.pinned.empty()) text += ", pins frozen";
    if (!state.panelShown) text += "  (H: panel, O: this)";
    ImDrawList* draw = ImGui::GetForegroundDrawList();
    ImVec2 size = ImGui::CalcTextSize(text.c_str());
    ImVec2 at(std::max(4.0f, float(windowWidth) - size.x - 8.0f), std::max(4.0f, float(windowHeight) - size.y - 8.0f));
    draw->AddRectFilled(ImVec2(at.x - 4, at.y - 3), ImVec2(at.x + size.x + 4, at.y + size.y + 3), IM_COL32(0, 0, 0, 200));
    draw->AddText(at, IM_COL32(255, 255, 255, 255), text.c_str());
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
    ImGui::TextWrapped("A %s: %s", c.a.label.c_str(), describeTime(c.msA.stats()).c_str());
    ImGui::TextWrapped("B %s: %s", c.b.label.c_str(), describeTime(c.msB.stats()).c_str());
    ImGui::TextWrapped("%s", describeRatio(c.bOverA(), "B", "A").c_str());
    ImGui::PushStyleColor(ImGuiCol_Text, ImGui::GetStyleColorVec4(ImGuiCol_TextDisabled));
    ImGui::TextWrapped("medians of the last %zu frames each with 95%% intervals, the sides in a random order each "
                       "frame (seed %llu); reset when a setting changes", c.msA.count(),
                       static_cast<unsigned long long>(c.seed));
    ImGui::PopStyleColor();
    ImGui::TextWrapped("displayed: PSNR %.2f dB%s, max abs %d, RMSE %.4f (8-bit RGB)", c.difference.psnrDb,
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

namespace {

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

// The shading and history I computed for pin `pin` (its side's), or under the cursor.
void drawDeepProbes(const Inspector& inspector, size_t pin, const std::string& side) {
    for (const Inspector::Deep& deep : inspector.deep) {
        if (deep.pin != pin || (deep.side != side && pin != Inspector::kHovered)) continue;
        std::string title = "shading and history at --time " + std::to_string(deep.timeSeconds).substr(0, 8) +
                            (deep.side.empty() ? "" : ", " + deep.side);
        if (!ImGui::TreeNode(title.c_str())) continue;
        if (deep.report.shading) ImGui::TextWrapped("%s", shadingText(*deep.report.shading).c_str());
        if (deep.report.history) ImGui::TextWrapped("%s", historyText(*deep.report.history).c_str());
        ImGui::TreePop();
    }
}

}  // namespace

// The inspector's section of the panel: view controls, value counts, the probes.
void drawInspectorPanel(WindowState& state, double clockSeconds) {
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
            ImGui::TextWrapped("values: NaN %ld, +Inf %ld, -Inf %ld, negative %ld of %ld; finite %.4g .. %.4g%s", s.nan,
                               s.positiveInfinity, s.negativeInfinity, s.negative, s.values, s.min, s.max,
                               s.undrawn ? ("; " + std::to_string(s.undrawn) + " px not drawn (the sky: left out)").c_str() : "");
        }
    } else if (state.chosen.view == kOverviewName) {
        drawOverlayChoices(inspector);
        for (const std::string& line : inspector.overviewCounts) ImGui::TextWrapped("%s", line.c_str());
    }
    for (size_t i = 0; i < inspector.hoveredProbes.size(); ++i) {
        const SideProbe& hovered = inspector.hoveredProbes[i];
        std::string title = "under the cursor" + (hovered.side.empty() ? "" : ", " + hovered.side) + "###hovered" +
                            std::to_string(i);
        if (ImGui::TreeNodeEx(title.c_str(), ImGuiTreeNodeFlags_DefaultOpen)) {
            ImGui::TextWrapped("%s", probeText(hovered.probe).c_str());
            ImGui::TreePop();
        }
    }
    if (inspector.hoveredProbes.empty()) ImGui::TextDisabled("move the cursor over the frame to probe it");
    if (!inspector.pinned.empty()) {
        if (ImGui::Checkbox("freeze the pins' values (F)", &inspector.frozen) && inspector.frozen)
            inspector.frozenAt = clockSeconds;
        if (inspector.frozen) {
            ImGui::SameLine();
            ImGui::TextDisabled("at --time %.2f", inspector.frozenAt);
        }
    }
    if (ImGui::Button(inspector.pinned.empty() ? "shading and history under the cursor (I)"
                                               : "shading and history of the pins (I)"))
        inspector.deepRequested = true;
    for (size_t i = 0; i < inspector.pinnedProbes.size(); ++i) {
        for (const SideProbe& pin : inspector.pinnedProbes[i]) {
            // A short label (tree nodes do not wrap), the summary wrapped under it.
            std::string label = "#" + std::to_string(i + 1) + (pin.side.empty() ? "" : " " + pin.side) + "###pin" +
                                std::to_string(i) + pin.side;
            bool open = ImGui::TreeNode(label.c_str());
            ImGui::Indent();
            ImGui::TextWrapped("%s", probeSummary(pin.probe).c_str());
            ImGui::Unindent();
            if (open) {
                ImGui::TextWrapped("%s", probeText(pin.probe).c_str());
                drawDeepProbes(inspector, i, pin.side);
                ImGui::TreePop();
            }
        }
    }
    if (inspector.pinned.empty()) drawDeepProbes(inspector, Inspector::kHovered, "");
    if (!inspector.pinned.empty() && ImGui::Button("unpin all")) inspector.pinned.clear();
}

}  // namespace window
}  // namespace oasis
