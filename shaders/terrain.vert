// Terrain vertices: a polar grid cell (ring, segment) placed around the camera, raised to the
// noise height. Normals come from the height's analytic gradient, exact however coarse the grid.
// OUTPUT_HEIGHTS: TerrainHeightsPass's program: each grid vertex's place and height (the noise),
// captured by transform feedback once a frame. Every other variant reads those back as attributes,
// so the noise is not evaluated again for each cascade, the G-buffer and the reflection.
// MIRRORED: the mirror image across the water plane, clipped to what lies above the water.
// OUTPUT_SHADOW: the same vertices seen from the sun, into one shadow cascade.
#include "common/frame_block.glsl"

#if defined(OUTPUT_HEIGHTS)
#include "common/terrain.glsl"

layout(location = 0) in vec2 gridCoordinate;  // (ring fraction, segment fraction)
out vec2 heightsOffset;  // horizontal offset from the camera, world units
out vec3 heightsHeight;  // terrainHeightFromCamera: (height, d height / dx, d height / dz)

void main() {
    // Ring 0 is the point under the camera (a fan of zero-area triangles closes the centre);
    // ring i >= 1 sits at firstRadius * ratio^(i-1), out to the view distance.
    float ring = floor(gridCoordinate.x * frame.terrainGridCounts.x + 0.5);
    float radius = ring == 0.0 ? 0.0 : frame.terrainGrid.z * pow(frame.terrainGrid.w, ring - 1.0);
    float azimuth = frame.terrainGrid.x + (2.0 * gridCoordinate.y - 1.0) * frame.terrainGrid.y;
    heightsOffset = radius * vec2(sin(azimuth), -cos(azimuth));
    heightsHeight = terrainHeightFromCamera(heightsOffset);
    gl_Position = vec4(0.0, 0.0, 0.0, 1.0);  // nothing is rasterised (GL_RASTERIZER_DISCARD)
}

#else
#include "common/water_clip_vertex.glsl"

// This frame's grid vertex, as TerrainHeightsPass left it (render/scene_geometry.h).
layout(location = 1) in vec2 gridOffset;
layout(location = 2) in vec3 gridHeight;
out vec3 vRelativePosition;
out vec3 vNormal;
#if defined(OUTPUT_SHADOW)
#include "common/shadow_caster.glsl"
#endif

void main() {
    vec3 relative = vec3(gridOffset.x, gridHeight.x - frame.cameraPosition.y, gridOffset.y);
    vNormal = normalize(vec3(-gridHeight.y, 1.0, -gridHeight.z));
#if defined(MIRRORED)
    clipAtWater(gridHeight.x - frame.water.x);  // keep only what is above the water
    relative.y = 2.0 * (frame.water.x - frame.cameraPosition.y) - relative.y;
#endif
    vRelativePosition = relative;
#if defined(OUTPUT_SHADOW)
    gl_Position = shadowCasterPosition(relative);
#else
    gl_Position = frame.viewProjection * vec4(relative, 1.0);
#endif
}
#endif
