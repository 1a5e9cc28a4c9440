// The two pipelines as pass lists.
#include "render/pipeline.h"

#include <algorithm>

#include "passes/clear_pass.h"
#include "passes/depth_copy_pass.h"
#include "passes/light_tiling_pass.h"
#include "passes/light_volume_pass.h"
#include "passes/lighting_pass.h"
#include "passes/reflection_clear_pass.h"
#include "passes/reflection_upsample_pass.h"
#include "passes/shadow_pass.h"
#include "passes/sky_pass.h"
#include "passes/terrain_heights_pass.h"
#include "passes/terrain_pass.h"
#include "passes/tone_map_pass.h"
#include "passes/vegetation_pass.h"
#include "passes/water_composite_pass.h"
#include "passes/water_mask_pass.h"

namespace oasis {

const char* pipelineName(PipelineKind kind) { return kind == PipelineKind::Forward ? "forward" : "deferred"; }

bool parsePipelineKind(const std::string& text, PipelineKind& out) {
    if (text == "forward") { out = PipelineKind::Forward; return true; }
    if (text == "deferred") { out = PipelineKind::Deferred; return true; }
    return false;
}

Pipeline::Pipeline(PipelineKind kind) : kind_(kind) {
    auto add = [this](auto pass) { passes_.push_back(std::move(pass)); };
    // The terrain's heights for every pass that draws it, then the sun's shadow maps: every
    // shading pass after it reads them (both pipelines alike).
    add(std::make_unique<TerrainHeightsPass>());
    add(std::make_unique<ShadowPass>());
    if (kind == PipelineKind::Deferred) {
        add(std::make_unique<ClearPass>(SurfaceOutput::GBuffer));
        add(std::make_unique<TerrainPass>(SurfaceOutput::GBuffer));
        add(std::make_unique<VegetationPass>(SurfaceOutput::GBuffer));
        add(std::make_unique<DepthCopyPass>());
        // The point lights: tiled (a light list per screen tile, added by LightingPass) or the
        // stencil volumes after it; each pass is active only with its method.
        add(std::make_unique<LightTilingPass>());
        add(std::make_unique<LightingPass>());
        add(std::make_unique<SkyPass>(SurfaceOutput::GBuffer));
        // Before the water mask: the depth under the water is still the terrain's, which the
        // volumes test against (the G-buffer there holds that terrain).
        add(std::make_unique<LightVolumePass>());
        add(std::make_unique<WaterMaskPass>());
        add(std::make_unique<ReflectionClearPass>(SurfaceOutput::GBuffer));
        add(std::make_unique<TerrainPass>(SurfaceOutput::GBuffer, Mirroring::Mirrored));
        add(std::make_unique<VegetationPass>(SurfaceOutput::GBuffer, Mirroring::Mirrored));
        add(std::make_unique<DepthCopyPass>(Mirroring::Mirrored));
        add(std::make_unique<LightTilingPass>(Mirroring::Mirrored));
        add(std::make_unique<LightingPass>(Mirroring::Mirrored));
        add(std::make_unique<SkyPass>(SurfaceOutput::GBuffer, Mirroring::Mirrored));
        add(std::make_unique<LightVolumePass>(Mirroring::Mirrored));
    } else {
        add(std::make_unique<ClearPass>(SurfaceOutput::Forward));
        add(std::make_unique<TerrainPass>(SurfaceOutput::Forward));
        add(std::make_unique<VegetationPass>(SurfaceOutput::Forward));
        add(std::make_unique<SkyPass>(SurfaceOutput::Forward));
        add(std::make_unique<WaterMaskPass>());
        add(std::make_unique<ReflectionClearPass>(SurfaceOutput::Forward));
        add(std::make_unique<TerrainPass>(SurfaceOutput::Forward, Mirroring::Mirrored));
        add(std::make_unique<VegetationPass>(SurfaceOutput::Forward, Mirroring::Mirrored));
        add(std::make_unique<SkyPass>(SurfaceOutput::Forward, Mirroring::Mirrored));
    }
    // A reflection drawn at a reduced resolution is brought to the frame's here (else inactive).
    add(std::make_unique<ReflectionUpsamplePass>());
    add(std::make_unique<WaterCompositePass>());
    add(std::make_unique<ToneMapPass>());
}

bool Pipeline::run(PassContext& context, const std::string& stopBefore,
                   const std::function<void(const Pass&)>& afterEach) const {
    if (!stopBefore.empty() && !hasPass(stopBefore)) return false;
    gl::DebugGroup group(pipelineName(kind_));
    for (const auto& pass : passes_) {
        if (pass->name() == stopBefore) break;
        if (!pass->active(context.frame)) continue;
        OnlyWhereWaterIsSeen onlyWithWater(context, pass->reflectionWork());
        if (pass->reflectionWork()) {
            ReflectionContext reflection(context);  // the reflection's targets, maybe reduced
            pass->run(reflection.get());
        } else {
            pass->run(context);
        }
        if (afterEach) afterEach(*pass);
    }
    return true;
}

bool Pipeline::hasPass(const std::string& name) const {
    return std::any_of(passes_.begin(), passes_.end(), [&](const auto& pass) { return pass->name() == name; });
}

std::string Pipeline::passNames() const {
    std::string names;
    for (const auto& pass : passes_) names += (names.empty() ? "" : ", ") + pass->name();
    return names;
}

bool Pipeline::writes(Target target) const {
    return std::any_of(passes_.begin(), passes_.end(), [&](const auto& pass) {
        auto written = pass->writes();
        return std::find(written.begin(), written.end(), target) != written.end();
    });
}

}  // namespace oasis
