// CPU twin of shaders/common/sky.glsl for the GPU tests: the sky's radiance along a direction
// (gradient, sun glow and disk, stars, and the cloud deck from the frame's detail-noise origins),
// so a test can check what the GPU drew where the sky shows, directly or in the water.
#pragma once
#include <glm/glm.hpp>

#include "render/frame_data.h"

namespace oasis::gputest {

// cloudCover(): (cover, thickness) of the cloud deck along the camera-relative unit direction d.
// Evaluated in float step for step (the GPU's noise is float; src/scene/noise.cpp is its twin).
glm::dvec2 cloudCoverCpu(const FrameData& frame, glm::dvec3 d);

// stars(): the star term alone (0 by day, and where no star cell lies).
double starCpu(const FrameData& frame, glm::dvec3 d);

// skyRadiance(): linear radiance of the sky along d, clouds included.
glm::dvec3 skyRadianceCpu(const FrameData& frame, glm::dvec3 d);

// Directions whose sky the CPU cannot reproduce to float precision: the sun disk's edge (a
// smoothstep over 4e-5 of cos) and, at night, stars and their neighbours (a float floor on a
// 1/300 lattice decides the cell).
bool skyIsSensitive(const FrameData& frame, glm::dvec3 d);

}  // namespace oasis::gputest
