// The water plane's pixels go to the stencil buffer (and, with WATER_BOUNDS, widen the rectangle
// of visible water: common/water_bounds.glsl); no colour is written. The tests run before the
// shader, so only the water that is seen is recorded.
// WATER_PLANE_ONLY: the reduced-resolution reflection's own mask (passes/reflection_clear_pass.cpp),
// drawn without a depth test and recording nothing: the frame's mask has recorded the rectangle.
#if !defined(WATER_PLANE_ONLY)
#define WATER_BOUNDS_RECORDER
#include "common/water_bounds.glsl"

#if defined(WATER_BOUNDS)
layout(early_fragment_tests) in;
#endif

void main() { recordWaterPixel(ivec2(gl_FragCoord.xy)); }
#else
void main() {}
#endif
