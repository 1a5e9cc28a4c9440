// Terrain: depth-tested, back faces culled; direct draws mark kStencilTerrain.
#include "passes/terrain_pass.h"

namespace oasis {

void TerrainPass::execute(PassContext& context) {
    bindSurfaceOutput(context.targets, output_, mirroring_);
    glEnable(GL_DEPTH_TEST);
    glDepthFunc(GL_LESS);
    glDepthMask(GL_TRUE);
    glEnable(GL_CULL_FACE);
    glCullFace(GL_BACK);
    if (mirroring_ == Mirroring::Direct) {
        glEnable(GL_STENCIL_TEST);
        glStencilFunc(GL_ALWAYS, kStencilTerrain, 0xFF);
        glStencilOp(GL_KEEP, GL_KEEP, GL_REPLACE);
        glStencilMask(0xFF);
    }
    beginMirroredDraw(mirroring_);
    glUseProgram(context.shaders.program(variantName("terrain", output_, mirroring_)));
    context.geometry.drawTerrain();
    endMirroredDraw(mirroring_);
    glDisable(GL_STENCIL_TEST);
    glDisable(GL_CULL_FACE);
    glDisable(GL_DEPTH_TEST);
}

}  // namespace oasis
