// Test probe: writes terrainHeight() at world points given in a float texture, one per pixel,
// so tests can compare the GPU's heights with the CPU's (src/scene/terrain.cpp).
#include "common/frame_block.glsl"
#include "common/terrain.glsl"

uniform sampler2D sourceTexture;  // rg = world x, z
layout(location = 0) out vec4 outHeight;

void main() {
    vec2 worldXZ = texelFetch(sourceTexture, ivec2(gl_FragCoord.xy), 0).rg;
    outHeight = vec4(terrainHeight(worldXZ), 1.0);
}
