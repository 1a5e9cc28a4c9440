// One full-screen triangle; every pixel's surface comes from the G-buffer.
#include "passes/lighting_pass.h"

namespace oasis {

void LightingPass::execute(PassContext& context) {
    bindSurfaceOutput(context.targets, SurfaceOutput::Forward, mirroring_);
    glDisable(GL_DEPTH_TEST);
    bindGBufferInputs(context.targets);
    beginMirroredDraw(mirroring_);
    if (mirroring_ == Mirroring::Mirrored) beginWaterBoundedDraw(context);
    glUseProgram(context.shaders.program(
        context.targets.layout().program(mirroring_ == Mirroring::Mirrored ? "lighting.mirrored" : "lighting")));
    context.geometry.drawFullscreenTriangle();
    if (mirroring_ == Mirroring::Mirrored) endWaterBoundedDraw(context);
    endMirroredDraw(mirroring_);
}

}  // namespace oasis
