// Terrain: depth-tested, back faces culled; direct draws mark kStencilTerrain.
#include "passes/terrain_pass.h"

namespace oasis {

void TerrainPass::execute(PassContext& context) {
    beginSurfaceDraw(context, kStencilTerrain);
    glEnable(GL_CULL_FACE);
    glCullFace(GL_BACK);
    glUseProgram(surfaceProgram(context, "terrain"));
    context.geometry.drawTerrain();
    glDisable(GL_CULL_FACE);
    endSurfaceDraw();
}

}  // namespace oasis
