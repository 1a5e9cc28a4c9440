// Terrain: depth-tested, back faces culled, stencil marked with kStencilTerrain.
#include "passes/terrain_pass.h"

namespace oasis {

void TerrainPass::execute(PassContext& context) {
    bindSurfaceOutput(context.targets, output_);
    glEnable(GL_DEPTH_TEST);
    glDepthFunc(GL_LESS);
    glDepthMask(GL_TRUE);
    glEnable(GL_CULL_FACE);
    glCullFace(GL_BACK);
    glEnable(GL_STENCIL_TEST);
    glStencilFunc(GL_ALWAYS, kStencilTerrain, 0xFF);
    glStencilOp(GL_KEEP, GL_KEEP, GL_REPLACE);
    glStencilMask(0xFF);
    glUseProgram(context.shaders.program(output_ == SurfaceOutput::GBuffer ? "terrain.gbuffer" : "terrain.forward"));
    context.geometry.drawTerrain();
    glDisable(GL_STENCIL_TEST);
    glDisable(GL_CULL_FACE);
    glDisable(GL_DEPTH_TEST);
}

}  // namespace oasis
