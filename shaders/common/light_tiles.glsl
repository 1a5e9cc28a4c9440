// The per-tile light lists of tiled light culling: written by the compute pass (light_tiles.comp,
// LIGHT_TILES_WRITE), read by the lighting variant (lighting.frag, LIGHTS_TILED). Tile t owns
// LIGHT_TILE_STRIDE words from t * LIGHT_TILE_STRIDE: the nearest and farthest distance of its
// surfaces from the camera (float bits; nearest > farthest for a tile without surfaces), then per
// slice of that range (OASIS_LIGHT_TILE_SLICES equal parts) the number of lights reaching the
// slice's surfaces (the true number, even past the maximum) and up to the maximum light indices,
// in list order.
#ifndef OASIS_LIGHT_TILES_GLSL
#define OASIS_LIGHT_TILES_GLSL
#include "common/shared_constants.glsl"
#include "common/storage_layout.glsl"

const int LIGHT_TILE_SIZE = OASIS_LIGHT_TILE_SIZE;
const int LIGHT_TILE_SLICES = OASIS_LIGHT_TILE_SLICES;
const int LIGHT_TILE_MAX = OASIS_LIGHT_TILE_MAX_LIGHTS;
const int LIGHT_SLICE_STRIDE = OASIS_LIGHT_TILE_MAX_LIGHTS + 1;
const int LIGHT_TILE_STRIDE = 2 + OASIS_LIGHT_TILE_SLICES * LIGHT_SLICE_STRIDE;

#if defined(LIGHT_TILES_WRITE)
OASIS_STORAGE_LAYOUT(OASIS_BINDING_LIGHT_TILES) writeonly buffer LightTileBuffer {
    uint tileWords[];
};
#else
OASIS_STORAGE_LAYOUT(OASIS_BINDING_LIGHT_TILES) readonly buffer LightTileBuffer {
    uint tileWords[];
};
#endif

// Tiles cover the frame row by row from its bottom-left pixel; the last column and row may be partial.
int lightTileOf(ivec2 pixel, ivec2 frameSize) {
    int tilesPerRow = (frameSize.x + LIGHT_TILE_SIZE - 1) / LIGHT_TILE_SIZE;
    ivec2 tile = pixel / LIGHT_TILE_SIZE;
    return tile.y * tilesPerRow + tile.x;
}

// Where a surface at `distanceToCamera` falls in its tile's range, in slices (0..SLICES); the
// slice is its whole part. The compute pass puts a surface within 10^-3 of a slice's edge in both
// slices, so the lighting pass, which computes the same value in another shader, finds every light
// of its surface even where the two round differently.
float lightSlicePosition(float distanceToCamera, float nearest, float farthest) {
    return (distanceToCamera - nearest) / max(farthest - nearest, 1e-20) * float(LIGHT_TILE_SLICES);
}
int lightSliceOf(float slicePosition) { return clamp(int(floor(slicePosition)), 0, LIGHT_TILE_SLICES - 1); }

#endif
