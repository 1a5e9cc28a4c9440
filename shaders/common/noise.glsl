// 2D simplex noise with its analytic gradient, and the fractal sum the terrain is built from,
// evaluated around an exactly known origin (the camera) so that far from the world's origin the
// heights keep their precision. src/scene/noise.cpp is the same arithmetic in C++; tests hold the
// two within 1e-4 in height, also 1e5 units out.
// Gradients come from an integer hash (exact on CPU and GPU), not from a float permutation.

#ifndef OASIS_NOISE_GLSL
#define OASIS_NOISE_GLSL
#include "common/shared_constants.glsl"

const float SIMPLEX_SKEW = 0.36602540378;    // (sqrt(3) - 1) / 2
const float SIMPLEX_UNSKEW = 0.21132486540;  // (3 - sqrt(3)) / 6
const float SIMPLEX_SCALE = 99.204334582;    // maps the sum to [-1, 1]

uint hashCell(ivec2 cell) {
    uint h = uint(cell.x) * 0x8da6b343u + uint(cell.y) * 0xd8163841u;
    h ^= h >> 16u; h *= 0x7feb352du;
    h ^= h >> 15u; h *= 0x846ca68bu;
    h ^= h >> 16u;
    return h;
}

vec2 cellGradient(ivec2 cell) {
    // Eight unit directions; the index is the hash's low bits.
    uint k = hashCell(cell) & 7u;
    float d = 0.70710678;
    if (k == 0u) return vec2(1.0, 0.0);
    if (k == 1u) return vec2(-1.0, 0.0);
    if (k == 2u) return vec2(0.0, 1.0);
    if (k == 3u) return vec2(0.0, -1.0);
    if (k == 4u) return vec2(d, d);
    if (k == 5u) return vec2(-d, d);
    if (k == 6u) return vec2(d, -d);
    return vec2(-d, -d);
}

// One simplex corner: value and gradient of t^4 * dot(g, x), t = 0.5 - |x|^2.
vec3 simplexCorner(vec2 x, ivec2 cell) {
    float t = 0.5 - dot(x, x);
    if (t <= 0.0) return vec3(0.0);
    vec2 g = cellGradient(cell);
    float gx = dot(g, x);
    float t2 = t * t;
    float t4 = t2 * t2;
    return vec3(t4 * gx, t4 * g - 8.0 * t2 * t * gx * x);
}

// Simplex noise at the point whose skewed coordinates are baseCell + skewedOffset: the integer
// part stays an integer (exact however far from the origin), only the small offset is a float.
// Returns (noise, d noise / dx, d noise / dy) in unskewed coordinates; noise in [-1, 1].
vec3 simplexNoiseSkewed(ivec2 baseCell, vec2 skewedOffset) {
    vec2 whole = floor(skewedOffset);
    ivec2 cell = baseCell + ivec2(whole);
    vec2 f = skewedOffset - whole;
    vec2 x0 = f - (f.x + f.y) * SIMPLEX_UNSKEW;  // unskewed, from the cell's first corner
    ivec2 step = x0.x > x0.y ? ivec2(1, 0) : ivec2(0, 1);
    vec2 x1 = x0 - vec2(step) + SIMPLEX_UNSKEW;
    vec2 x2 = x0 - 1.0 + 2.0 * SIMPLEX_UNSKEW;
    vec3 sum = simplexCorner(x0, cell) + simplexCorner(x1, cell + step)
             + simplexCorner(x2, cell + ivec2(1, 1));
    return SIMPLEX_SCALE * sum;
}

vec2 simplexSkew(vec2 p) { return p + (p.x + p.y) * SIMPLEX_SKEW; }

// Noise at an absolute point, for small coordinates (materials, ripples).
vec3 simplexNoise(vec2 p) { return simplexNoiseSkewed(ivec2(0), simplexSkew(p)); }

// The fractal sum's octaves: each rotated by (0.8, 0.6), doubled in frequency and shifted by
// (17, -31) per octave, so lattice directions do not line up.
vec2 nextOctave(vec2 q) { return vec2(1.6 * q.x - 1.2 * q.y, 1.2 * q.x + 1.6 * q.y); }

// Fractal sum of `octaves` simplex layers at noise coordinates `origin + local`, where each
// octave's image of `origin` is given exactly, split in the skewed lattice into an integer cell
// (zw) and a fraction (xy): octaveOrigins[o] (src/scene/noise.h computes them in double). Only
// `local` (small: the offset from the camera) is carried in float, so the precision does not
// depend on how far the origin is from zero. Returns (sum, d sum / dx, d sum / dy) per unit of
// `local`.
vec3 fractalNoiseFrom(vec4 octaveOrigins[OASIS_NOISE_MAX_OCTAVES], vec2 local, int octaves) {
    vec3 result = vec3(0.0);
    float amplitude = 1.0;
    // Jacobian of the octave's coordinates with respect to `local`, as columns (jx, jy).
    vec2 jx = vec2(1.0, 0.0);
    vec2 jy = vec2(0.0, 1.0);
    vec2 q = local;
    for (int octave = 0; octave < octaves; ++octave) {
        vec4 origin = octaveOrigins[octave];
        vec3 n = simplexNoiseSkewed(ivec2(origin.zw), origin.xy + simplexSkew(q));
        result.x += amplitude * n.x;
        result.y += amplitude * dot(n.yz, jx);
        result.z += amplitude * dot(n.yz, jy);
        q = nextOctave(q);
        jx = nextOctave(jx);
        jy = nextOctave(jy);
        amplitude *= 0.5;
    }
    return result;
}

#endif
