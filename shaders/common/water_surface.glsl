// The water's surface over what lies under it, for one point of the plane: the reflection weighted
// by Fresnel for the rippled normal plus the sun's glint, faded by fog. Premultiplied: the result
// is rgb + (1 - a) x under. The composite (water_composite.frag) draws it; the probe's shading
// record (probe_shading.frag) evaluates the same function at one pixel.
#ifndef OASIS_WATER_SURFACE_GLSL
#define OASIS_WATER_SURFACE_GLSL
#include "common/lighting.glsl"

// `reflectedScene`: the Reflection target's value at the pixel (used only with reflections active).
vec4 waterSurface(vec3 relativePosition, vec3 reflectedScene) {
    vec3 normal = waterNormal(relativePosition.xz);
    vec3 toCamera = normalize(-relativePosition);
    float fresnel = fresnelSchlick(dot(normal, toCamera));
    vec3 reflected = reflectionsActive() ? reflectedScene
                                         : skyRadiance(reflect(-toCamera, normal));  // without the mirrored scene: the sky alone
    vec3 halfway = normalize(frame.sunDirection.xyz + toCamera);
    float glint = frame.sunDirection.y > 0.0 ? 2.0 * pow(max(dot(normal, halfway), 0.0), 800.0) : 0.0;
    float fog = smoothstep(frame.terrainGridCounts.z, frame.terrainGridCounts.w, length(relativePosition));
    RECORD_TERM(OASIS_TERM_WATER_NORMAL, vec4(normal, dot(normal, toCamera)));
    RECORD_TERM(OASIS_TERM_FRESNEL, vec4(fresnel, glint, fog, frame.waterTint.w));
    RECORD_TERM(OASIS_TERM_REFLECTED, vec4(reflected, 0.0));
    return vec4((fresnel * reflected + glint * frame.sunRadiance.rgb) * (1.0 - fog), fresnel * (1.0 - fog));
}

#endif
