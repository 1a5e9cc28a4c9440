// The grid's heights by transform feedback (core in OpenGL 3.0 and OpenGL ES 3.0, so every tier
// takes this one path): terrain.vert's OUTPUT_HEIGHTS variant, one point per grid vertex.
#include "passes/terrain_heights_pass.h"

namespace oasis {

void TerrainHeightsPass::execute(PassContext& context) {
    glUseProgram(context.shaders.program("terrain.heights"));
    context.geometry.computeTerrainHeights();
}

}  // namespace oasis
