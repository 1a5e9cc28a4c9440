// Clears with every write mask open so an earlier pass's state cannot leave stale data; only what a
// later pass reads where no surface wrote it: the depth-stencil always (its far plane is "nothing
// drawn"), Info's sky flag in the layouts whose readers have no depth, and for a stopped frame the
// targets the views show whole (Radiance, Reflection).
#include "passes/clear_pass.h"

#include "common/shared_constants.glsl"

namespace oasis {

// The targets the clear leaves for a whole frame. The G-buffer's colour targets are read only where
// a surface was drawn (lighting depth-tests to the surfaces; the views and the probe mask the sky
// themselves: gbufferSkyAt and gbufferSurfaceShownAt in gbuffer.glsl), so clearing them would only
// write bytes no one reads. Where the layout stores position (full, standard) its readers tell the
// sky by Info's SKY flag, so Info alone is cleared; compact tells it by depth and clears no colour.
// Forward clears the depth-stencil only: a whole forward frame writes every pixel of Radiance.
static std::vector<Access> clearedTargets(const FrameSetup& frame, SurfaceOutput output) {
    std::vector<Access> cleared;
    if (output == SurfaceOutput::GBuffer && !frame.positionFromDepth) cleared.push_back({Target::Info, Use::Write});
    // The whole depth-stencil anew (the scissor off): what an earlier pass left there is dead.
    appendDepthStencil(cleared, {Use::DepthWrite, Use::StencilWrite, Use::Replace});
    return cleared;
}

// A frame stopped early shows Radiance and Reflection as they were: LightingPass leaves the sky's
// pixels to SkyPass, and the mirrored passes write Reflection only inside the water, so a frame
// stopped before them starts them from black, not from an earlier frame's.
static std::vector<Access> clearedForStoppedFrame() {
    return {{Target::Radiance, Use::Write}, {Target::Reflection, Use::Write}};
}

std::vector<Access> ClearPass::declaredAccesses(const FrameSetup& frame) const {
    std::vector<Access> used = clearedTargets(frame, output_);
    if (clearsStoppedFrameTargets(frame))
        for (const Access& access : clearedForStoppedFrame()) used.push_back(access);
    return used;
}

void ClearPass::execute(PassContext& context) {
    const FrameTargets& targets = context.targets;
    const GLfloat nothing[4] = {0.0f, 0.0f, 0.0f, 0.0f};
    glColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
    glDepthMask(GL_TRUE);
    glStencilMask(0xFF);
    glDisable(GL_SCISSOR_TEST);
    if (clearsStoppedFrameTargets(context.frame)) {
        // Each on its own: the framebuffer of the G-buffer's writes need not hold them.
        for (const Access& access : clearedForStoppedFrame()) {
            bindFramebufferOf(targets, {access});
            glClearBufferfv(GL_COLOR, 0, nothing);
        }
    }
    std::vector<Access> cleared = clearedTargets(context.frame, output_);
    bindFramebufferOf(targets, cleared);
    if (output_ == SurfaceOutput::GBuffer && !context.frame.positionFromDepth) {
        // clearedInfo() in gbuffer.glsl: the sky flag in the layout's flags channel.
        glm::vec4 skyInfo = targets.layout().clearedInfo();
        glClearBufferfv(GL_COLOR, 0, &skyInfo[0]);
    }
    glClearBufferfi(GL_DEPTH_STENCIL, 0, targets.depth().farPlaneWindowDepth, kStencilNothing);
}

}  // namespace oasis
