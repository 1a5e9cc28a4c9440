// CPU twin of shaders/common/noise.glsl: 2D simplex noise with analytic gradient and its fractal
// sum around an exactly known origin. The float arithmetic is kept step for step the same as the
// GLSL so CPU and GPU heights agree; the origins are computed here in double.
#pragma once
#include <array>
#include <cstdint>

#include <glm/glm.hpp>

#include "common/shared_constants.glsl"

namespace oasis {

// Hash of an integer lattice cell; identical to hashCell() in GLSL.
uint32_t hashCell(glm::ivec2 cell);

// The fractal sum has at most this many octaves (FrameData holds an origin for each).
constexpr int kMaxNoiseOctaves = OASIS_NOISE_MAX_OCTAVES;

// (noise, d/dx, d/dy) with noise in [-1, 1], at the point whose skewed lattice coordinates are
// baseCell + skewedOffset: the integer part exact however far out, only the offset a float.
glm::vec3 simplexNoiseSkewed(glm::ivec2 baseCell, glm::vec2 skewedOffset);
glm::vec2 simplexSkew(glm::vec2 p);
// The same at an absolute point, for small coordinates.
glm::vec3 simplexNoise(glm::vec2 p);

// A noise coordinate known in double, split in the skewed lattice for the GPU:
// (fraction.x, fraction.y, cell.x, cell.y), the cell exact in float up to 2^24.
glm::vec4 skewedOrigin(glm::dvec2 p);

// The octave origins of the fractal sum around noise coordinate p (each octave's rotated,
// doubled and shifted image of p, split by skewedOrigin); unused entries are zero.
using NoiseOrigins = std::array<glm::vec4, kMaxNoiseOctaves>;
NoiseOrigins fractalNoiseOrigins(glm::dvec2 p, int octaves);

// Fractal sum of `octaves` (clamped to kMaxNoiseOctaves) rotated, frequency-doubled layers at
// noise coordinate origin + local, from the origins above: (sum, d/dlocal.x, d/dlocal.y).
// The GPU's fractalNoiseFrom step for step.
glm::vec3 fractalNoiseFrom(const NoiseOrigins& origins, glm::vec2 local, int octaves);

// The reference: the fractal sum at p with every octave's point taken in double.
glm::vec3 fractalNoise(glm::dvec2 p, int octaves);

}  // namespace oasis
