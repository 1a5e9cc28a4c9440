// The reduced reflection's texels, bilinearly, into the frame's Reflection at its water pixels.
#include "passes/reflection_upsample_pass.h"

#include "render/texture_units.h"

namespace oasis {

void ReflectionUpsamplePass::execute(PassContext& context) {
    if (!context.reflectionTargets) return;  // drawn at full resolution: nothing to bring over
    // Reflection work, but drawn into the frame's targets: the frame's water rectangle and query.
    OnlyWhereWaterIsSeen onlyWithWater(context, true);
    bindDeclaredOutputs(context);
    // Bound by hand: the reduced reflection's own Reflection is none of this context's targets,
    // so no declaration of it binds it (the frame's Reflection is what the pass writes).
    glActiveTexture(GL_TEXTURE0 + kUnitSource);
    glBindTexture(GL_TEXTURE_2D, context.reflectionTargets->texture(Target::Reflection));
    glEnable(GL_STENCIL_TEST);
    glStencilFunc(GL_EQUAL, kStencilWater, 0xFF);
    glStencilOp(GL_KEEP, GL_KEEP, GL_KEEP);
    glStencilMask(0x00);
    beginWaterBoundedDraw(context);
    glUseProgram(context.shaders.program("reflection.upsample"));
    context.geometry.drawFullscreenTriangle();
    endWaterBoundedDraw(context);
    glDisable(GL_STENCIL_TEST);
    glStencilMask(0xFF);
}

}  // namespace oasis
