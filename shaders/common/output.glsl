// Linear radiance to the 8-bit display colour: exposure, an exponential tone curve, gamma 2.2.
#ifndef OASIS_OUTPUT_GLSL
#define OASIS_OUTPUT_GLSL
vec3 displayEncode(vec3 radiance) {
    vec3 mapped = vec3(1.0) - exp(-max(radiance, vec3(0.0)) * frame.depthRange.w);
    return pow(mapped, vec3(1.0 / 2.2));
}
#endif
