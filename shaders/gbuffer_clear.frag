// Writes the G-buffer's clear values (nothing drawn: the sky) where the stencil allows, so the
// mirrored scene starts from an empty G-buffer inside the water and from the far plane in depth.
#include "common/surface.glsl"

layout(location = 0) out vec4 outAlbedo;
layout(location = 1) out vec4 outNormal;
layout(location = 2) out vec4 outPosition;
layout(location = 3) out vec4 outInfo;

void main() {
    outAlbedo = vec4(0.0);
    outNormal = vec4(0.0);
    outPosition = vec4(0.0);
    outInfo = CLEARED_INFO;
}
