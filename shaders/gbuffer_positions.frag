// Surface positions as the G-buffer gives them back to lighting (stored, or reconstructed from
// depth), into a float target that tests and the bench read: camera-relative xyz, w 1; sky 0.
#include "common/gbuffer.glsl"

layout(location = 0) out vec4 outPosition;

void main() {
    ivec2 pixel = ivec2(gl_FragCoord.xy);
    outPosition = gbufferSkyAt(pixel) ? vec4(0.0) : vec4(gbufferPositionAt(pixel), 1.0);
}
