// The mirrored geometry's clip at the water plane, vertex side: clipAtWater(d) keeps d >= 0.
// gl_ClipDistance[0] where the context has it; where it does not (OpenGL ES without
// GL_EXT_clip_cull_distance: OASIS_NO_CLIP_DISTANCE) the distance goes to the fragment shader,
// which discards below zero (common/water_clip_fragment.glsl): the same pixels, as the distance
// is linear over the triangle either way.
#ifndef OASIS_WATER_CLIP_VERTEX_GLSL
#define OASIS_WATER_CLIP_VERTEX_GLSL

#if defined(OASIS_NO_CLIP_DISTANCE)
out float vWaterClip;
void clipAtWater(float distance) { vWaterClip = distance; }
#else
void clipAtWater(float distance) { gl_ClipDistance[0] = distance; }
#endif

#endif
