// One triangle that covers the screen, at the far plane when FULLSCREEN_AT_FAR_PLANE is defined
// (the sky draws there so the depth test keeps it behind everything; where that is in NDC depends
// on the depth convention). No vertex buffer needed. The reflection's passes (MIRRORED, or
// WATER_BOUNDED for the ones that are not mirrored draws) clip it to the visible water
// (common/water_bounds.glsl).
#if defined(FULLSCREEN_AT_FAR_PLANE)
#include "common/frame_block.glsl"
#endif
#if defined(MIRRORED) || defined(WATER_BOUNDED)
#include "common/water_bounds.glsl"
#endif
out vec2 vScreenUv;

void main() {
    vec2 corner = vec2(float((gl_VertexID << 1) & 2), float(gl_VertexID & 2));
    vScreenUv = corner;
#if defined(FULLSCREEN_AT_FAR_PLANE)
    gl_Position = vec4(corner * 2.0 - 1.0, frame.depthConvention.w, 1.0);
#else
    gl_Position = vec4(corner * 2.0 - 1.0, 0.0, 1.0);
#endif
#if defined(MIRRORED) || defined(WATER_BOUNDED)
    clipToWaterBounds(gl_Position);
#endif
}
