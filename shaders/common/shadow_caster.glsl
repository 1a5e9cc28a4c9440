// A shadow caster's vertex seen from the sun, into the cascade ShadowPass draws (OUTPUT_SHADOW
// variants of terrain.vert and vegetation.vert). Casters nearer the sun than the cascade's box
// must still shadow it: GL_DEPTH_CLAMP keeps them (ShadowPass enables it); where the context has
// none (OpenGL ES 3.0 without GL_EXT_depth_clamp: OASIS_NO_DEPTH_CLAMP) the vertex is flattened
// onto the box's front ("pancaking"; the projection is orthographic, w = 1), so the rasteriser
// does not clip it away. A triangle that crosses the front then has its depth interpolated from
// the flattened vertex: nearer the sun than the true surface inside the box, never farther.
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
