// One full-screen triangle; every pixel's surface comes from the G-buffer. With the tiled light
// method the variant also adds the lights its LightTilingPass listed for the pixel's tile.
#include "passes/lighting_pass.h"

#include "passes/light_tiling_pass.h"

namespace oasis {

void LightingPass::execute(PassContext& context) {
    bool fused = toneMapFusedInto(context.frame, SurfaceOutput::Forward, mirroring_);
    bindSurfaceOutput(context.targets, SurfaceOutput::Forward, mirroring_, fused);
    glDisable(GL_DEPTH_TEST);
    bindGBufferInputs(context.targets);
    beginMirroredDraw(mirroring_);
    if (mirroring_ == Mirroring::Mirrored) beginWaterBoundedDraw(context);
    std::string program = mirroring_ == Mirroring::Mirrored ? "lighting.mirrored" : fused ? "lighting.tonemapped" : "lighting";
    if (LightTilingPass::tiledLightsActive(context.frame, mirroring_)) program += ".tiled";
    glUseProgram(context.shaders.program(context.targets.layout().program(program)));
    context.geometry.drawFullscreenTriangle();
    if (mirroring_ == Mirroring::Mirrored) endWaterBoundedDraw(context);
    endMirroredDraw(mirroring_);
}

}  // namespace oasis
