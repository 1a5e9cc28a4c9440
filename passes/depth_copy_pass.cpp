// A full-screen draw that writes each pixel's depth from the G-buffer's depth texture.
#include "passes/depth_copy_pass.h"

#include "render/texture_units.h"

namespace oasis {

void DepthCopyPass::execute(PassContext& context) {
    const FrameTargets& targets = context.targets;
    bindDeclaredOutputs(context);
    glActiveTexture(GL_TEXTURE0 + kUnitDepth);
    glBindTexture(GL_TEXTURE_2D, targets.texture(Target::DepthStencil));
    glTexParameteri(GL_TEXTURE_2D, GL_DEPTH_STENCIL_TEXTURE_MODE, GL_DEPTH_COMPONENT);
    glEnable(GL_DEPTH_TEST);
    glDepthFunc(GL_ALWAYS);
    glDepthMask(GL_TRUE);
    glDisable(GL_STENCIL_TEST);
    // The mirrored copy is read only inside the water (stencil-tested passes).
    bool mirrored = mirroring_ == Mirroring::Mirrored;
    if (mirrored) beginWaterBoundedDraw(context);
    glUseProgram(context.shaders.program(mirrored ? "depth.copy.mirrored" : "depth.copy"));
    context.geometry.drawFullscreenTriangle();
    if (mirrored) endWaterBoundedDraw(context);
    glDisable(GL_DEPTH_TEST);
}

}  // namespace oasis
