// The light list as the frame's light path reads it, for the check's pass-by-pass search
// (src/check/check_buffers.h): column i holds lightAt(i), its position and radius in row 0 and
// its colour and intensity in row 1; pixel (0, 2) holds lightCount(). Compared between paths, an
// SSBO list and a UBO list that the shaders read alike agree, and one read wrong is named.
#include "common/lights.glsl"

layout(location = 0) out vec4 outDecoded;

void main() {
    ivec2 pixel = ivec2(gl_FragCoord.xy);
    if (pixel.y == 2) {
        outDecoded = vec4(float(lightCount()));
        return;
    }
    if (pixel.x >= lightCount()) {  // past the list the shaders see: no light to read
        outDecoded = vec4(0.0);
        return;
    }
    PointLight light = lightAt(pixel.x);
    outDecoded = pixel.y == 0 ? light.positionRadius : light.colourIntensity;
}
