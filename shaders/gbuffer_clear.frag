// Writes the G-buffer's clear values (nothing drawn: the sky) where the stencil allows, so the
// mirrored scene starts from an empty G-buffer inside the water and from the far plane in depth.
#define OUTPUT_GBUFFER
#include "common/gbuffer.glsl"

void main() {
    outAlbedo = vec4(0.0);
    outNormal = vec4(0.0);
#if !defined(GBUFFER_COMPACT)
    outPosition = vec4(0.0);
#endif
    outInfo = clearedInfo();
}
