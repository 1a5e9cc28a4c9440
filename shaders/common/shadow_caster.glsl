// A shadow caster's vertex seen from the sun, into the cascade ShadowPass draws (OUTPUT_SHADOW
// variants of terrain.vert and vegetation.vert). Casters nearer the sun than the cascade's box
// must still shadow it: GL_DEPTH_CLAMP keeps them (ShadowPass enables it). Where the context has
// none (OpenGL ES 3.0 without GL_EXT_depth_clamp: OASIS_NO_DEPTH_CLAMP) the box itself reaches
// towards the sun up to the highest caster (ShadowCasterDepth::Contained, render/shadow_cascades.h),
// and only past that reach's cap (a sun under a degree high) is a vertex flattened onto the
// front ("pancaking"; the projection is orthographic, w = 1) so the rasteriser does not clip it
// away. Flattening changes the depth slope of a triangle crossing the front, and so its
// slope-scaled polygon offset: shadows a few pixels apart from the clamped ones.
#ifndef OASIS_SHADOW_CASTER_GLSL
#define OASIS_SHADOW_CASTER_GLSL
#include "common/frame_block.glsl"

uniform int shadowCascade;  // the cascade ShadowPass draws (common/shadows.glsl reads them all)

vec4 shadowCasterPosition(vec3 relative) {
    vec4 clip = frame.shadowMatrices[shadowCascade] * vec4(relative, 1.0);
#if defined(OASIS_NO_DEPTH_CLAMP)
    clip.z = max(clip.z, -clip.w);
#endif
    return clip;
}

#endif
