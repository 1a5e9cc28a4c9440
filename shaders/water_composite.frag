// The water surface over what lies under it (already in Radiance, absorbed by depth in the
// shading): common/water_surface.glsl's reflection weighted by Fresnel plus the sun's glint.
// Output is premultiplied for blending ONE, ONE_MINUS_SRC_ALPHA: result = F*reflection + glint + (1-F)*under.
// TONE_MAP_FUSED: the last colour written on water pixels, so it does that blend itself, with the
// value under the water read from Radiance (not attached here), rounded as Radiance would store
// it, and writes the display colour to Final; Radiance keeps the under-water value.
#include "common/frame_block.glsl"
#include "common/water_surface.glsl"
#include "common/water_fragment.glsl"
#if defined(TONE_MAP_FUSED)
#include "common/output.glsl"
uniform sampler2D radianceTexture;
#endif

uniform sampler2D reflectionTexture;
layout(location = 0) out vec4 outColour;

void main() {
    vec3 relativePosition = waterFragmentPosition();  // WATER_FULLSCREEN: found per fragment (common/water_fragment.glsl)
    vec3 reflectedScene = reflectionsActive() ? texelFetch(reflectionTexture, ivec2(gl_FragCoord.xy), 0).rgb : vec3(0.0);
    vec4 water = waterSurface(relativePosition, reflectedScene);
#if defined(TONE_MAP_FUSED)
    vec3 under = texelFetch(radianceTexture, ivec2(gl_FragCoord.xy), 0).rgb;
    outColour = finalColour(water.rgb + (1.0 - water.a) * under);
#else
    outColour = water;
#endif
}
