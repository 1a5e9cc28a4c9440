// Detail noise around the camera: one simplex octave of a layer (ripples, ground colour, wind
// gusts) at a point given relative to the camera. The layer's origin (the camera's noise
// coordinates, drift included) comes exactly from the CPU, so neither distance from the world's
// origin nor hours of drift cost precision. Returns (noise, d/du, d/dv) per noise unit.
#ifndef OASIS_DETAIL_NOISE_GLSL
#define OASIS_DETAIL_NOISE_GLSL
#include "common/noise.glsl"

float detailNoiseScale(int layer) { return frame.detailNoiseScales[layer / 4][layer % 4]; }

vec3 detailNoise(int layer, vec2 relativeXZ) {
    vec4 origin = frame.detailNoiseOrigins[layer];
    return simplexNoiseSkewed(ivec2(origin.zw), origin.xy + simplexSkew(relativeXZ * detailNoiseScale(layer)));
}

#endif
