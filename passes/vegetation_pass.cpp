// Vegetation: depth-tested and written like the terrain, both faces drawn (a billboard turns to
// face the camera, and a mirror reverses its winding); direct draws mark kStencilVegetation.
#include "passes/vegetation_pass.h"

namespace oasis {

void VegetationPass::execute(PassContext& context) {
    beginSurfaceDraw(context, kStencilVegetation);
    glDisable(GL_CULL_FACE);
    glUseProgram(surfaceProgram(context, "vegetation"));
    context.vegetation.draw(mirroring_);
    endSurfaceDraw();
}

}  // namespace oasis
