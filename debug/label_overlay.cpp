// ImGui-rendered labels for the overview tiles.
#include "debug/label_overlay.h"

#include <epoxy/gl.h>
#include <imgui.h>
#include <imgui_impl_opengl3.h>

#include "debug/imgui_gl_labels.h"
#include "debug/imgui_gles/imgui_impl_opengl3_gles.h"
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

// The backend build for the current context's API: desktop GL, or OpenGL ES 3 (--api gles).
bool esContext() { return !epoxy_is_desktop_gl(); }

}  // namespace

LabelOverlay::LabelOverlay() {
    ImGuiContext* previous = ImGui::GetCurrentContext();
    context_ = ImGui::CreateContext();
    ImGui::SetCurrentContext(context_);
    ImGui::GetIO().IniFilename = nullptr;
    es_ = esContext();
    if (es_) ImGui_ImplOpenGL3Es_Init("#version 300 es");
    else ImGui_ImplOpenGL3_Init("#version 330 core");
    ImGui::SetCurrentContext(previous);
}

LabelOverlay::~LabelOverlay() {
    {
        ContextScope scope(context_);
        if (es_) ImGui_ImplOpenGL3Es_Shutdown();
        else ImGui_ImplOpenGL3_Shutdown();
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

void LabelOverlay::drawWith(const std::function<void(ImDrawList&)>& paint, int width, int height, float scale) {
    ContextScope scope(context_);
    // The backend restores the program current before it; make that one that cannot have been
    // deleted since (a deleted program that was current stops existing once unbound).
    glUseProgram(0);
    ImGuiIO& io = ImGui::GetIO();
    io.DisplaySize = ImVec2(float(width), float(height));
    io.DeltaTime = 1.0f / 60.0f;
    io.FontGlobalScale = scale;
    if (es_) ImGui_ImplOpenGL3Es_NewFrame();
    else ImGui_ImplOpenGL3_NewFrame();
    ImGui::NewFrame();
    nameImGuiObjects(*ImGui::GetForegroundDrawList(), "ImGui labels");
    paint(*ImGui::GetForegroundDrawList());
    ImGui::Render();
    gl::DebugGroup group("LabelOverlay (ImGui)");
    if (es_) ImGui_ImplOpenGL3Es_RenderDrawData(ImGui::GetDrawData());
    else ImGui_ImplOpenGL3_RenderDrawData(ImGui::GetDrawData());
}

}  // namespace oasis
