// Vegetation: depth-tested and written like the terrain, both faces drawn (a billboard turns to
// face the camera, and a mirror reverses its winding); direct draws mark kStencilVegetation.
#include "passes/vegetation_pass.h"

namespace oasis {

void VegetationPass::execute(PassContext& context) {
    beginSurfaceDraw(context, kStencilVegetation);
    glDisable(GL_CULL_FACE);
    GLuint program = surfaceProgram(context, "vegetation");
    glUseProgram(program);
    context.vegetation.draw(mirroring_, program, context.frame.trimmedBillboards);
    endSurfaceDraw();
}

}  // namespace oasis
