// The water quad, stencil only (and the rectangle of visible water, where it can be recorded).
#include "passes/water_mask_pass.h"

#include <limits>

#include "render/texture_units.h"

namespace oasis {

void drawWaterSurface(PassContext& context, const std::string& program) {
    if (!context.depthClamp) {
        glUseProgram(context.shaders.program(program + ".fullscreen"));
        context.geometry.drawFullscreenTriangle();
        return;
    }
    glEnable(GL_DEPTH_CLAMP);
    glUseProgram(context.shaders.program(program));
    context.geometry.drawWaterGrid();
    glDisable(GL_DEPTH_CLAMP);
}

void markWaterStencil(PassContext& context, const char* program) {
    glColorMask(GL_FALSE, GL_FALSE, GL_FALSE, GL_FALSE);
    glEnable(GL_STENCIL_TEST);
    glStencilFunc(GL_ALWAYS, kStencilWater, 0xFF);
    glStencilOp(GL_KEEP, GL_KEEP, GL_REPLACE);
    glStencilMask(0xFF);
    // The plane must not be clipped by the near plane when the eye is at it: the grid is drawn
    // depth-clamped, and without depth clamp a full-screen triangle finds the plane per fragment
    // (common/water_fragment.glsl), since the grid would lose the water nearer than the near plane.
    drawWaterSurface(context, program);
    glDisable(GL_STENCIL_TEST);
    glColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
}

void WaterMaskPass::execute(PassContext& context) {
    bindDeclaredOutputs(context);  // the depth-stencil target alone
    glEnable(GL_DEPTH_TEST);
    glDepthFunc(context.targets.depth().nearerFunc);
    glDepthMask(depth_ == WaterDepth::Written ? GL_TRUE : GL_FALSE);
    if (context.waterBounds) {
        // An empty box (min > max) that the water's fragments widen (common/water_bounds.glsl).
        const GLint empty[4] = {std::numeric_limits<GLint>::max(), std::numeric_limits<GLint>::max(),
                                std::numeric_limits<GLint>::min(), std::numeric_limits<GLint>::min()};
        glBindBufferBase(GL_SHADER_STORAGE_BUFFER, kWaterBoundsStorageBinding, context.waterBounds);
        glBufferSubData(GL_SHADER_STORAGE_BUFFER, 0, sizeof(empty), empty);
    }
    if (context.waterSeen) glBeginQuery(GL_ANY_SAMPLES_PASSED, context.waterSeen);
    markWaterStencil(context, "water.mask");
    if (context.waterSeen) glEndQuery(GL_ANY_SAMPLES_PASSED);
    if (context.waterBounds) {
        glMemoryBarrier(GL_SHADER_STORAGE_BARRIER_BIT);
        glBindBufferBase(GL_SHADER_STORAGE_BUFFER, kWaterBoundsStorageBinding, 0);
    }
    glDepthMask(GL_TRUE);
    glDisable(GL_DEPTH_TEST);
}

}  // namespace oasis
