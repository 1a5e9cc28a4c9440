// A shaded point as both pipelines see it: what the G-buffer stores and what lighting reads.
// Specular power and intensity are quantised here, by the material, so an 8-bit info target
// stores them exactly and forward and deferred shade with the same numbers.
#ifndef OASIS_SURFACE_GLSL
#define OASIS_SURFACE_GLSL

#include "common/shared_constants.glsl"
const uint SURFACE_SKY = OASIS_SURFACE_SKY;              // nothing drawn: lighting evaluates the sky instead
const uint SURFACE_REFLECTED = OASIS_SURFACE_REFLECTED;  // seen in the water: the mirrored scene
const uint SURFACE_PLANT = OASIS_SURFACE_PLANT;          // a plant billboard

struct Surface {
    vec3 albedo;            // linear reflectance
    vec3 normal;            // unit, world space, as the unmirrored surface faces
    vec3 relativePosition;  // where the camera sees it (the mirror image when REFLECTED) minus the camera
    float specularPower;    // integer 1..255
    float specularIntensity;// multiple of 1/255
    uint flags;
};

float quantiseUnit(float x) { return round(clamp(x, 0.0, 1.0) * 255.0) / 255.0; }

vec4 encodeInfo(Surface s) {
    return vec4(s.specularPower / 255.0, s.specularIntensity, float(s.flags) / 255.0, 1.0);
}

// The G-buffer values of a pixel where nothing was drawn: the clear values and ReflectionClearPass.
const vec4 CLEARED_INFO = vec4(0.0, 0.0, float(SURFACE_SKY) / 255.0, 0.0);

uint infoFlags(vec4 info) { return uint(round(info.b * 255.0)); }

void decodeInfo(vec4 info, inout Surface s) {
    s.specularPower = round(info.r * 255.0);
    s.specularIntensity = info.g;
    s.flags = infoFlags(info);
}

#endif
