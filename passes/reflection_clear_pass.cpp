// A stencil-masked full-screen draw at the far plane with depth test ALWAYS: only the water
// pixels are touched, never the whole buffer. At a reduced resolution the reflection's own
// targets first get their water mask: the water plane, drawn without a depth test.
#include "passes/reflection_clear_pass.h"

#include "passes/water_mask_pass.h"

namespace oasis {
namespace {

// The reduced reflection's depth-stencil cleared and its water marked wherever the plane lies,
// seen or hidden: the frame's depth is not at this size to test against, and the bilinear
// upsample's taps beside a shore then land on mirrored scene too, not on the clear colour.
// Its Reflection is cleared as well, so taps just outside the water read zero, never stale memory.
void markReducedWater(PassContext& reflection) {
    const FrameTargets& targets = reflection.targets;
    bindFramebufferOf(targets, {{Target::Reflection, Use::Write}, {Target::DepthStencil, Use::StencilWrite}});
    const GLfloat nothing[4] = {0.0f, 0.0f, 0.0f, 0.0f};
    glClearBufferfv(GL_COLOR, 0, nothing);
    glDepthMask(GL_TRUE);
    glStencilMask(0xFF);
    glClearBufferfi(GL_DEPTH_STENCIL, 0, targets.depth().farPlaneWindowDepth, kStencilNothing);
    markWaterStencil(reflection, "water.mask.plane");  // no depth test: every point of the plane
}

}  // namespace

// The mirrored draw that resets the water's depth (and the G-buffer's "nothing drawn" there).
static std::vector<Access> waterReset(const FrameSetup& frame, SurfaceOutput output) {
    std::vector<Access> reset;
    if (output == SurfaceOutput::GBuffer)
        for (Target target : surfaceOutputTargets(frame, output)) reset.push_back({target, Use::Write});
    appendDepthStencil(reset, {Use::DepthWrite, Use::StencilTest});
    return reset;
}

std::vector<Access> ReflectionClearPass::accesses(const FrameSetup& frame) const {
    std::vector<Access> used;
    if (reflection_ == ReflectionTarget::Cleared) used.push_back({Target::Reflection, Use::Write});
    if (frame.reflectionsActive)
        for (const Access& access : waterReset(frame, output_)) used.push_back(access);
    return used;
}

void ReflectionClearPass::execute(PassContext& context) {
    const FrameTargets& targets = context.targets;
    if (reflection_ == ReflectionTarget::Cleared) {
        bindFramebufferOf(targets, {{Target::Reflection, Use::Write}});
        const GLfloat nothing[4] = {0.0f, 0.0f, 0.0f, 0.0f};
        glClearBufferfv(GL_COLOR, 0, nothing);
    }
    if (!context.frame.reflectionsActive) return;

    // The Reflection target's clear above always runs (the views show it outside the water; left
    // alone it would hold whatever the memory held: NaNs on zink); the G-buffer's clear of the
    // water only where water is seen.
    OnlyWhereWaterIsSeen onlyWithWater(context, true);
    ReflectionContext reflection(context);
    PassContext& mirrored = reflection.get();
    if (reflection.reduced()) markReducedWater(mirrored);
    bindFramebufferOf(mirrored.targets, waterReset(mirrored.frame, output_));
    bool writeGBuffer = output_ == SurfaceOutput::GBuffer;
    glColorMask(writeGBuffer, writeGBuffer, writeGBuffer, writeGBuffer);
    glEnable(GL_DEPTH_TEST);
    glDepthFunc(GL_ALWAYS);
    glDepthMask(GL_TRUE);
    beginMirroredDraw(Mirroring::Mirrored);
    beginWaterBoundedDraw(mirrored);
    glUseProgram(mirrored.shaders.program(mirrored.targets.layout().program("gbuffer.clear")));
    mirrored.geometry.drawFullscreenTriangle();
    endWaterBoundedDraw(mirrored);
    endMirroredDraw(Mirroring::Mirrored);
    glDisable(GL_DEPTH_TEST);
    glColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
}

}  // namespace oasis
