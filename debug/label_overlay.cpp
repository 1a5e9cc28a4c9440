// ImGui-rendered labels for the overview tiles.
#include "debug/label_overlay.h"

#include <epoxy/gl.h>
#include <imgui.h>

#include <algorithm>
#include <cfloat>
#include <cmath>

#include "debug/imgui_gl_backend.h"
#include "debug/imgui_gl_labels.h"
#include "gl/objects.h"

namespace oasis {
namespace {

// Makes `context` current for a scope and restores whatever was current before.
struct ContextScope {
    explicit ContextScope(ImGuiContext* context) : previous(ImGui::GetCurrentContext()) {
        ImGui::SetCurrentContext(context);
    }
    ~ContextScope() { ImGui::SetCurrentContext(previous); }
    ImGuiContext* previous;
};

}  // namespace

LabelOverlay::LabelOverlay() {
    ImGuiContext* previous = ImGui::GetCurrentContext();
    context_ = ImGui::CreateContext();
    ImGui::SetCurrentContext(context_);
    ImGui::GetIO().IniFilename = nullptr;
    es_ = imguiGlBackendInit();
    ImGui::SetCurrentContext(previous);
}

LabelOverlay::~LabelOverlay() {
    {
        ContextScope scope(context_);
        imguiGlBackendShutdown(es_);
    }
    ImGui::DestroyContext(context_);
}

void LabelOverlay::draw(const std::vector<Label>& labels, int width, int height, float scale) {
    drawWith([&](ImDrawList& draw) {
        float pad = 3.0f * scale;
        for (const Label& label : labels) {
            ImVec2 size = ImGui::CalcTextSize(label.text.c_str());
            ImVec2 corner(label.x, label.y);
            draw.AddRectFilled(corner, ImVec2(corner.x + size.x + 2 * pad, corner.y + size.y + 2 * pad),
                               IM_COL32(0, 0, 0, 190));
            draw.AddText(ImVec2(corner.x + pad, corner.y + pad), IM_COL32(255, 255, 255, 255), label.text.c_str());
        }
    }, width, height, scale);
}

int LabelOverlay::wrappedLines(const std::string& text, float wrapWidth, float scale) {
    ContextScope scope(context_);
    ImFontAtlas* fonts = ImGui::GetIO().Fonts;
    if (!fonts->IsBuilt()) fonts->Build();  // the default font, as the first frame would build it
    ImFont* font = fonts->Fonts[0];
    const float size = font->FontSize * scale;  // what AddText(nullptr, 0.0f, ...) draws at
    ImVec2 extent = font->CalcTextSizeA(size, FLT_MAX, wrapWidth, text.c_str(), text.c_str() + text.size());
    return std::max(1, int(std::lround(extent.y / size)));
}

void LabelOverlay::drawWith(const std::function<void(ImDrawList&)>& paint, int width, int height, float scale) {
    ContextScope scope(context_);
    // The backend restores the program current before it; make that one that cannot have been
    // deleted since (a deleted program that was current stops existing once unbound).
    glUseProgram(0);
    ImGuiIO& io = ImGui::GetIO();
    io.DisplaySize = ImVec2(float(width), float(height));
    io.DeltaTime = 1.0f / 60.0f;
    io.FontGlobalScale = scale;
    imguiGlBackendNewFrame(es_);
    ImGui::NewFrame();
    nameImGuiObjects(*ImGui::GetForegroundDrawList(), "ImGui labels");
    paint(*ImGui::GetForegroundDrawList());
    ImGui::Render();
    gl::DebugGroup group("LabelOverlay (ImGui)");
    imguiGlBackendRender(es_, ImGui::GetDrawData());
}

}  // namespace oasis
