// The per-frame uniform block as a C++ struct: the one declaration lives in
// shaders/common/frame_data.glsl and is included here with GLSL's types mapped to GLM's.
#pragma once
#include <glm/glm.hpp>

namespace oasis {
namespace glsl_types {
using vec4 = glm::vec4;
using mat4 = glm::mat4;
#include "common/frame_data.glsl"
}  // namespace glsl_types
using FrameData = glsl_types::FrameData;
static_assert(sizeof(FrameData) == (2 + OASIS_SHADOW_MAX_CASCADES) * 64 + (22 + OASIS_DETAIL_LAYERS + OASIS_NOISE_MAX_OCTAVES + OASIS_PLANT_MAX_CELLS) * 16, "FrameData must match std140 layout");
}  // namespace oasis
