// Per-frame data shared by C++ (src/render/frame_data.h includes this file) and every shader.
// Only vec4 and mat4 members, so std140 (UBO) and the C++ struct have the same bytes.

#ifndef OASIS_FRAME_DATA_GLSL
#define OASIS_FRAME_DATA_GLSL
#include "common/shared_constants.glsl"

struct FrameData {
    mat4 viewProjection;         // world (camera-relative) -> clip
    mat4 inverseViewProjection;  // clip -> world (camera-relative)
    vec4 cameraPosition;         // xyz world position; w unused
    vec4 sunDirection;           // xyz towards the sun (unit); w = sun elevation (sin)
    vec4 sunRadiance;            // rgb sun colour times intensity; w unused
    vec4 skyZenith;              // rgb zenith colour; w unused
    vec4 skyHorizon;             // rgb horizon colour; w unused
    vec4 groundAmbient;          // rgb light bounced from the ground; w unused
    vec4 terrainShape;           // x frequency, y amplitude, z base height, w octaves
    vec4 terrainGrid;            // x central azimuth, y half-width (rad), z first ring radius, w ring ratio
    vec4 terrainGridCounts;      // x rings, y segments, z fog start, w fog end
    vec4 depthRange;             // x near, y far, z time (s), w exposure
    vec4 depthConvention;        // x 1 when depth is reversed (near 1, far 0), y NDC z of the near plane,
                                 // z window depth of the far plane; w NDC z of the far plane (the
                                 // sky's full-screen draw). See common/depth.glsl.
    vec4 water;                  // x level (world y), y absorption per unit, z ripple strength, w flags
    vec4 waterTint;              // rgb colour deep water tends to; w Fresnel reflectance at normal incidence
    vec4 vegetation;             // x wind strength, y flutter phase (rad), zw unused
    vec4 vegetationAtlas;        // x atlas columns, y atlas rows, z texels per cell side, w pixels per world unit at unit eye distance
    vec4 screen;                 // x width, y height (pixels), z 1 / width, w 1 / height
    // The target drawn into against the frame: xy its pixels per frame pixel (1, or 1/2 and 1/4
    // while the reflection is drawn at a reduced resolution), z pixels the reflection's rectangle
    // of visible water is widened by (0, or 1 for the bilinear upsample's taps), w unused.
    vec4 targetScale;
    // Each atlas cell's drawn bounds (u0, v0, u1, v1) in the cell, v up (PlantAtlas::drawnBounds),
    // or the whole cell (0, 0, 1, 1): the plant billboards are trimmed to them.
    vec4 plantDrawnBounds[OASIS_PLANT_MAX_CELLS];
    // The camera's terrain-noise coordinates per octave, split in the skewed simplex lattice:
    // xy the fraction, zw the integer cell (exact in float to 2^24). See noise.glsl.
    vec4 terrainNoiseOrigins[OASIS_NOISE_MAX_OCTAVES];
    vec4 detailNoiseOrigins[OASIS_DETAIL_LAYERS];  // the same for each detail layer (shared_constants.glsl)
    vec4 detailNoiseScales[2];   // noise units per world unit of layer i: [i / 4][i % 4]
    // Sun shadows (common/shadows.glsl, src/render/shadow_cascades.h): per cascade, camera-relative
    // world -> the cascade's clip space (xy -1..1 across its map, z -1..1 across its depth range).
    mat4 shadowMatrices[OASIS_SHADOW_MAX_CASCADES];
    vec4 shadow;                 // x 1 when the maps were drawn this frame, y cascade count, z fade start, w fade end (eye distance)
    vec4 shadowTexel;            // per cascade: world units per map texel
    vec4 shadowDepthRange;       // per cascade: world units across its depth range (clip z -1..1)
};

#endif
