// A shaded point as both pipelines see it: what the G-buffer stores and what lighting reads.
// Specular power and intensity are quantised here, by the material, so an 8-bit info target
// stores them exactly and forward and deferred shade with the same numbers.
#ifndef OASIS_SURFACE_GLSL
#define OASIS_SURFACE_GLSL

const uint SURFACE_SKY = 1u;    // a sky pixel
const uint SURFACE_UNLIT = 2u;  // albedo already holds the display colour; lighting copies it

struct Surface {
    vec3 albedo;            // linear reflectance, or the display colour when UNLIT
    vec3 normal;            // unit, world space
    vec3 relativePosition;  // world position minus the camera position
    float specularPower;    // integer 1..255
    float specularIntensity;// multiple of 1/255
    uint flags;
};

float quantiseUnit(float x) { return round(clamp(x, 0.0, 1.0) * 255.0) / 255.0; }

vec4 encodeInfo(Surface s) {
    return vec4(s.specularPower / 255.0, s.specularIntensity, float(s.flags) / 255.0, 1.0);
}

uint infoFlags(vec4 info) { return uint(round(info.b * 255.0)); }

void decodeInfo(vec4 info, inout Surface s) {
    s.specularPower = round(info.r * 255.0);
    s.specularIntensity = info.g;
    s.flags = infoFlags(info);
}

#endif
