// Deferred lighting: reads one pixel's surface from the G-buffer and shades it with the same
// function the forward pipeline calls while drawing; where nothing was drawn (the SKY flag the
// clear leaves) it evaluates the sky. MIRRORED: the same for the reflection, into Reflection.
#include "common/frame_block.glsl"
#include "common/gbuffer.glsl"
#include "common/lighting.glsl"

in vec2 vScreenUv;
layout(location = 0) out vec4 outColour;

void main() {
#if defined(MIRRORED)
    const bool reflected = true;
#else
    const bool reflected = false;
#endif
    ivec2 pixel = ivec2(gl_FragCoord.xy);
    if (gbufferSkyAt(pixel)) {
        outColour = vec4(skySeenAlong(viewRayDirection(vScreenUv), reflected), 1.0);
        return;
    }
    outColour = vec4(shadeSurface(readGBuffer(pixel)), 1.0);
}
