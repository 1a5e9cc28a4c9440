// The reduced reflection's texels, bilinearly, into the frame's Reflection at its water pixels.
#include "passes/reflection_upsample_pass.h"

#include "render/texture_units.h"

namespace oasis {

void ReflectionUpsamplePass::execute(PassContext& context) {
    // Reflection work, but drawn into the frame's targets: the frame's water rectangle and query.
    // The reduced Reflection is bound from the declaration (bindDeclaredInputs, kInputBindings).
    OnlyWhereWaterIsSeen onlyWithWater(context, true);
    bindDeclaredOutputs(context);
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
