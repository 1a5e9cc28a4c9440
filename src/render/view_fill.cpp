// The views' two fills, as lists of the deferred geometry passes (no shading passes).
#include "render/view_fill.h"

#include "passes/clear_pass.h"
#include "passes/reflection_clear_pass.h"
#include "passes/terrain_heights_pass.h"
#include "passes/terrain_pass.h"
#include "passes/vegetation_pass.h"
#include "passes/water_mask_pass.h"

namespace oasis {

const char* waterSceneName(WaterScene scene) { return scene == WaterScene::Direct ? "direct" : "mirrored"; }

std::optional<WaterScene> parseWaterScene(const std::string& text) {
    if (text == "direct") return WaterScene::Direct;
    if (text == "mirrored") return WaterScene::Mirrored;
    return std::nullopt;
}

ViewFill::ViewFill() {
    auto directScene = [](std::vector<std::unique_ptr<Pass>>& list) {
        list.push_back(std::make_unique<TerrainHeightsPass>());  // the fill may run before any frame has
        list.push_back(std::make_unique<ClearPass>(SurfaceOutput::GBuffer));
        list.push_back(std::make_unique<TerrainPass>(SurfaceOutput::GBuffer));
        list.push_back(std::make_unique<VegetationPass>(SurfaceOutput::GBuffer));
    };
    directScene(direct_);
    direct_.push_back(std::make_unique<WaterMaskPass>(WaterDepth::Kept));

    directScene(mirrored_);
    mirrored_.push_back(std::make_unique<WaterMaskPass>(WaterDepth::Written));
    mirrored_.push_back(std::make_unique<ReflectionClearPass>(SurfaceOutput::GBuffer,
                                                              ReflectionClearPass::ReflectionTarget::Kept));
    mirrored_.push_back(std::make_unique<TerrainPass>(SurfaceOutput::GBuffer, Mirroring::Mirrored));
    mirrored_.push_back(std::make_unique<VegetationPass>(SurfaceOutput::GBuffer, Mirroring::Mirrored));
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
        if (pass->active(context.frame)) pass->run(context);
    shown.scene = scene;
    shown.description = scene == WaterScene::Direct
                            ? "the direct scene (the lakebed under the water)"
                            : "the mirrored scene (what the water reflects; nothing drawn where it reflects the sky)";
    return shown;
}

}  // namespace oasis
