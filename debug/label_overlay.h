// Text labels drawn over the display target with Dear ImGui's built-in font, in a private ImGui
// context so it works headless (EGL) as well as beside the window's own ImGui panel.
#pragma once
#include <functional>
#include <string>
#include <vector>

struct ImGuiContext;
struct ImDrawList;

namespace oasis {

struct Label {
    std::string text;
    float x, y;  // top-left corner in pixels, y down from the top of the target
};

class LabelOverlay {
public:
    LabelOverlay();
    ~LabelOverlay();
    LabelOverlay(const LabelOverlay&) = delete;
    LabelOverlay& operator=(const LabelOverlay&) = delete;

    // Draws the labels into the bound framebuffer of the given size.
    void draw(const std::vector<Label>& labels, int width, int height, float scale);
    // Draws whatever `paint` adds to a draw list (text, rectangles, gradients) the same way.
    void drawWith(const std::function<void(ImDrawList&)>& paint, int width, int height, float scale);
    // How many lines `text` takes drawn at `scale` and wrapped at `wrapWidth` pixels, as ImGui
    // wraps it (at word ends and after punctuation, so more than its length over the width).
    int wrappedLines(const std::string& text, float wrapWidth, float scale);

private:
    ImGuiContext* context_ = nullptr;
    bool es_ = false;  // built with the OpenGL ES 3 backend (an ES context: --api gles)
};

}  // namespace oasis
