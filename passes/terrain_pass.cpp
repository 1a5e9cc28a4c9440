// Terrain: depth-tested, back faces culled; direct draws mark kStencilTerrain.
#include "passes/terrain_pass.h"

#include "render/light_paths.h"

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
    // Shaded here (forward), the fragments loop over the point lights through the frame's light path.
    std::string program = variantName("terrain", output_, mirroring_);
    if (output_ == SurfaceOutput::Forward) program += lightsVariantSuffix(context.frame.lightsPath);
    glUseProgram(context.shaders.program(program));
    context.geometry.drawTerrain();
    endMirroredDraw(mirroring_);
    glDisable(GL_STENCIL_TEST);
    glDisable(GL_CULL_FACE);
    glDisable(GL_DEPTH_TEST);
}

}  // namespace oasis
