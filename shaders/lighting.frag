// Deferred lighting: reads one pixel's surface from the G-buffer and shades it with the same
// function the forward pipeline calls while drawing; where nothing was drawn (the SKY flag the
// clear leaves) it evaluates the sky. MIRRORED: the same for the reflection, into Reflection.
#include "common/frame_block.glsl"
#include "common/surface.glsl"
#include "common/lighting.glsl"

uniform sampler2D gAlbedo;
uniform sampler2D gNormal;
uniform sampler2D gPosition;
uniform sampler2D gInfo;
in vec2 vScreenUv;
layout(location = 0) out vec4 outColour;

void main() {
#if defined(MIRRORED)
    const bool reflected = true;
#else
    const bool reflected = false;
#endif
    ivec2 pixel = ivec2(gl_FragCoord.xy);
    vec4 info = texelFetch(gInfo, pixel, 0);
    if ((infoFlags(info) & SURFACE_SKY) != 0u) {
        outColour = vec4(skySeenAlong(viewRayDirection(vScreenUv), reflected), 1.0);
        return;
    }
    Surface s;
    s.albedo = texelFetch(gAlbedo, pixel, 0).rgb;
    s.normal = texelFetch(gNormal, pixel, 0).xyz;
    s.relativePosition = texelFetch(gPosition, pixel, 0).xyz;
    decodeInfo(info, s);
    outColour = vec4(shadeSurface(s), 1.0);
}
