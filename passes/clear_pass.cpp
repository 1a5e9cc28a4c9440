// Clears with every write mask open so an earlier pass's state cannot leave stale data; only what a
// later pass does not overwrite (depth-stencil always, the G-buffer, Radiance for a stopped frame).
#include "passes/clear_pass.h"

#include "common/shared_constants.glsl"

namespace oasis {

// The targets the clear leaves: the G-buffer's, or for forward only the depth-stencil (a whole
// forward frame writes every pixel of Radiance); Radiance too for a frame stopped early.
static std::vector<Access> clearedTargets(const FrameSetup& frame, SurfaceOutput output) {
    std::vector<Access> cleared;
    if (output == SurfaceOutput::GBuffer)
        for (Target target : surfaceOutputTargets(frame, output)) cleared.push_back({target, Use::Write});
    appendDepthStencil(cleared, {Use::DepthWrite, Use::StencilWrite});
    return cleared;
}

std::vector<Access> ClearPass::accesses(const FrameSetup& frame) const {
    std::vector<Access> used = clearedTargets(frame, output_);
    if (!frame.runsToEnd) used.push_back({Target::Radiance, Use::Write});
    return used;
}

void ClearPass::execute(PassContext& context) {
    std::vector<Access> cleared = clearedTargets(context.frame, output_);
    if (output_ == SurfaceOutput::Forward && !context.frame.runsToEnd) cleared.push_back({Target::Radiance, Use::Write});
    bindFramebufferOf(context.targets, cleared);
    glColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
    glDepthMask(GL_TRUE);
    glStencilMask(0xFF);
    glDisable(GL_SCISSOR_TEST);
    const GLfloat nothing[4] = {0.0f, 0.0f, 0.0f, 0.0f};
    if (output_ == SurfaceOutput::GBuffer) {
        // clearedInfo() in gbuffer.glsl: the sky flag in the layout's flags channel.
        glm::vec4 skyInfo = context.targets.layout().clearedInfo();
        const FrameTargets& targets = context.targets;
        // Albedo, normal and position are read only where the sky flag is clear, but the views
        // and the probe show them everywhere, so they are cleared too; Info once, to the sky.
        for (int slot = 0; slot < targets.gbufferSlotCount(); ++slot)
            glClearBufferfv(GL_COLOR, slot, slot == targets.gbufferSlot(Target::Info) ? &skyInfo[0] : nothing);
        if (!context.frame.runsToEnd) {
            // LightingPass leaves the sky's pixels to SkyPass: a frame stopped between them shows
            // Radiance from black there, not an earlier frame's.
            bindFramebufferOf(targets, {{Target::Radiance, Use::Write}});
            glClearBufferfv(GL_COLOR, 0, nothing);
            bindFramebufferOf(targets, cleared);
        }
    } else if (!context.frame.runsToEnd) {
        // A whole forward frame needs no colour clear: every pixel of Radiance is written by a
        // surface or, where none was drawn (depth still at the far plane), by SkyPass. A frame
        // stopped early shows Radiance as it was, so it starts from black.
        glClearBufferfv(GL_COLOR, 0, nothing);
    }
    glClearBufferfi(GL_DEPTH_STENCIL, 0, context.targets.depth().farPlaneWindowDepth, kStencilNothing);
}

}  // namespace oasis
