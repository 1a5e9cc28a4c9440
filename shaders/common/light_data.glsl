// One point light, shared by C++ (src/render/light_data.h includes this file) and every light path
// of shaders/common/lights.glsl. Only vec4 members, so std140 (UBO), std430 (SSBO) and the C++
// struct have the same 32 bytes and one upload serves every path.

#ifndef OASIS_LIGHT_DATA_GLSL
#define OASIS_LIGHT_DATA_GLSL

struct PointLight {
    vec4 positionRadius;   // xyz camera-relative position (computed in double on the CPU), w radius
    vec4 colourIntensity;  // rgb linear colour, w intensity (radiance scale at 1 unit, before falloff)
};

#endif
