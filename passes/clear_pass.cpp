// Clears with every write mask open so an earlier pass's state cannot leave stale data.
#include "passes/clear_pass.h"

#include "common/shared_constants.glsl"

namespace oasis {

void ClearPass::execute(PassContext& context) {
    bindSurfaceOutput(context.targets, output_);
    glColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
    glDepthMask(GL_TRUE);
    glStencilMask(0xFF);
    glDisable(GL_SCISSOR_TEST);
    const GLfloat nothing[4] = {0.0f, 0.0f, 0.0f, 0.0f};
    if (output_ == SurfaceOutput::GBuffer) {
        // CLEARED_INFO in surface.glsl: the sky flag, stored as flags / 255.
        const GLfloat skyInfo[4] = {0.0f, 0.0f, float(OASIS_SURFACE_SKY) / 255.0f, 0.0f};
        for (int attachment = 0; attachment < 3; ++attachment) glClearBufferfv(GL_COLOR, attachment, nothing);
        glClearBufferfv(GL_COLOR, 3, skyInfo);
    } else {
        glClearBufferfv(GL_COLOR, 0, nothing);
    }
    glClearBufferfi(GL_DEPTH_STENCIL, 0, context.targets.depth().farPlaneWindowDepth, kStencilNothing);
}

}  // namespace oasis
