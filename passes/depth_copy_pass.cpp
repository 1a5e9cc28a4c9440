// A depth-only blit between two D24S8 textures of the same size (GL 3.0: every tier has it).
#include "passes/depth_copy_pass.h"

namespace oasis {

void DepthCopyPass::execute(PassContext& context) {
    const FrameTargets& targets = context.targets;
    glBindFramebuffer(GL_READ_FRAMEBUFFER, targets.gbufferFramebuffer());
    glBindFramebuffer(GL_DRAW_FRAMEBUFFER, targets.sceneDepthFramebuffer());
    glBlitFramebuffer(0, 0, targets.width(), targets.height(), 0, 0, targets.width(), targets.height(),
                      GL_DEPTH_BUFFER_BIT, GL_NEAREST);
    glBindFramebuffer(GL_FRAMEBUFFER, 0);
}

}  // namespace oasis
