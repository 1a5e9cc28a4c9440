// Which scene the views show under the water, and the passes that put it in the G-buffer.
//
// A finished frame leaves the water pixels inconsistent for inspection: the deferred pipeline
// refills its G-buffer there with the mirrored scene (for the reflection's lighting) and the
// water composite then puts the water's own depth back; the forward pipeline draws no G-buffer.
// Before a view, the probe or an encoding-error measurement reads the G-buffer, depth or stencil
// of a finished frame, the renderer runs one of two fills so that every view of the frame agrees:
//   direct   - the surfaces under the water (the lakebed) in the G-buffer AND depth; the stencil
//              marks the water;
//   mirrored - inside the water what it reflects (the mirrored scene, or nothing where it
//              reflects the sky) in the G-buffer AND depth, as the deferred reflection lit it.
// Radiance, Reflection and Final are never touched. A frame stopped early (--stop-before) is
// shown as the frame left it instead.
#pragma once
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "passes/pass.h"

namespace oasis {

enum class WaterScene { Direct, Mirrored };

const char* waterSceneName(WaterScene scene);                     // "direct", "mirrored"
std::optional<WaterScene> parseWaterScene(const std::string& text);
inline constexpr const char* kWaterSceneNames = "direct, mirrored";

// What the views show at water pixels, and why (for legends, the panel and the probe).
struct ViewScene {
    std::optional<WaterScene> scene;  // empty: a frame stopped early, shown as it was left
    std::string description;          // "the direct scene (the lakebed under the water)"
    std::string reason;               // why, when it is not simply what was asked for
};

class ViewFill {
public:
    ViewFill();
    // Fills the G-buffer, depth and stencil with `scene` (a mirrored scene needs the frame's
    // reflections; without them the direct scene is filled and the result says so).
    ViewScene run(PassContext& context, WaterScene scene) const;
    // The passes run() runs for `scene` in `frame` (the direct ones where the frame has no
    // mirrored scene): what a view's frame is culled against (FrameViews::setSink).
    std::vector<const Pass*> passes(WaterScene scene, const FrameSetup& frame) const;
    // The deferred steps of the direct scene that fill a stopped forward frame's G-buffer
    // (Renderer::fillStoppedFrame runs those whose forward step ran).
    const std::vector<std::unique_ptr<Pass>>& stoppedFrameFill() const { return stoppedFrame_; }

private:
    std::vector<std::unique_ptr<Pass>> direct_, mirrored_, stoppedFrame_;
};

}  // namespace oasis
