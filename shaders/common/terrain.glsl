// The terrain's height (same maths as src/scene/terrain.cpp) and its material: sand by the
// water, grass on gentle ground, rock on steep or high ground, broken up by noise.
#ifndef OASIS_TERRAIN_GLSL
#define OASIS_TERRAIN_GLSL
#include "common/detail_noise.glsl"
#include "common/noise.glsl"
#include "common/surface.glsl"

#include "common/shared_constants.glsl"

// (height, d height / dx, d height / dz) at the point `relativeXZ` (world units) from the camera.
// The noise is taken around the camera's exactly known noise coordinates (FrameData's origins),
// so a camera 1e5 units out gets the same precision as one at the origin.
vec3 terrainHeightFromCamera(vec2 relativeXZ) {
    vec4 shape = frame.terrainShape;  // frequency, amplitude, base height, octaves
    vec3 n = fractalNoiseFrom(frame.terrainNoiseOrigins, relativeXZ * shape.x, int(shape.w));
    // h = amplitude * (n + k n^2): broad flat valleys for the water, sharper ridges above.
    const float k = OASIS_TERRAIN_VALLEY_FLATTENING;
    float slopeScale = shape.y * shape.x * (1.0 + 2.0 * k * n.x);
    return vec3(shape.y * (n.x + k * n.x * n.x) + shape.z, slopeScale * n.y, slopeScale * n.z);
}

// relativePosition is where the camera sees the point; when `reflected` that is its mirror image.
Surface terrainSurface(vec3 relativePosition, vec3 normal, bool reflected) {
    vec3 world = relativePosition + frame.cameraPosition.xyz;
    if (reflected) world.y = 2.0 * frame.water.x - world.y;
    float aboveWater = world.y - frame.water.x;
    float broad = detailNoise(OASIS_DETAIL_GROUND_BROAD, relativePosition.xz).x;
    // Fine variation fades out with distance, where a pixel spans many of its cycles.
    float fine = detailNoise(OASIS_DETAIL_GROUND_FINE, relativePosition.xz).x *
                 (1.0 - smoothstep(40.0, 250.0, length(relativePosition)));
    float slope = 1.0 - normal.y;

    vec3 sand = vec3(0.40, 0.29, 0.14);
    vec3 grass = mix(vec3(0.045, 0.10, 0.02), vec3(0.13, 0.14, 0.04), 0.5 + 0.5 * broad);
    vec3 rock = mix(vec3(0.17, 0.145, 0.13), vec3(0.27, 0.24, 0.21), 0.5 + 0.5 * fine);
    float sandAmount = 1.0 - smoothstep(1.5, 4.0, aboveWater + 1.5 * broad);
    float rockAmount = max(smoothstep(0.30, 0.45, slope + 0.06 * broad),
                           smoothstep(48.0, 62.0, aboveWater + 8.0 * broad));

    Surface s;
    s.albedo = mix(mix(grass, sand, sandAmount), rock, rockAmount) * (0.9 + 0.1 * fine);
    s.normal = normal;
    s.relativePosition = relativePosition;
    s.specularPower = round(mix(mix(4.0, 16.0, sandAmount), 24.0, rockAmount));
    s.specularIntensity = quantiseUnit(mix(mix(0.04, 0.10, sandAmount), 0.18, rockAmount));
    s.flags = reflected ? SURFACE_REFLECTED : 0u;
    return s;
}

#endif
