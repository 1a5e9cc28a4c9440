// Sun shadows: how much of the sun reaches a surface point, read from the cascaded shadow maps
// ShadowPass drew this frame (src/render/shadow_cascades.h fits them). The one function both
// pipelines call, through shadeSurface: forward with the interpolated position, deferred with the
// G-buffer's (stored or reconstructed), the reflection with the mirrored surface's real position.
#ifndef OASIS_SHADOWS_GLSL
#define OASIS_SHADOWS_GLSL
#include "common/frame_block.glsl"

// One layer per cascade; depth comparison on (GL_COMPARE_REF_TO_TEXTURE) with linear filtering,
// so each tap is the hardware's 2x2 percentage-closer filter. Works from GL 3.3 up.
uniform sampler2DArrayShadow shadowMap;

// The receiver's offsets against self-shadowing (acne), in texels of its cascade: along the
// surface normal and towards the sun in depth. Their sum (2.5 texels) bounds how far a shadow can
// detach from its caster (peter-panning); docs/shadows.md gives it in world units per cascade.
const float SHADOW_NORMAL_OFFSET_TEXELS = 1.5;
const float SHADOW_DEPTH_BIAS_TEXELS = 1.0;

struct SunShadow {
    float lit;    // 0 in full shadow .. 1 in full sun
    int cascade;  // the cascade that answered, -1 where none holds the point (or shadows are off)
};

SunShadow sunShadow(vec3 position, vec3 normal) {
    SunShadow result = SunShadow(1.0, -1);
    if (frame.shadow.x == 0.0) return result;
    int count = int(frame.shadow.y);
    vec2 mapSize = vec2(textureSize(shadowMap, 0).xy);
    // The filter reaches 1.5 texels from the centre: a point needs that much map around it.
    float margin = 2.0 * 2.0 / mapSize.x;
    for (int c = 0; c < count; ++c) {
        float texel = frame.shadowTexel[c];
        vec3 p = position + normal * (texel * SHADOW_NORMAL_OFFSET_TEXELS);
        vec4 clip = frame.shadowMatrices[c] * vec4(p, 1.0);
        // The finest cascade that holds the point answers (not the eye distance: a reflected
        // surface's real position can lie outside the slice its distance names). Its depth too:
        // with a low sun a cascade's square reaches far along the sun's rays, and a point nearer
        // the sun than its depth range (where casters are clamped) must ask a wider cascade.
        if (any(greaterThan(abs(clip.xy), vec2(1.0 - margin))) || abs(clip.z) >= 1.0) continue;
        vec3 coord = clip.xyz * 0.5 + 0.5;
        coord.z -= SHADOW_DEPTH_BIAS_TEXELS * texel / frame.shadowDepthRange[c];
        // 3x3 taps a texel apart of the 2x2 comparison: a smooth 4x4-texel footprint, so edges
        // neither alias nor shimmer (the cascades are snapped to whole texels as well).
        float sum = 0.0;
        for (int y = -1; y <= 1; ++y)
            for (int x = -1; x <= 1; ++x)
                sum += texture(shadowMap, vec4(coord.xy + vec2(float(x), float(y)) / mapSize, float(c), coord.z));
        result.lit = sum / 9.0;
        result.cascade = c;
        break;
    }
    // Beyond the last cascade the shadows fade out rather than stop at a line.
    result.lit = mix(result.lit, 1.0, smoothstep(frame.shadow.z, frame.shadow.w, length(position)));
    return result;
}

#endif
