// CPU twin of shaders/common/noise.glsl: 2D simplex noise with analytic gradient and its fractal sum.
// The arithmetic is kept step for step the same as the GLSL so CPU and GPU heights agree.
#pragma once
#include <cstdint>
#include <glm/glm.hpp>

namespace oasis {

// Hash of an integer lattice cell; identical to hashCell() in GLSL.
uint32_t hashCell(glm::ivec2 cell);

// (noise, d/dx, d/dy) with noise in [-1, 1].
glm::vec3 simplexNoise(glm::vec2 p);

// Fractal sum of `octaves` rotated, frequency-doubled layers: (sum, d/dx, d/dy).
glm::vec3 fractalNoise(glm::vec2 p, int octaves);

}  // namespace oasis
