// The per-tile light lists of tiled light culling: written by the compute pass (light_tiles.comp,
// LIGHT_TILES_WRITE), read by the lighting variant (lighting.frag, LIGHTS_TILED). Tile t owns
// OASIS_LIGHT_TILE_MAX_LIGHTS + 1 words from t * stride: the number of lights reaching the tile
// (the true number, even past the maximum), then up to the maximum light indices in list order.
#ifndef OASIS_LIGHT_TILES_GLSL
#define OASIS_LIGHT_TILES_GLSL
#include "common/shared_constants.glsl"

const int LIGHT_TILE_SIZE = OASIS_LIGHT_TILE_SIZE;
const int LIGHT_TILE_MAX = OASIS_LIGHT_TILE_MAX_LIGHTS;
const int LIGHT_TILE_STRIDE = OASIS_LIGHT_TILE_MAX_LIGHTS + 1;

#if defined(LIGHT_TILES_WRITE)
layout(std430) writeonly buffer LightTileBuffer {
    uint tileWords[];
};
#else
layout(std430) readonly buffer LightTileBuffer {
    uint tileWords[];
};
#endif

// Tiles cover the frame row by row from its bottom-left pixel; the last column and row may be partial.
int lightTileOf(ivec2 pixel, ivec2 frameSize) {
    int tilesPerRow = (frameSize.x + LIGHT_TILE_SIZE - 1) / LIGHT_TILE_SIZE;
    ivec2 tile = pixel / LIGHT_TILE_SIZE;
    return tile.y * tilesPerRow + tile.x;
}

#endif
