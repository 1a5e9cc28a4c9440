// Vegetation: depth-tested and written like the terrain, both faces drawn (a billboard turns to
// face the camera, and a mirror reverses its winding); direct draws mark kStencilVegetation.
#include "passes/vegetation_pass.h"

#include "render/texture_units.h"

namespace oasis {

void VegetationPass::execute(PassContext& context) {
    beginSurfaceDraw(context, kStencilVegetation);
    glDisable(GL_CULL_FACE);
    glUseProgram(surfaceProgram(context, "vegetation"));
    // The mirrored billboards read the visible water's rectangle to drop those that miss it.
    const bool readsWaterBounds = mirroring_ == Mirroring::Mirrored && context.waterBounds;
    if (readsWaterBounds) glBindBufferBase(GL_SHADER_STORAGE_BUFFER, kWaterBoundsStorageBinding, context.waterBounds);
    // The draw binds the plant atlas itself: made once for the scene, it is no frame resource a
    // declaration could bind (the instances it draws are: PlantInstances).
    context.vegetation.draw(mirroring_);
    if (readsWaterBounds) glBindBufferBase(GL_SHADER_STORAGE_BUFFER, kWaterBoundsStorageBinding, 0);
    endSurfaceDraw();
}

}  // namespace oasis
