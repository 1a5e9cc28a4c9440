// The water plane's pixels go to the stencil buffer (and, with WATER_BOUNDS, widen the rectangle
// of visible water: common/water_bounds.glsl); no colour is written. The tests run before the
// shader, so only the water that is seen is recorded.
// WATER_PLANE_ONLY: the reduced-resolution reflection's own mask (passes/reflection_clear_pass.cpp),
// drawn without a depth test and recording nothing: the frame's mask has recorded the rectangle.
// WATER_FULLSCREEN (common/water_fragment.glsl): the water found per fragment, whose depth the
// shader writes, so the tests run after it and the rectangle also takes water hidden behind
// terrain (wider than needed, never narrower: the reflection's pixels are the same).
#include "common/water_fragment.glsl"
#if !defined(WATER_PLANE_ONLY)
#define WATER_BOUNDS_RECORDER
#include "common/water_bounds.glsl"

#if defined(WATER_BOUNDS) && !defined(WATER_FULLSCREEN)
layout(early_fragment_tests) in;
#endif

void main() {
    waterFragmentPosition();
    recordWaterPixel(ivec2(gl_FragCoord.xy));
}
#else
void main() { waterFragmentPosition(); }
#endif
