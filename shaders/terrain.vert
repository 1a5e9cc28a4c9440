// Terrain vertices: a polar grid cell (ring, segment) placed around the camera, raised to the
// noise height. Normals come from the height's analytic gradient, exact however coarse the grid.
// MIRRORED: the mirror image across the water plane, clipped to what lies above the water.
// OUTPUT_SHADOW: the same vertices seen from the sun, into one shadow cascade.
#include "common/frame_block.glsl"
#include "common/terrain.glsl"
#include "common/water_clip_vertex.glsl"

layout(location = 0) in vec2 gridCoordinate;  // (ring fraction, segment fraction)
out vec3 vRelativePosition;
out vec3 vNormal;
#if defined(OUTPUT_SHADOW)
#include "common/shadow_caster.glsl"
#endif

void main() {
    // Ring 0 is the point under the camera (a fan of zero-area triangles closes the centre);
    // ring i >= 1 sits at firstRadius * ratio^(i-1), out to the view distance.
    float ring = floor(gridCoordinate.x * frame.terrainGridCounts.x + 0.5);
    float radius = ring == 0.0 ? 0.0 : frame.terrainGrid.z * pow(frame.terrainGrid.w, ring - 1.0);
    float azimuth = frame.terrainGrid.x + (2.0 * gridCoordinate.y - 1.0) * frame.terrainGrid.y;
    vec2 offset = radius * vec2(sin(azimuth), -cos(azimuth));
    vec3 height = terrainHeightFromCamera(offset);
    vec3 relative = vec3(offset.x, height.x - frame.cameraPosition.y, offset.y);
    vNormal = normalize(vec3(-height.y, 1.0, -height.z));
#if defined(MIRRORED)
    clipAtWater(height.x - frame.water.x);  // keep only what is above the water
    relative.y = 2.0 * (frame.water.x - frame.cameraPosition.y) - relative.y;
#endif
    vRelativePosition = relative;
#if defined(OUTPUT_SHADOW)
    gl_Position = shadowCasterPosition(relative);
#else
    gl_Position = frame.viewProjection * vec4(relative, 1.0);
#endif
}
