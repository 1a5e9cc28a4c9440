// One full-screen triangle at the far plane; every pixel's surface comes from the G-buffer. Where
// the depth-stencil target can be attached, the depth test keeps the triangle to the surfaces
// (SkyPass draws the rest): llvmpipe runs both sides of a shader's branches, so a sky branch here
// cost every pixel the sky's noise as well as the sun's shading. With the tiled light method the
// variant also adds the lights its LightTilingPass listed for the pixel's tile.
#include "passes/lighting_pass.h"

#include "passes/light_tiling_pass.h"

namespace oasis {

bool LightingPass::testsSurfaces(const FrameSetup& frame) const {
    // Mirrored, the depth comes from the copy; a layout that stores position reads no depth; the
    // compact layout's in-place read may also test where the context allows it (read-only depth).
    bool samplesTheTarget = mirroring_ == Mirroring::Direct && frame.depthReadInPlace && frame.positionFromDepth;
    return !samplesTheTarget || frame.readOnlyDepth;
}

void LightingPass::execute(PassContext& context) {
    bool fused = toneMapFusedInto(context.frame, SurfaceOutput::Forward, mirroring_);
    bool mirrored = mirroring_ == Mirroring::Mirrored;
    bool surfacesOnly = testsSurfaces(context.frame);
    if (surfacesOnly) {
        // Radiance (or Reflection) with the depth-stencil target, which is tested, never written.
        bindSurfaceOutput(context.targets, SurfaceOutput::Forward, mirroring_, fused);
        glEnable(GL_DEPTH_TEST);
        glDepthFunc(context.targets.depth().fartherFunc);
        glDepthMask(GL_FALSE);
    } else {
        // Every pixel; the sky's are left black for SkyPass to draw over.
        glBindFramebuffer(GL_FRAMEBUFFER, context.targets.radianceOnlyFramebuffer(fused));
        glViewport(0, 0, context.targets.width(), context.targets.height());
        glDisable(GL_DEPTH_TEST);
    }
    bool inPlace = !mirrored && context.frame.depthReadInPlace;
    bindGBufferInputs(context.targets, inPlace ? DepthRead::FromTarget : DepthRead::FromCopy);
    beginMirroredDraw(mirroring_);
    if (mirrored) beginWaterBoundedDraw(context);
    std::string program = mirrored ? "lighting.mirrored" : fused ? "lighting.tonemapped" : "lighting";
    if (LightTilingPass::tiledLightsActive(context.frame, mirroring_)) program += ".tiled";
    glUseProgram(context.shaders.program(context.targets.layout().program(program)));
    context.geometry.drawFullscreenTriangle();
    if (mirrored) endWaterBoundedDraw(context);
    endMirroredDraw(mirroring_);
    glDepthMask(GL_TRUE);
    glDisable(GL_DEPTH_TEST);
}

}  // namespace oasis
