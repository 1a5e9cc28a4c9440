// Clears with every write mask open so an earlier pass's state cannot leave stale data.
#include "passes/clear_pass.h"

namespace oasis {

void ClearPass::execute(PassContext& context) {
    bindSurfaceOutput(context.targets, output_);
    glColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
    glDepthMask(GL_TRUE);
    glStencilMask(0xFF);
    glDisable(GL_SCISSOR_TEST);
    glClearColor(0.0f, 0.0f, 0.0f, 0.0f);
    glClearDepth(1.0);
    glClearStencil(kStencilNothing);
    glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT | GL_STENCIL_BUFFER_BIT);
}

}  // namespace oasis
