// The views' two fills, as lists of the deferred geometry passes (no shading passes).
#include "frame/view_fill.h"

#include "frame/frame_assembly.h"
#include "frame/pipeline.h"

namespace oasis {

const char* waterSceneName(WaterScene scene) { return scene == WaterScene::Direct ? "direct" : "mirrored"; }

std::optional<WaterScene> parseWaterScene(const std::string& text) {
    if (text == "direct") return WaterScene::Direct;
    if (text == "mirrored") return WaterScene::Mirrored;
    return std::nullopt;
}

ViewFill::ViewFill()
    : direct_(assembleFrame(FrameOutput::ViewFillDirect)),
      mirrored_(assembleFrame(FrameOutput::ViewFillMirrored)),
      stoppedFrame_(assembleFrame(FrameOutput::StoppedFrameFill)) {}

std::vector<const Pass*> ViewFill::passes(WaterScene scene, const FrameSetup& frame) const {
    std::vector<const Pass*> list;
    for (const auto& pass : scene == WaterScene::Mirrored && frame.reflectionsActive ? mirrored_ : direct_)
        list.push_back(pass.get());
    return list;
}

ViewScene ViewFill::run(PassContext& context, WaterScene scene) const {
    ViewScene shown;
    if (scene == WaterScene::Mirrored && !context.frame.reflectionsActive) {
        scene = WaterScene::Direct;
        shown.reason = "mirrored was asked for, but this frame has no mirrored scene (reflections off, or the "
                       "camera at or under the water)";
    }
    gl::DebugGroup group(scene == WaterScene::Direct ? "views: direct scene" : "views: mirrored scene");
    for (const auto& pass : scene == WaterScene::Direct ? direct_ : mirrored_)
        if (pass->active(context.frame)) runValidated(*pass, context);
    shown.scene = scene;
    shown.description = scene == WaterScene::Direct
                            ? "the direct scene (the lakebed under the water)"
                            : "the mirrored scene (what the water reflects; nothing drawn where it reflects the sky)";
    return shown;
}

}  // namespace oasis
