// Display texture -> default framebuffer.
#include "passes/present_pass.h"

#include "render/texture_units.h"

namespace oasis {

void PresentPass::run(PassContext& context, int windowWidth, int windowHeight) {
    gl::DebugGroup group(name().c_str());
    glBindFramebuffer(GL_FRAMEBUFFER, 0);
    glViewport(0, 0, windowWidth, windowHeight);
    glDisable(GL_DEPTH_TEST);
    glDisable(GL_STENCIL_TEST);
    glActiveTexture(GL_TEXTURE0 + kUnitSource);
    glBindTexture(GL_TEXTURE_2D, context.targets.displayTexture());
    glUseProgram(context.shaders.program("present"));
    context.geometry.drawFullscreenTriangle();
}

}  // namespace oasis
