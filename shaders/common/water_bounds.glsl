// The screen rectangle of the frame's visible water: the water mask's fragments (those that pass
// its depth test, early) widen it, and the reflection's full-screen draws (its clear, the mirrored
// depth copy, lighting and sky) clip their triangle to it, so they rasterise only where water is
// seen, and nothing at all when none is. Clipping a full-screen triangle changes no pixel; the
// mirrored geometry and the water quad are not clipped: new vertices at the clip edges would move
// their interpolated attributes and depth by rounding, and the frame would no longer be the one
// every fallback draws bit for bit (they stay stencil-masked). WATER_BOUNDS is a context define (frame/renderer_choices.cpp: where
// vertex and fragment shaders have storage blocks); without it nothing is recorded or clipped.
// The water mask's fragment shader defines WATER_BOUNDS_RECORDER before including this (it
// records); fullscreen.vert clips with it, the mirrored billboards (vegetation.vert) cull with it.
#ifndef OASIS_WATER_BOUNDS_GLSL
#define OASIS_WATER_BOUNDS_GLSL
#include "common/frame_block.glsl"
#include "common/shared_constants.glsl"

#if defined(WATER_BOUNDS)
// Pixels (gl_FragCoord, bottom-up), inclusive: x min, y min, x max, y max; reset each frame to an
// empty box (min > max) by WaterMaskPass. Bound by name (render/texture_units.h).
buffer WaterBoundsBuffer { ivec4 waterPixels; };

#if defined(WATER_BOUNDS_RECORDER)
void recordWaterPixel(ivec2 pixel) {
    // Bounds only ever widen, so a read that lags behind can only cause an atomic that was not
    // needed, never skip one that was: most fragments change nothing and pay no atomic.
    if (pixel.x < waterPixels.x) atomicMin(waterPixels.x, pixel.x);
    if (pixel.y < waterPixels.y) atomicMin(waterPixels.y, pixel.y);
    if (pixel.x > waterPixels.z) atomicMax(waterPixels.z, pixel.x);
    if (pixel.y > waterPixels.w) atomicMax(waterPixels.w, pixel.y);
}
#else

// The rectangle's pixel edges (x0, y0, x1, y1) in the target drawn into: the frame's own, or the
// reflection's at a reduced resolution, there widened by frame.targetScale.z pixels so that the
// upsample's bilinear taps beside every water pixel were drawn too. At full resolution the scale
// is 1 and the widening 0, exactly: the same edges as the frame's pixels.
vec4 waterRectangleInTarget() {
    vec4 edges = vec4(vec2(waterPixels.xy), vec2(waterPixels.zw) + 1.0) * frame.targetScale.xyxy;
    return vec4(floor(edges.xy), ceil(edges.zw)) + vec4(-frame.targetScale.zz, frame.targetScale.zz);
}

// Whether a mirrored billboard (its four corners in clip space) lands wholly outside the rectangle,
// so none of its fragments could pass the water's stencil: the vertex shader then drops the whole
// quad (every corner computes the same answer), which changes no pixel, unlike clipping it. Only
// when this frame bounds its reflection; never with a corner at or behind the eye.
bool billboardMissesWater(vec4 c0, vec4 c1, vec4 c2, vec4 c3) {
    if ((uint(frame.water.w) & OASIS_WATER_BOUNDED_FLAG) == 0u) return false;
    if (min(min(c0.w, c1.w), min(c2.w, c3.w)) <= 1e-4) return false;
    vec2 p0 = c0.xy / c0.w, p1 = c1.xy / c1.w, p2 = c2.xy / c2.w, p3 = c3.xy / c3.w;
    // Window pixels, with a pixel to spare for rounding.
    vec2 low = (min(min(p0, p1), min(p2, p3)) * 0.5 + 0.5) * frame.screen.xy - 1.0;
    vec2 high = (max(max(p0, p1), max(p2, p3)) * 0.5 + 0.5) * frame.screen.xy + 1.0;
    vec4 water = waterRectangleInTarget();
    return any(lessThan(high, water.xy)) || any(greaterThan(low, water.zw));
}

// gl_ClipDistance[1..4] against the rectangle's edges (pixel edges, so every water pixel's centre
// is half a pixel inside); the passes of the reflection enable them (passes/pass.cpp).
void clipToWaterBounds(vec4 clipPosition) {
    vec4 edges = waterRectangleInTarget() * frame.screen.zwzw * 2.0 - 1.0;
    gl_ClipDistance[1] = clipPosition.x - edges.x * clipPosition.w;
    gl_ClipDistance[2] = clipPosition.y - edges.y * clipPosition.w;
    gl_ClipDistance[3] = edges.z * clipPosition.w - clipPosition.x;
    gl_ClipDistance[4] = edges.w * clipPosition.w - clipPosition.y;
}
#endif
#elif defined(WATER_BOUNDS_RECORDER)
void recordWaterPixel(ivec2 pixel) {}
#else
void clipToWaterBounds(vec4 clipPosition) {}
bool billboardMissesWater(vec4 c0, vec4 c1, vec4 c2, vec4 c3) { return false; }
#endif

#endif
