// Deferred lighting: reads one pixel's surface from the G-buffer and shades it with the same
// function the forward pipeline calls while drawing. Unlit pixels (the sky) are copied.
#include "common/frame_block.glsl"
#include "common/surface.glsl"
#include "common/output.glsl"
#include "common/lighting.glsl"

uniform sampler2D gAlbedo;
uniform sampler2D gNormal;
uniform sampler2D gPosition;
uniform sampler2D gInfo;
layout(location = 0) out vec4 outColour;

void main() {
    ivec2 pixel = ivec2(gl_FragCoord.xy);
    Surface s;
    s.albedo = texelFetch(gAlbedo, pixel, 0).rgb;
    s.normal = texelFetch(gNormal, pixel, 0).xyz;
    s.relativePosition = texelFetch(gPosition, pixel, 0).xyz;
    decodeInfo(texelFetch(gInfo, pixel, 0), s);
    vec3 colour = (s.flags & SURFACE_UNLIT) != 0u ? s.albedo : displayEncode(shadeSurface(s));
    outColour = vec4(colour, 1.0);
}
