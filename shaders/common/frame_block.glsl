// The per-frame uniform block every shader reads (bound from C++ to kFrameBlockBinding).
#ifndef OASIS_FRAME_BLOCK_GLSL
#define OASIS_FRAME_BLOCK_GLSL
#include "common/frame_data.glsl"
layout(std140) uniform FrameBlock {
    FrameData frame;
};
#endif
