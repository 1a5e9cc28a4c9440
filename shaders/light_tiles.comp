// Tiled light culling: one invocation per screen tile (OASIS_LIGHT_TILE_SIZE^2 pixels) bounds the
// tile's G-buffer surfaces with two boxes (positions as the lighting pass reads them: stored, or rebuilt
// from depth under either convention; a reflection's where it really is) and lists the lights whose
// sphere reaches the box, in light order, into the tile's slice of LightTileBuffer. The boxes hold
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
    uint flags = gbufferFlagsAt(pixel);
#if defined(MIRRORED)
    if ((flags & SURFACE_REFLECTED) == 0u) return false;
#endif
    if ((flags & SURFACE_SKY) != 0u) return false;
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
    // Two boxes, split at the middle of the tile's range of distances from the camera: a tile
    // across a silhouette (a hill before the far shore) then leaves out the lights in the gap.
    vec3 position;
    float nearest = 3.0e38, farthest = 0.0;
    for (int y = first.y; y < last.y; ++y)
        for (int x = first.x; x < last.x; ++x)
            if (tileSurfaceAt(ivec2(x, y), position)) {
                float distanceToCamera = length(position);
                nearest = min(nearest, distanceToCamera);
                farthest = max(farthest, distanceToCamera);
            }
    int base = lightTileOf(first, frameSize) * LIGHT_TILE_STRIDE;
    uint listed = 0u;
    if (nearest <= farthest) {  // a tile without surfaces of this half lists nothing
        float split = 0.5 * (nearest + farthest);
        vec3 nearLo = vec3(3.0e38), nearHi = vec3(-3.0e38), farLo = nearLo, farHi = nearHi;
        for (int y = first.y; y < last.y; ++y)
            for (int x = first.x; x < last.x; ++x)
                if (tileSurfaceAt(ivec2(x, y), position)) {
                    if (length(position) <= split) {
                        nearLo = min(nearLo, position);
                        nearHi = max(nearHi, position);
                    } else {
                        farLo = min(farLo, position);
                        farHi = max(farHi, position);
                    }
                }
        int count = lightCount();
        for (int i = 0; i < count; ++i) {
            PointLight light = lightAt(i);
            // An empty far box (all surfaces at one distance) has lo > hi: clamp then yields a point
            // that is not in it, so it is skipped explicitly.
            bool reaches = lightReachesBox(light, nearLo, nearHi) ||
                           (farLo.x <= farHi.x && lightReachesBox(light, farLo, farHi));
            if (!reaches) continue;
            // Past the maximum only the count goes on: the lighting pass then uses every light.
            if (listed < uint(LIGHT_TILE_MAX)) tileWords[base + 1 + int(listed)] = uint(i);
            ++listed;
        }
    }
    tileWords[base] = listed;
}
