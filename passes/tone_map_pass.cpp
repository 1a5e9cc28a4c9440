// One full-screen triangle sampling Radiance.
#include "passes/tone_map_pass.h"

namespace oasis {

void ToneMapPass::execute(PassContext& context) {
    bindDeclaredOutputs(context);
    glDisable(GL_DEPTH_TEST);
    glUseProgram(context.shaders.program("tonemap"));
    context.geometry.drawFullscreenTriangle();
}

}  // namespace oasis
