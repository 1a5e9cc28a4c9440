// The water plane: one quad at the water level spanning the view distance around the camera.
#include "common/frame_block.glsl"

out vec3 vRelativePosition;

void main() {
    vec2 corner = vec2(float((gl_VertexID << 1) & 2), float(gl_VertexID & 2)) - 1.0;  // strip order
    float extent = frame.terrainGridCounts.w;
    vRelativePosition = vec3(corner.x * extent, frame.water.x - frame.cameraPosition.y, corner.y * extent);
    gl_Position = frame.viewProjection * vec4(vRelativePosition, 1.0);
}
