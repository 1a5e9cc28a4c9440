// The terrain's height (same maths as src/scene/terrain.cpp) and its material: sand by the
// water, grass on gentle ground, rock on steep or high ground (strata and cracks of its own, lit
// through its normal), broken up by noise; detail fades with each pixel's footprint.
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

// World units of surface one pixel spans at this point: the distance over the pixels per world unit
// at unit distance, stretched where the surface is seen at a grazing angle (the screen-space
// footprint, from the frame's projection rather than derivatives, so both pipelines agree exactly).
float terrainPixelFootprint(vec3 relativePosition, vec3 normal) {
    float distance = max(length(relativePosition), 1e-3);
    float facing = max(abs(dot(normal, relativePosition)) / distance, 0.25);
    return distance / (max(frame.vegetationAtlas.w, 1.0) * facing);
}

// How much of a detail whose cycle is `period` world units survives that footprint: all of it
// while a cycle spans 6 pixels or more, none once it spans 3 (before it can alias or shimmer).
float detailVisibility(float period, float footprint) {
    return 1.0 - smoothstep(1.0 / 6.0, 1.0 / 3.0, footprint / period);
}

// Rock's own structure in world space: horizontal strata (bands of height, warped by the ground's
// noise, each with its own shade and a ledge at its top) cut by vertical cracks (the zero lines of
// a noise over x, z, so on a cliff they run down its face). Returns (shade, bump gradient x y z):
// the shade multiplies the rock's albedo, the gradient (of a bump height) tilts its normal.
vec4 rockStructure(vec3 world, vec3 relativePosition, float broad, float fine, float steepness, float footprint) {
    const float strataPeriod = 1.7, thickStrataPeriod = 7.0;
    // Strata: height warped by the broad noise, so the bands undulate along the cliff.
    float warped = world.y + 4.0 * broad + 0.6 * fine;
    // Thin strata and their ledges show on steep faces; flat rock keeps the thick bands' shades.
    float thinVisible = detailVisibility(strataPeriod, footprint) * steepness;
    float thickVisible = detailVisibility(thickStrataPeriod, footprint);
    float band = floor(warped / strataPeriod), thickBand = floor(warped / thickStrataPeriod);
    float bandShade = float(hashCell(ivec2(int(band), 17)) & 255u) / 255.0;
    float thickShade = float(hashCell(ivec2(int(thickBand), 29)) & 255u) / 255.0;
    // Within a band: a ledge, the top 15 % of the band stepping out (its slope in height).
    float within = fract(warped / strataPeriod);
    float ledgeT = clamp((within - 0.80) / 0.15, 0.0, 1.0);
    float ledge = ledgeT * ledgeT * (3.0 - 2.0 * ledgeT);
    float ledgeSlope = 6.0 * ledgeT * (1.0 - ledgeT) / (0.15 * strataPeriod);  // d ledge / d y
    // Cracks: where the crack noise crosses zero, a groove about 0.08 units wide.
    vec3 crackNoise = detailNoise(OASIS_DETAIL_ROCK_CRACKS, relativePosition.xz);
    float crackScale = detailNoiseScale(OASIS_DETAIL_ROCK_CRACKS);
    vec2 crackGradient = crackNoise.yz * crackScale;  // per world unit
    float crackWidth = 0.08 * length(crackGradient) + 1e-4;
    float crackVisible = detailVisibility(0.6, footprint);
    float crackT = clamp(abs(crackNoise.x) / crackWidth, 0.0, 1.0);
    // Only on steep faces, and only along some of the zero lines (gated by the fine noise).
    float crackAmount = crackVisible * steepness * smoothstep(-0.2, 0.2, fine);
    float crack = (1.0 - crackT * crackT * (3.0 - 2.0 * crackT)) * crackAmount;
    // The groove's depth is 0.04 units: its height -0.04 crack, differentiated through the noise.
    vec2 crackBump = 0.04 * sign(crackNoise.x) * 6.0 * crackT * (1.0 - crackT) / crackWidth * crackGradient;

    float shade = mix(1.0, 0.78 + 0.44 * thickShade, thickVisible) *
                  mix(1.0, 0.86 + 0.28 * bandShade, thinVisible) *
                  mix(1.0, 1.06, ledge * thinVisible) * (1.0 - 0.45 * crack);
    // The ledge stands 0.12 units out over its rise; the bump gradient's height part.
    vec3 bump = vec3(0.0, 0.12 * ledgeSlope * thinVisible, 0.0) + vec3(crackBump.x, 0.0, crackBump.y) * crackAmount;
    return vec4(shade, bump);
}

// The normal tilted by a bump height's world gradient (its part along the surface).
vec3 bumpedNormal(vec3 normal, vec3 bumpGradient) {
    return normalize(normal - (bumpGradient - dot(bumpGradient, normal) * normal));
}

// relativePosition is where the camera sees the point; when `reflected` that is its mirror image.
Surface terrainSurface(vec3 relativePosition, vec3 normal, bool reflected) {
    vec3 world = relativePosition + frame.cameraPosition.xyz;
    if (reflected) world.y = 2.0 * frame.water.x - world.y;
    float aboveWater = world.y - frame.water.x;
    float footprint = terrainPixelFootprint(relativePosition, normal);
    float broad = detailNoise(OASIS_DETAIL_GROUND_BROAD, relativePosition.xz).x;
    // Fine variation fades out with the footprint, before a pixel spans several of its cycles.
    float fine = detailNoise(OASIS_DETAIL_GROUND_FINE, relativePosition.xz).x *
                 detailVisibility(1.0 / detailNoiseScale(OASIS_DETAIL_GROUND_FINE), footprint);
    float slope = 1.0 - normal.y;

    vec3 sand = vec3(0.40, 0.29, 0.14);
    vec3 grass = mix(vec3(0.045, 0.10, 0.02), vec3(0.13, 0.14, 0.04), 0.5 + 0.5 * broad);
    float sandAmount = 1.0 - smoothstep(1.5, 4.0, aboveWater + 1.5 * broad);
    // Rock where the ground is steep: a narrow band around slope 0.33 (1 - normal.y), its edge
    // broken by noise, so the rock's outline follows the slope's contour instead of smearing.
    // The lowest it reaches, 0.33 - 0.05 - 0.025 - 0.012 = 0.243, keeps clear of the plants'
    // ground rule (scene/placement.h, minNormalY 0.76).
    float steepRock = smoothstep(-0.012, 0.012, slope - 0.33 + 0.05 * broad + 0.025 * fine);
    float rockAmount = max(steepRock, smoothstep(48.0, 62.0, aboveWater + 8.0 * broad));
    // Only where rock shows (most of the frame is grass or sand): the same result, less work.
    vec4 structure = vec4(1.0, 0.0, 0.0, 0.0);
    if (rockAmount > 0.0)
        structure = rockStructure(world, relativePosition, broad, fine, smoothstep(0.25, 0.55, slope), footprint);
    // About as bright as the grass, grey: it reads by its hue and structure, not as a white smear.
    vec3 rock = mix(vec3(0.085, 0.078, 0.07), vec3(0.145, 0.132, 0.118), 0.5 + 0.5 * fine) * structure.x;

    Surface s;
    s.albedo = mix(mix(grass, sand, sandAmount), rock, rockAmount) * (0.9 + 0.1 * fine);
    s.normal = rockAmount > 0.0 ? bumpedNormal(normal, structure.yzw * rockAmount) : normal;
    s.relativePosition = relativePosition;
    s.specularPower = round(mix(mix(4.0, 16.0, sandAmount), 12.0, rockAmount));
    s.specularIntensity = quantiseUnit(mix(mix(0.04, 0.10, sandAmount), 0.07, rockAmount));
    s.flags = reflected ? SURFACE_REFLECTED : 0u;
    return s;
}

#endif
