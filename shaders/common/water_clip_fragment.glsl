// The mirrored geometry's clip at the water plane, fragment side (see water_clip_vertex.glsl):
// belowWater() is true where the vertex side's clip distance puts the fragment below the water and
// the context has no gl_ClipDistance; false otherwise (the rasteriser clipped it already). Callers
// discard after their light loop (vegetation.frag says why: llvmpipe's UBO lights after a discard).
#ifndef OASIS_WATER_CLIP_FRAGMENT_GLSL
#define OASIS_WATER_CLIP_FRAGMENT_GLSL

#if defined(MIRRORED) && defined(OASIS_NO_CLIP_DISTANCE)
in float vWaterClip;
bool belowWater() { return vWaterClip < 0.0; }
#else
bool belowWater() { return false; }
#endif

#endif
