// 2D simplex noise with its analytic gradient, and the fractal sum the terrain is built from.
// src/scene/noise.cpp is the same arithmetic in C++; tests hold the two within 1e-4 in height.
// Gradients come from an integer hash (exact on CPU and GPU), not from a float permutation.

#ifndef OASIS_NOISE_GLSL
#define OASIS_NOISE_GLSL

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

// Returns (noise, d noise / dx, d noise / dy); noise in [-1, 1].
vec3 simplexNoise(vec2 p) {
    vec2 skewed = floor(p + (p.x + p.y) * SIMPLEX_SKEW);
    ivec2 cell = ivec2(skewed);
    vec2 x0 = p - skewed + (skewed.x + skewed.y) * SIMPLEX_UNSKEW;
    ivec2 step = x0.x > x0.y ? ivec2(1, 0) : ivec2(0, 1);
    vec2 x1 = x0 - vec2(step) + SIMPLEX_UNSKEW;
    vec2 x2 = x0 - 1.0 + 2.0 * SIMPLEX_UNSKEW;
    vec3 sum = simplexCorner(x0, cell) + simplexCorner(x1, cell + step)
             + simplexCorner(x2, cell + ivec2(1, 1));
    return SIMPLEX_SCALE * sum;
}

// Fractal sum of `octaves` simplex layers, each rotated by (0.8, 0.6) and doubled in frequency
// so lattice directions do not line up. Returns (sum, d sum / dx, d sum / dy).
// Each octave's small offset is added at evaluation, not carried into the next octave: carried,
// it doubles with every octave and the finest layer would be evaluated near 2000, where a float
// step is 1e-4 and CPU and GPU rounding visibly disagree.
vec3 fractalNoise(vec2 p, int octaves) {
    vec3 result = vec3(0.0);
    float amplitude = 1.0;
    // Jacobian of the octave's coordinates with respect to p, as columns (jx, jy).
    vec2 jx = vec2(1.0, 0.0);
    vec2 jy = vec2(0.0, 1.0);
    vec2 q = p;
    for (int octave = 0; octave < octaves; ++octave) {
        vec3 n = simplexNoise(q + vec2(17.0, -31.0) * float(octave));
        result.x += amplitude * n.x;
        result.y += amplitude * dot(n.yz, jx);
        result.z += amplitude * dot(n.yz, jy);
        q = vec2(1.6 * q.x - 1.2 * q.y, 1.2 * q.x + 1.6 * q.y);
        jx = vec2(1.6 * jx.x - 1.2 * jx.y, 1.2 * jx.x + 1.6 * jx.y);
        jy = vec2(1.6 * jy.x - 1.2 * jy.y, 1.2 * jy.x + 1.6 * jy.y);
        amplitude *= 0.5;
    }
    return result;
}

#endif
