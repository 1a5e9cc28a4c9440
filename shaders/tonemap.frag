// Radiance (linear HDR) to Final (8-bit display colour).
#include "common/frame_block.glsl"
#include "common/output.glsl"

uniform sampler2D radianceTexture;
layout(location = 0) out vec4 outColour;

void main() {
    outColour = vec4(displayEncode(texelFetch(radianceTexture, ivec2(gl_FragCoord.xy), 0).rgb), 1.0);
}
