// The water surface over what lies under it (already in Radiance, absorbed by depth in the
// shading): the reflection weighted by Fresnel for the rippled normal, plus the sun's glint.
// Output is premultiplied for blending ONE, ONE_MINUS_SRC_ALPHA: result = F*reflection + glint + (1-F)*under.
// TONE_MAP_FUSED: the last colour written on water pixels, so it does that blend itself, with the
// value under the water read from Radiance (not attached here), rounded as Radiance would store
// it, and writes the display colour to Final; Radiance keeps the under-water value.
#include "common/frame_block.glsl"
#include "common/lighting.glsl"
#if defined(TONE_MAP_FUSED)
#include "common/output.glsl"
uniform sampler2D radianceTexture;
#endif

uniform sampler2D sourceTexture;  // Reflection
in vec3 vRelativePosition;
layout(location = 0) out vec4 outColour;

void main() {
    vec3 normal = waterNormal(vRelativePosition.xz);
    vec3 toCamera = normalize(-vRelativePosition);
    float fresnel = fresnelSchlick(dot(normal, toCamera));
    vec3 reflected = reflectionsActive()
        ? texelFetch(sourceTexture, ivec2(gl_FragCoord.xy), 0).rgb
        : skyRadiance(reflect(-toCamera, normal));  // without the mirrored scene: the sky alone
    vec3 halfway = normalize(frame.sunDirection.xyz + toCamera);
    float glint = frame.sunDirection.y > 0.0 ? 2.0 * pow(max(dot(normal, halfway), 0.0), 800.0) : 0.0;
    float fog = smoothstep(frame.terrainGridCounts.z, frame.terrainGridCounts.w, length(vRelativePosition));
    vec4 water = vec4((fresnel * reflected + glint * frame.sunRadiance.rgb) * (1.0 - fog), fresnel * (1.0 - fog));
#if defined(TONE_MAP_FUSED)
    vec3 under = texelFetch(radianceTexture, ivec2(gl_FragCoord.xy), 0).rgb;
    outColour = finalColour(water.rgb + (1.0 - water.a) * under);
#else
    outColour = water;
#endif
}
