// The point light as a C++ struct: the one declaration lives in shaders/common/light_data.glsl
// and is included here with GLSL's types mapped to GLM's (as frame_data.h does for FrameData).
#pragma once
#include <glm/glm.hpp>

namespace oasis {
namespace glsl_light_types {
using vec4 = glm::vec4;
#include "common/light_data.glsl"
}  // namespace glsl_light_types
using PointLight = glsl_light_types::PointLight;
static_assert(sizeof(PointLight) == 32, "PointLight must match the std140 and std430 layouts (two vec4s)");
}  // namespace oasis
