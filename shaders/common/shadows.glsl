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

// The 3x3 taps a texel apart of the 2x2 comparison, a smooth 4x4-texel footprint (edges neither
// alias nor shimmer; the cascades are snapped to whole texels as well), taken as 2x2 taps. Along
// an axis, with f the point's fraction between texel centres, the three taps weigh the four texels
// (1 - f, 1, 1, f) / 3: the first pair (weight 2 - f) is one tap placed 1 / (2 - f) of the way
// between them, the second (1 + f) one placed f / (1 + f) of the way; the weights are a product
// of the two axes', so four taps give what nine did (up to the filter's own rounding). On
// llvmpipe a tap costs about 0.8 ms over a 1280x720 frame.
float tentFilteredShadow(vec3 coord, int cascade, vec2 mapSize) {
    vec2 texel = coord.xy * mapSize - 0.5;
    vec2 base = floor(texel);
    vec2 f = texel - base;
    vec2 weightLow = 2.0 - f, weightHigh = 1.0 + f;
    vec2 low = (base - 0.5 + 1.0 / weightLow) / mapSize;   // between texels base - 1 and base
    vec2 high = (base + 1.5 + f / weightHigh) / mapSize;   // between texels base + 1 and base + 2
    float sum = weightLow.x * weightLow.y * texture(shadowMap, vec4(low.x, low.y, float(cascade), coord.z)) +
                weightHigh.x * weightLow.y * texture(shadowMap, vec4(high.x, low.y, float(cascade), coord.z)) +
                weightLow.x * weightHigh.y * texture(shadowMap, vec4(low.x, high.y, float(cascade), coord.z)) +
                weightHigh.x * weightHigh.y * texture(shadowMap, vec4(high.x, high.y, float(cascade), coord.z));
    return sum / 9.0;
}

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
        // A box that reaches towards the sun past its sphere (ShadowCasterDepth::Contained, no
        // depth clamp) asks the same: the sphere's diameter (texel x map size) is the back part of
        // the depth range, so its front sits at this clip depth; -1 where the two are one.
        float sphereFront = 1.0 - 2.0 * (texel * mapSize.x) / frame.shadowDepthRange[c];
        if (any(greaterThan(abs(clip.xy), vec2(1.0 - margin))) || clip.z >= 1.0 || clip.z <= sphereFront) continue;
        vec3 coord = clip.xyz * 0.5 + 0.5;
        coord.z -= SHADOW_DEPTH_BIAS_TEXELS * texel / frame.shadowDepthRange[c];
        result.lit = tentFilteredShadow(coord, c, mapSize);
        result.cascade = c;
        break;
    }
    // Beyond the last cascade the shadows fade out rather than stop at a line.
    result.lit = mix(result.lit, 1.0, smoothstep(frame.shadow.z, frame.shadow.w, length(position)));
    return result;
}

#endif
