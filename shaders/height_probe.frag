// Test probe: writes terrainHeightFromCamera() at points given relative to the camera in a float
// texture, one per pixel, so tests can compare the GPU's heights with the CPU's (src/scene/terrain.cpp).
#include "common/frame_block.glsl"
#include "common/terrain.glsl"

uniform sampler2D sourceTexture;  // rg = x, z relative to the camera
layout(location = 0) out vec4 outHeight;

void main() {
    vec2 relativeXZ = texelFetch(sourceTexture, ivec2(gl_FragCoord.xy), 0).rg;
    outHeight = vec4(terrainHeightFromCamera(relativeXZ), 1.0);
}
