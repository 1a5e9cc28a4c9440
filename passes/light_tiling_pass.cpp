// Tiled light culling: one invocation per screen tile; the lists are made visible to the
// lighting pass's storage reads by a barrier. The buffer grows with the frame and is kept.
#include "passes/light_tiling_pass.h"

#include "common/shared_constants.glsl"
#include "render/texture_units.h"

namespace oasis {

int LightTilingPass::tilesAcross(int pixels) { return (pixels + OASIS_LIGHT_TILE_SIZE - 1) / OASIS_LIGHT_TILE_SIZE; }

size_t LightTilingPass::listBytes(int width, int height) {
    // Per tile (common/light_tiles.glsl): its distance range, then per slice a count and a list.
    size_t wordsPerTile = 2 + size_t(OASIS_LIGHT_TILE_SLICES) * size_t(OASIS_LIGHT_TILE_MAX_LIGHTS + 1);
    return size_t(tilesAcross(width)) * size_t(tilesAcross(height)) * wordsPerTile * sizeof(GLuint);
}

void LightTilingPass::execute(PassContext& context) {
    const FrameTargets& targets = context.targets;
    const int divisor = drawnAtDivisor(context.frame);  // the mirrored lists at the reflection's scale
    const int width = targets.width(divisor), height = targets.height(divisor);
    size_t bytes = listBytes(width, height);
    if (!tiles_.name()) tiles_ = gl::createBuffer("tiled lights: per-tile light lists");
    if (bytes > tilesBytes_) {
        glBindBuffer(GL_SHADER_STORAGE_BUFFER, tiles_.name());
        glBufferData(GL_SHADER_STORAGE_BUFFER, GLsizeiptr(bytes), nullptr, GL_DYNAMIC_COPY);
        tilesBytes_ = bytes;
    }
    // Its own lists, which it writes (the readers get them bound from their declarations).
    glBindBufferRange(GL_SHADER_STORAGE_BUFFER, kLightTileStorageBinding, tiles_.name(), 0, GLsizeiptr(bytes));
    glUseProgram(context.shaders.program(targets.layout().program(mirroring_ == Mirroring::Mirrored ? "light.tiles.mirrored" : "light.tiles")));
    // The G-buffer was drawn just now with its framebuffer still bound. GL needs no barrier here
    // (drawn texels are visible to later commands' fetches), but softpipe's dispatch reads them
    // stale from its render-target cache: the driver workaround flush-before-compute-read.
    if (context.flushBeforeComputeRead) glMemoryBarrier(GL_TEXTURE_FETCH_BARRIER_BIT);
    // One invocation per tile, 8x8 tiles a work group (light_tiles.comp).
    glDispatchCompute(GLuint((tilesAcross(width) + 7) / 8), GLuint((tilesAcross(height) + 7) / 8), 1);
    glMemoryBarrier(GL_SHADER_STORAGE_BARRIER_BIT);
}

}  // namespace oasis
