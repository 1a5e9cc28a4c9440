// Tiled light culling: one work group per screen tile (OASIS_LIGHT_TILE_SIZE^2 pixels) bounds the
// tile's G-buffer surfaces with a box (positions as the lighting pass reads them: stored, or rebuilt
// from depth under either convention; a reflection's where it really is) and lists the lights whose
// sphere reaches the box, in light order, into the tile's slice of LightTileBuffer. A box holds
// every surface of the tile, so any light that lights one of its pixels is listed; sky pixels are
// left out, and a tile of sky alone lists nothing.
#define LIGHT_TILES_WRITE
#include "common/frame_block.glsl"
#include "common/gbuffer.glsl"
#include "common/lights.glsl"
#include "common/light_tiles.glsl"

layout(local_size_x = OASIS_LIGHT_TILE_SIZE, local_size_y = OASIS_LIGHT_TILE_SIZE) in;

const int THREADS = OASIS_LIGHT_TILE_SIZE * OASIS_LIGHT_TILE_SIZE;
shared uint boxMin[3];           // the box, as order-preserving bit patterns of floats (atomics are on uints)
shared uint boxMax[3];
shared uint hitsOf[THREADS];     // lights each invocation found, then where its run starts in the list
shared uint tileTotal;

// Floats as uints whose unsigned order is the floats' order: negatives flipped whole, positives
// with the sign bit set.
uint orderedBits(float value) {
    uint bits = floatBitsToUint(value);
    return (bits & 0x80000000u) != 0u ? ~bits : (bits | 0x80000000u);
}
float fromOrderedBits(uint bits) {
    return uintBitsToFloat((bits & 0x80000000u) != 0u ? (bits & 0x7FFFFFFFu) : ~bits);
}

// The sphere reaches the box: the box's nearest point lies inside it. The radius is widened by a
// part in 10^4 so that rounding never leaves out a light pointLightRadiance() would count.
bool lightReachesBox(PointLight light, vec3 lo, vec3 hi) {
    vec3 centre = light.positionRadius.xyz;
    vec3 offset = clamp(centre, lo, hi) - centre;
    float radius = light.positionRadius.w * 1.0001;
    return dot(offset, offset) < radius * radius;
}

void main() {
    ivec2 frameSize = textureSize(gInfo, 0);
    ivec2 pixel = ivec2(gl_GlobalInvocationID.xy);
    uint local = gl_LocalInvocationIndex;
    if (local < 3u) {
        boxMin[local] = 0xFFFFFFFFu;
        boxMax[local] = 0u;
    }
    memoryBarrierShared();
    barrier();
    if (all(lessThan(pixel, frameSize)) && !gbufferSkyAt(pixel)) {
        Surface s;
        s.relativePosition = gbufferPositionAt(pixel);
        s.flags = gbufferFlagsAt(pixel);
        vec3 position = litPosition(s);
        for (int axis = 0; axis < 3; ++axis) {
            atomicMin(boxMin[axis], orderedBits(position[axis]));
            atomicMax(boxMax[axis], orderedBits(position[axis]));
        }
    }
    memoryBarrierShared();
    barrier();

    // Each invocation tests a contiguous run of the lights, so the list comes out in light order
    // and the lighting pass sums in the same order every frame.
    bool empty = boxMin[0] > boxMax[0];
    vec3 lo = vec3(fromOrderedBits(boxMin[0]), fromOrderedBits(boxMin[1]), fromOrderedBits(boxMin[2]));
    vec3 hi = vec3(fromOrderedBits(boxMax[0]), fromOrderedBits(boxMax[1]), fromOrderedBits(boxMax[2]));
    int count = empty ? 0 : lightCount();
    int perInvocation = (count + THREADS - 1) / THREADS;
    int first = min(int(local) * perInvocation, count), last = min(first + perInvocation, count);
    uint hits = 0u;
    for (int i = first; i < last; ++i)
        if (lightReachesBox(lightAt(i), lo, hi)) ++hits;
    hitsOf[local] = hits;
    memoryBarrierShared();
    barrier();
    if (local == 0u) {  // exclusive prefix sum: where each run starts
        uint total = 0u;
        for (int k = 0; k < THREADS; ++k) {
            uint h = hitsOf[k];
            hitsOf[k] = total;
            total += h;
        }
        tileTotal = total;
    }
    memoryBarrierShared();
    barrier();

    int tile = int(gl_WorkGroupID.y * gl_NumWorkGroups.x + gl_WorkGroupID.x);
    int base = tile * LIGHT_TILE_STRIDE;
    if (local == 0u) tileWords[base] = tileTotal;
    // An overflowing tile's list is never read (the lighting pass loops over every light there).
    if (tileTotal > uint(LIGHT_TILE_MAX)) return;
    uint slot = hitsOf[local];
    for (int i = first; i < last; ++i)
        if (lightReachesBox(lightAt(i), lo, hi)) tileWords[base + 1 + int(slot++)] = uint(i);
}
