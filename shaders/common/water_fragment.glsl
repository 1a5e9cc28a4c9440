// The water surface's camera-relative position at this fragment, for the water's mask and
// composite. Drawn as the water grid (water.vert) it is the interpolated vRelativePosition.
// WATER_FULLSCREEN, the tiers without depth clamp (OpenGL ES 3.0 without GL_EXT_depth_clamp,
// --force gles30 or no-depth-clamp): there the near plane would clip the grid and lose the water
// nearer the eye than it, so a full-screen triangle is drawn instead and each fragment meets the
// water plane along its view ray, discards where the ray misses the water, and writes the depth
// GL_DEPTH_CLAMP gives the grid there (the plane's depth, clamped to the depth range).
#ifndef OASIS_WATER_FRAGMENT_GLSL
#define OASIS_WATER_FRAGMENT_GLSL
#include "common/frame_block.glsl"

#if defined(WATER_FULLSCREEN)
#include "common/depth.glsl"

vec3 waterFragmentPosition() {
    vec2 ndc = gl_FragCoord.xy * frame.screen.zw * 2.0 - 1.0;
    vec4 onNearPlane = frame.inverseViewProjection * vec4(ndc, frame.depthConvention.y, 1.0);
    vec3 ray = onNearPlane.xyz / onNearPlane.w;  // camera-relative, in front of the eye
    // The grid's plane and square (water.vert): at the water level, extent around the camera.
    float along = (frame.water.x - frame.cameraPosition.y) / ray.y;
    if (!(along > 0.0)) discard;  // the ray leaves the plane behind it (or runs along it)
    vec3 position = ray * along;
    if (max(abs(position.x), abs(position.z)) > frame.terrainGridCounts.w) discard;
    vec4 clip = frame.viewProjection * vec4(position, 1.0);
    float ndcDepth = clip.z / clip.w;
    gl_FragDepth = clamp(depthReversed() ? ndcDepth : ndcDepth * 0.5 + 0.5, 0.0, 1.0);
    return position;
}
#else
in vec3 vRelativePosition;
vec3 waterFragmentPosition() { return vRelativePosition; }
#endif

#endif
