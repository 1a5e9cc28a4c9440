// The sky is a full-screen triangle at the far plane: depth test LEQUAL (GEQUAL reversed) against
// the cleared far-plane depth keeps it only where nothing was drawn; it writes no depth and no stencil.
#include "passes/sky_pass.h"

namespace oasis {

void SkyPass::execute(PassContext& context) {
    bool fused = toneMapFusedInto(context.frame, SurfaceOutput::Forward, mirroring_);
    bindDeclaredOutputs(context);
    glEnable(GL_DEPTH_TEST);
    glDepthFunc(context.targets.depth().nearerOrEqualFunc);
    glDepthMask(GL_FALSE);
    beginMirroredDraw(mirroring_);
    if (mirroring_ == Mirroring::Mirrored) beginWaterBoundedDraw(context);
    glUseProgram(context.shaders.program(variantName("sky", SurfaceOutput::Forward, mirroring_) +
                                         (fused ? ".tonemapped" : "")));
    context.geometry.drawFullscreenTriangle();
    if (mirroring_ == Mirroring::Mirrored) endWaterBoundedDraw(context);
    endMirroredDraw(mirroring_);
    glDepthMask(GL_TRUE);
    glDisable(GL_DEPTH_TEST);
}

}  // namespace oasis
