// One full-screen triangle; every pixel's surface comes from the G-buffer. With the tiled light
// method the variant also adds the lights its LightTilingPass listed for the pixel's tile.
#include "passes/lighting_pass.h"

#include "passes/light_tiling_pass.h"

namespace oasis {

void LightingPass::execute(PassContext& context) {
    bool fused = toneMapFusedInto(context.frame, SurfaceOutput::Forward, mirroring_);
    bool mirrored = mirroring_ == Mirroring::Mirrored;
    // Mirrored, the stencil keeps the shading inside the water, so the depth-stencil target is
    // attached and depth comes from the copy; direct, nothing is tested and the target is read.
    bool inPlace = !mirrored && context.frame.depthReadInPlace;
    if (!inPlace) {
        bindSurfaceOutput(context.targets, SurfaceOutput::Forward, mirroring_, fused);
    } else {
        glBindFramebuffer(GL_FRAMEBUFFER, context.targets.radianceOnlyFramebuffer(fused));
        glViewport(0, 0, context.targets.width(), context.targets.height());
    }
    glDisable(GL_DEPTH_TEST);
    bindGBufferInputs(context.targets, inPlace ? DepthRead::FromTarget : DepthRead::FromCopy);
    beginMirroredDraw(mirroring_);
    if (mirrored) beginWaterBoundedDraw(context);
    std::string program = mirrored ? "lighting.mirrored" : fused ? "lighting.tonemapped" : "lighting";
    if (LightTilingPass::tiledLightsActive(context.frame, mirroring_)) program += ".tiled";
    glUseProgram(context.shaders.program(context.targets.layout().program(program)));
    context.geometry.drawFullscreenTriangle();
    if (mirrored) endWaterBoundedDraw(context);
    endMirroredDraw(mirroring_);
}

}  // namespace oasis
