// The water plane at the water level, spanning the view distance around the camera: a grid of
// OASIS_WATER_GRID_CELLS^2 cells, two triangles each, vertices generated from gl_VertexID.
#include "common/frame_block.glsl"

out vec3 vRelativePosition;

const ivec2 kCellCorners[6] = ivec2[6](ivec2(0, 0), ivec2(1, 0), ivec2(0, 1), ivec2(0, 1), ivec2(1, 0), ivec2(1, 1));

void main() {
    int cell = gl_VertexID / 6;
    ivec2 gridPoint = ivec2(cell % OASIS_WATER_GRID_CELLS, cell / OASIS_WATER_GRID_CELLS) + kCellCorners[gl_VertexID % 6];
    vec2 even = vec2(gridPoint) * (2.0 / float(OASIS_WATER_GRID_CELLS)) - 1.0;  // evenly spaced in -1..1
    vec2 corner = sign(even) * even * even;  // cells small near the camera, the edges kept at +-1
    float extent = frame.terrainGridCounts.w;
    vRelativePosition = vec3(corner.x * extent, frame.water.x - frame.cameraPosition.y, corner.y * extent);
    gl_Position = frame.viewProjection * vec4(vRelativePosition, 1.0);
}
