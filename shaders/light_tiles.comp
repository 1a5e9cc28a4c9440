// Tiled light culling: one invocation per screen tile (OASIS_LIGHT_TILE_SIZE^2 pixels) cuts the
// range of distances of the tile's G-buffer surfaces into slices, bounds each slice's with a box (positions as the lighting pass reads them: stored, or rebuilt
// from depth under either convention; a reflection's where it really is) and lists per slice the lights whose
// sphere reaches its box, in light order, into the tile's part of LightTileBuffer. The boxes hold
// every surface of the tile, so any light that lights one of its pixels is listed; sky pixels are
// left out, and a tile of sky alone lists nothing. MIRRORED: the reflection's surfaces only.
#define LIGHT_TILES_WRITE
#include "common/frame_block.glsl"
#include "common/gbuffer.glsl"
#include "common/lights.glsl"
#include "common/light_tiles.glsl"

// One invocation per tile, 8x8 tiles a group: no shared memory, atomics or barriers, which
// llvmpipe runs slowly (a work group per tile took about twice as long there), and the list comes
// out in light order by itself, so the lighting pass sums in the same order every frame.
layout(local_size_x = 8, local_size_y = 8) in;

// The sphere reaches the box: the box's nearest point lies inside it. The radius is widened by a
// part in 10^4 so that rounding never leaves out a light pointLightRadiance() would count.
bool lightReachesBox(PointLight light, vec3 lo, vec3 hi) {
    vec3 centre = light.positionRadius.xyz;
    vec3 offset = clamp(centre, lo, hi) - centre;
    float radius = light.positionRadius.w * 1.0001;
    return dot(offset, offset) < radius * radius;
}

// The tile's surfaces of this half: the direct scene's, or (MIRRORED) the reflection's, which lie
// inside the water only; outside it the G-buffer still holds the direct scene, never lit here.
bool tileSurfaceAt(ivec2 pixel, out vec3 position) {
    // The sky first: there the flags are undefined where the layout does not clear them.
    if (gbufferSkyAt(pixel)) return false;
    uint flags = gbufferFlagsAt(pixel);
#if defined(MIRRORED)
    if ((flags & SURFACE_REFLECTED) == 0u) return false;
#endif
    Surface s;
    s.relativePosition = gbufferPositionAt(pixel);
    s.flags = flags;
    position = litPosition(s);
    return true;
}

void main() {
    ivec2 frameSize = textureSize(gInfo, 0);
    ivec2 tile = ivec2(gl_GlobalInvocationID.xy);
    ivec2 tiles = (frameSize + LIGHT_TILE_SIZE - 1) / LIGHT_TILE_SIZE;
    if (any(greaterThanEqual(tile, tiles))) return;
    ivec2 first = tile * LIGHT_TILE_SIZE, last = min(first + LIGHT_TILE_SIZE, frameSize);
    // The tile's range of distances, cut into slices, each bounded by a box: a tile across a
    // silhouette (a hill before the far shore) leaves out the lights in the gap, and a pixel tests
    // only the lights of its slice.
    vec3 position;
    float nearest = 3.0e38, farthest = 0.0;
    for (int y = first.y; y < last.y; ++y)
        for (int x = first.x; x < last.x; ++x)
            if (tileSurfaceAt(ivec2(x, y), position)) {
                float distanceToCamera = length(position);
                nearest = min(nearest, distanceToCamera);
                farthest = max(farthest, distanceToCamera);
            }
    int tileBase = lightTileOf(first, frameSize) * LIGHT_TILE_STRIDE;
    tileWords[tileBase] = floatBitsToUint(nearest);
    tileWords[tileBase + 1] = floatBitsToUint(farthest);
    vec3 lo[LIGHT_TILE_SLICES], hi[LIGHT_TILE_SLICES];
    for (int k = 0; k < LIGHT_TILE_SLICES; ++k) {
        lo[k] = vec3(3.0e38);
        hi[k] = vec3(-3.0e38);
    }
    if (nearest <= farthest)
        for (int y = first.y; y < last.y; ++y)
            for (int x = first.x; x < last.x; ++x)
                if (tileSurfaceAt(ivec2(x, y), position)) {
                    float at = lightSlicePosition(length(position), nearest, farthest);
                    int slice = lightSliceOf(at);
                    // Near a slice's edge: in the neighbour's box too (see lightSlicePosition).
                    float inSlice = at - float(slice);
                    int neighbour = inSlice < 1e-3 ? slice - 1 : inSlice > 1.0 - 1e-3 ? slice + 1 : slice;
                    neighbour = clamp(neighbour, 0, LIGHT_TILE_SLICES - 1);
#if defined(OASIS_ARRAY_WRITE_BY_LOOP)
                    // The driver workaround array-write-by-loop (gl/driver_workarounds.h): softpipe
                    // lands a[i] = x with i differing per invocation in the element its first
                    // invocation of four names; writes at constant indices land where they should.
                    for (int k = 0; k < LIGHT_TILE_SLICES; ++k)
                        if (k == slice || k == neighbour) {
                            lo[k] = min(lo[k], position);
                            hi[k] = max(hi[k], position);
                        }
#else
                    lo[slice] = min(lo[slice], position);
                    hi[slice] = max(hi[slice], position);
                    lo[neighbour] = min(lo[neighbour], position);
                    hi[neighbour] = max(hi[neighbour], position);
#endif
                }
    uint listed[LIGHT_TILE_SLICES];
    vec3 tileLo = vec3(3.0e38), tileHi = vec3(-3.0e38);
    for (int k = 0; k < LIGHT_TILE_SLICES; ++k) {
        listed[k] = 0u;
        tileLo = min(tileLo, lo[k]);
        tileHi = max(tileHi, hi[k]);
    }
    int count = nearest <= farthest ? lightCount() : 0;  // a tile without surfaces of this half lists nothing
    for (int i = 0; i < count; ++i) {
        PointLight light = lightAt(i);
        if (!lightReachesBox(light, tileLo, tileHi)) continue;  // most lights: one test for the whole tile
        for (int k = 0; k < LIGHT_TILE_SLICES; ++k) {
            // An empty slice's box has lo > hi, where clamp() would give a point outside it.
            if (lo[k].x > hi[k].x || !lightReachesBox(light, lo[k], hi[k])) continue;
            // Past the maximum only the count goes on: the lighting pass then uses every light.
            if (listed[k] < uint(LIGHT_TILE_MAX)) tileWords[tileBase + 2 + k * LIGHT_SLICE_STRIDE + 1 + int(listed[k])] = uint(i);
            ++listed[k];
        }
    }
    for (int k = 0; k < LIGHT_TILE_SLICES; ++k) tileWords[tileBase + 2 + k * LIGHT_SLICE_STRIDE] = listed[k];
}
