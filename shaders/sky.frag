// Forward sky: the procedural sky along the view ray (its mirror image when MIRRORED), written
// where nothing else was drawn. The deferred pipeline evaluates the same function in lighting.frag.
#include "common/frame_block.glsl"
#include "common/lighting.glsl"

in vec2 vScreenUv;
layout(location = 0) out vec4 outColour;

void main() {
#if defined(MIRRORED)
    const bool reflected = true;
#else
    const bool reflected = false;
#endif
    outColour = vec4(skySeenAlong(viewRayThroughPixel(), reflected), 1.0);
}
