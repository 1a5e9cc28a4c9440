// A stencil-masked full-screen draw at the far plane with depth test ALWAYS: only the water
// pixels are touched, never the whole buffer.
#include "passes/reflection_clear_pass.h"

namespace oasis {

void ReflectionClearPass::execute(PassContext& context) {
    const FrameTargets& targets = context.targets;
    if (reflection_ == ReflectionTarget::Cleared) {
        glBindFramebuffer(GL_FRAMEBUFFER, targets.reflectionFramebuffer());
        glViewport(0, 0, targets.width(), targets.height());
        const GLfloat nothing[4] = {0.0f, 0.0f, 0.0f, 0.0f};
        glClearBufferfv(GL_COLOR, 0, nothing);
    }
    if (!context.frame.reflectionsActive) return;

    // The Reflection target's clear above always runs (the views show it outside the water; left
    // alone it would hold whatever the memory held: NaNs on zink); the G-buffer's clear of the
    // water only where water is seen.
    OnlyWhereWaterIsSeen onlyWithWater(context, true);
    bindSurfaceOutput(targets, output_, Mirroring::Mirrored);
    bool writeGBuffer = output_ == SurfaceOutput::GBuffer;
    glColorMask(writeGBuffer, writeGBuffer, writeGBuffer, writeGBuffer);
    glEnable(GL_DEPTH_TEST);
    glDepthFunc(GL_ALWAYS);
    glDepthMask(GL_TRUE);
    beginMirroredDraw(Mirroring::Mirrored);
    beginWaterBoundedDraw(context);
    glUseProgram(context.shaders.program(targets.layout().program("gbuffer.clear")));
    context.geometry.drawFullscreenTriangle();
    endWaterBoundedDraw(context);
    endMirroredDraw(Mirroring::Mirrored);
    glDisable(GL_DEPTH_TEST);
    glColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
}

}  // namespace oasis
