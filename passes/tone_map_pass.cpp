// One full-screen triangle sampling Radiance.
#include "passes/tone_map_pass.h"

#include "render/texture_units.h"

namespace oasis {

void ToneMapPass::execute(PassContext& context) {
    const FrameTargets& targets = context.targets;
    bindDeclaredOutputs(context);
    glDisable(GL_DEPTH_TEST);
    glActiveTexture(GL_TEXTURE0 + kUnitSource);
    glBindTexture(GL_TEXTURE_2D, targets.texture(Target::Radiance));
    glUseProgram(context.shaders.program("tonemap"));
    context.geometry.drawFullscreenTriangle();
}

}  // namespace oasis
