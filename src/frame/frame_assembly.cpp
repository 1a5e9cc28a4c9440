// The pass lists of every output, from one set of scene steps (frame/frame_assembly.h).
#include "frame/frame_assembly.h"

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
namespace {

template <typename P, typename... Arguments>
void add(PassList& list, Arguments... arguments) {
    list.push_back(std::make_unique<P>(arguments...));
}

// The steps that draw the scene's surfaces into `output`: cleared first (the direct scene's
// targets, or the water's depth for the mirrored scene), then the terrain and the plants.
void addSceneSteps(PassList& list, SurfaceOutput output, Mirroring mirroring,
                   ClearPass::StoppedFrameTargets stopped = ClearPass::StoppedFrameTargets::Cleared,
                   ReflectionClearPass::RunsIn runsIn = ReflectionClearPass::RunsIn::Frame) {
    if (mirroring == Mirroring::Direct) add<ClearPass>(list, output, stopped);
    else add<ReflectionClearPass>(list, output, runsIn);
    add<TerrainPass>(list, output, mirroring);
    add<VegetationPass>(list, output, mirroring);
}

// The deferred shading of one half of the frame over the G-buffer its scene steps filled. The
// point lights: tiled (a light list per screen tile, added by LightingPass) or the stencil volumes
// after the sky; the frame graph keeps the tiling and the depth copy only where they are read.
void addDeferredShading(PassList& list, Mirroring mirroring) {
    add<DepthCopyPass>(list, mirroring);
    add<LightTilingPass>(list, mirroring);
    add<LightingPass>(list, mirroring);
    add<SkyPass>(list, SurfaceOutput::GBuffer, mirroring);
    add<LightVolumePass>(list, mirroring);
}

PassList assembleFrameOf(SurfaceOutput surfaces) {
    PassList list;
    // The terrain's heights for every pass that draws it, then the sun's shadow maps, which every
    // shading pass after it reads.
    add<TerrainHeightsPass>(list);
    add<ShadowPass>(list);
    for (Mirroring mirroring : {Mirroring::Direct, Mirroring::Mirrored}) {
        addSceneSteps(list, surfaces, mirroring);
        if (surfaces == SurfaceOutput::GBuffer) addDeferredShading(list, mirroring);
        else add<SkyPass>(list, surfaces, mirroring);
        // After the direct half's light volumes: the depth under the water is still the
        // terrain's, which they test against (the G-buffer there holds that terrain).
        if (mirroring == Mirroring::Direct) add<WaterMaskPass>(list);
    }
    // A reflection drawn at a reduced resolution is brought to the frame's here (else inactive).
    add<ReflectionUpsamplePass>(list);
    add<WaterCompositePass>(list);
    add<ToneMapPass>(list);
    return list;
}

// The fills' passes, which draw into the frame's own targets (the mirrored scene too, whatever
// the frame's reflection resolution: Pass::drawAtFrameScale).
PassList assembleFill(FrameOutput output) {
    PassList list;
    if (output == FrameOutput::StoppedFrameFill) {
        // Only the steps the forward frame ran; the depth copy follows them where the deferred
        // frame's graph keeps it (Renderer::fillStoppedFrame).
        // Radiance and Reflection stay the forward frame's.
        addSceneSteps(list, SurfaceOutput::GBuffer, Mirroring::Direct, ClearPass::StoppedFrameTargets::Kept);
        add<DepthCopyPass>(list, Mirroring::Direct);
        add<WaterMaskPass>(list);
        return list;
    }
    add<TerrainHeightsPass>(list);  // the fill may run before any frame has
    // The views' fills redraw the scene's surfaces only: Radiance and Reflection stay the frame's.
    addSceneSteps(list, SurfaceOutput::GBuffer, Mirroring::Direct, ClearPass::StoppedFrameTargets::Kept);
    if (output == FrameOutput::ViewFillDirect) {
        add<WaterMaskPass>(list, WaterDepth::Kept);
        return list;
    }
    add<WaterMaskPass>(list, WaterDepth::Written);
    addSceneSteps(list, SurfaceOutput::GBuffer, Mirroring::Mirrored, ClearPass::StoppedFrameTargets::Kept,
                  ReflectionClearPass::RunsIn::ViewFill);
    return list;
}

}  // namespace

PassList assembleFrame(FrameOutput output) {
    if (output == FrameOutput::ForwardFrame) return assembleFrameOf(SurfaceOutput::Forward);
    if (output == FrameOutput::DeferredFrame) return assembleFrameOf(SurfaceOutput::GBuffer);
    PassList list = assembleFill(output);
    for (auto& pass : list) pass->drawAtFrameScale();
    return list;
}

}  // namespace oasis
