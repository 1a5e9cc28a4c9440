// Terrain: depth-tested, back faces culled; direct draws mark kStencilTerrain.
#include "passes/terrain_pass.h"

namespace oasis {

void TerrainPass::execute(PassContext& context) {
    beginSurfaceDraw(context, kStencilTerrain);
    glEnable(GL_CULL_FACE);
    glCullFace(GL_BACK);
    glUseProgram(context.shaders.program(variantName("terrain", output_, mirroring_)));
    context.geometry.drawTerrain();
    glDisable(GL_CULL_FACE);
    endSurfaceDraw();
}

}  // namespace oasis
